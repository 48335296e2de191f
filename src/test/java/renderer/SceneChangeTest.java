package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ConcurrentModificationException;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Geometry;
import lighting.AmbientLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import scene.Scene;

/**
 * A scene changed through its setters (or the course's public fields) while it renders: every
 * value the shading reads is in the render's stamp, so the render fails, naming the change, as it
 * does for an added shape or light, and never returns an image of two states. The change is made
 * by a light of the scene the first time it is shaded: in the middle of the render, every time.
 */
class SceneChangeTest {
    /** A point light that runs an action the first time it is shaded (from any worker). */
    private static final class Trigger extends PointLight {
        final AtomicReference<Runnable> action = new AtomicReference<>();

        Trigger() {
            super(new Color(80, 80, 80), new Point(0, 5, 5));
        }

        // The course method: a user's subclass of a library light is shaded through it.
        @Override
        public Color getIntensity(Point p) {
            Runnable a = action.getAndSet(null);
            if (a != null) a.run();
            return super.getIntensity(p);
        }
    }

    /** The shared scene of {@link TestScenes#everyEffect()}, its lights, and the trigger among them. */
    private record Fixture(Scene scene, Geometry floor, PointLight point, SpotLight spot, Trigger trigger) {
        static Fixture make() {
            Scene scene = TestScenes.everyEffect();
            Trigger trigger = new Trigger();
            scene.lights.add(trigger);
            return new Fixture(scene, (Geometry) scene.geometries.getItems().get(0), (PointLight) scene.lights.get(0),
                    (SpotLight) scene.lights.get(1), trigger);
        }
    }

    static Stream<Arguments> changes() {
        Stream<Arguments> each = Stream.of(
                change("setBackground", f -> f.scene.setBackground(new Color(1, 2, 3)), "its background was replaced"),
                change("the background field", f -> f.scene.background = new Color(1, 2, 3), "its background was replaced"),
                change("setAmbientLight", f -> f.scene.setAmbientLight(new AmbientLight(new Color(9, 9, 9), 1)),
                        "its ambient light was replaced"),
                change("Material.setKd", f -> f.floor.getMaterial().setKd(0.9), "a material of its geometries changed"),
                change("Material.setReflectionSpread", f -> f.floor.getMaterial().setReflectionSpread(0.01),
                        "a material of its geometries changed"),
                change("the material's kR field", f -> f.floor.getMaterial().kR = new Double3(0.05),
                        "a material of its geometries changed"),
                change("setMaterial", f -> f.floor.setMaterial(new Material()), "a material of its geometries changed"),
                change("setEmission", f -> f.floor.setEmission(new Color(200, 0, 0)),
                        "the emission of one of its geometries changed"),
                change("PointLight.setKl", f -> f.point.setKl(0.5), "the settings of its light #0 changed"),
                change("PointLight.setRadius", f -> f.point.setRadius(0.1), "the settings of its light #0 changed"),
                change("SpotLight.setNarrowBeam", f -> f.spot.setNarrowBeam(9), "the settings of its light #1 changed"),
                change("SpotLight.setKq", f -> f.spot.setKq(0.3), "the settings of its light #1 changed"));
        return each.flatMap(a -> Stream.of(Arguments.of(a.get()[0], a.get()[1], a.get()[2], false),
                Arguments.of(a.get()[0], a.get()[1], a.get()[2], true)));
    }

    private static Arguments change(String name, Consumer<Fixture> change, String message) {
        return Arguments.of(name, change, message);
    }

    @ParameterizedTest(name = "{0}, shared tracer: {3}")
    @MethodSource("changes")
    @DisplayName("a change mid-render fails the render, naming it; the image is not returned")
    void changedMidRender(String name, Consumer<Fixture> change, String message, boolean shared) {
        Fixture f = Fixture.make();
        RayTracerBasic tracer = new RayTracerBasic(f.scene).setBeamSize(2).setShadowSamples(2);
        if (shared) { // a tracer that rendered the scene for another camera first
            TestScenes.camera(f.scene, new ImageWriter("first", 8, 8)).setRayTracer(tracer).build().renderImage();
        }
        Camera camera = TestScenes.camera(f.scene, new ImageWriter("changed", 8, 8)).setRayTracer(tracer)
                .setMultithreading(2).build();
        f.trigger.action.set(() -> change.accept(f));
        assertThatThrownBy(camera::renderImage).isInstanceOf(ConcurrentModificationException.class)
                .hasMessage("the scene 'every-effect' changed during the render of changed: " + message
                        + messageTail(message) + " (a scene must not change while it renders; render it again when it is complete)");
        assertThat(f.trigger.action.get()).as("the change was made").isNull();
        // Once the scene stays put, the same camera renders it.
        assertThat(camera.renderImage()).isSameAs(camera);
    }

    /** The parenthesis each change's message carries after its words. */
    private static String messageTail(String message) {
        if (message.startsWith("its background")) return " (setBackground)";
        if (message.startsWith("its ambient")) return " (setAmbientLight)";
        if (message.startsWith("a material")) return " (a Material setter such as setKd, a field, or setMaterial)";
        if (message.startsWith("the emission")) return " (setEmission)";
        return message.endsWith("#0 changed") ? " (PointLight)" : " (SpotLight)";
    }

    static Stream<Arguments> reverted() {
        return Stream.of(
                change("PointLight.setKl, then back", f -> {
                    double kL = 0.02;
                    f.point.setKl(0.5).setKl(kL);
                }, "the settings of its light #0 changed"),
                change("SpotLight.setNarrowBeam, then back", f -> f.spot.setNarrowBeam(9).setNarrowBeam(3),
                        "the settings of its light #1 changed"),
                change("Material.setKd, then back", f -> f.floor.getMaterial().setKd(0.9).setKd(0.5),
                        "a material of its geometries changed"),
                change("setMaterial, then back", f -> {
                    Material m = f.floor.getMaterial();
                    f.floor.setMaterial(new Material()).setMaterial(m);
                }, "a material of its geometries changed"),
                change("setEmission, then back", f -> {
                    Color e = f.floor.getEmission();
                    f.floor.setEmission(new Color(200, 0, 0)).setEmission(e);
                }, "the emission of one of its geometries changed"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("reverted")
    @DisplayName("a change put back within the render fails it too: the setters count, the values alone would not show it")
    void changedAndPutBack(String name, Consumer<Fixture> change, String message) {
        Fixture f = Fixture.make();
        Camera camera = TestScenes.camera(f.scene, new ImageWriter("changed", 8, 8)).setMultithreading(2).build();
        f.trigger.action.set(() -> change.accept(f));
        assertThatThrownBy(camera::renderImage).isInstanceOf(ConcurrentModificationException.class)
                .hasMessageContaining("changed during the render of changed: " + message);
        assertThat(f.trigger.action.get()).as("the change was made").isNull();
    }

    @Test
    @DisplayName("setting a value equal to the old one is no change: the render goes through")
    void sameValues() {
        Fixture f = Fixture.make();
        Camera camera = TestScenes.camera(f.scene, new ImageWriter("same", 8, 8)).build();
        f.trigger.action.set(() -> {
            f.floor.getMaterial().setKd(0.5);
            f.point.setKl(0.02).setRadius(0.6);
            f.spot.setNarrowBeam(3);
        });
        assertThat(camera.renderImage()).isSameAs(camera);
        assertThat(f.trigger.action.get()).isNull();
    }
}
