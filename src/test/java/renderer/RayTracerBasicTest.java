package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Sphere;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/** {@link RayTracerBasic#traceRay(Ray)} called directly, outside a render (as course tests do). */
class RayTracerBasicTest {
    private static final Ray DOWN_Z = new Ray(new Point(0, 0, 10), new Vector(0, 0, -1));

    @Test
    @DisplayName("a geometry added after the first call is seen by the next call")
    void seesGeometryAddedAfterFirstCall() {
        Scene scene = new Scene("grows").setBackground(new Color(1, 2, 3));
        RayTracerBasic tracer = new RayTracerBasic(scene);
        assertThat(tracer.traceRay(DOWN_Z).toRgb()).isEqualTo(new Color(1, 2, 3).toRgb());

        scene.geometries.add(new Sphere(Point.ZERO, 1).setEmission(new Color(200, 0, 0)));
        assertThat(tracer.traceRay(DOWN_Z).toRgb()).isEqualTo(new Color(200, 0, 0).toRgb());
    }

    @Test
    @DisplayName("renders of one scene share its tree, yet a shape added deep in a nested list between them is drawn")
    void nextRenderSeesNestedAddition() {
        geometries.Geometries group = new geometries.Geometries(new Sphere(new Point(-0.6, 0, -5), 0.5).setEmission(new Color(0, 200, 0)));
        Scene scene = new Scene("grows between renders").setBackground(new Color(1, 2, 3));
        scene.geometries.add(group);
        ImageWriter first = new ImageWriter("before", 16, 16);
        TestScenes.camera(scene, first).setSummary(false).build().render();
        group.add(new geometries.Geometries(new Sphere(new Point(0.6, 0, -5), 0.5).setEmission(new Color(200, 0, 0))));
        ImageWriter second = new ImageWriter("after", 16, 16);
        TestScenes.camera(scene, second).setSummary(false).build().render();
        int red = 0, redBefore = 0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                if (((second.getRgb(x, y) >> 16) & 0xFF) > 100) ++red;
                if (((first.getRgb(x, y) >> 16) & 0xFF) > 100) ++redBefore;
            }
        assertThat(redBefore).as("red pixels before the red sphere was added").isZero();
        assertThat(red).as("red pixels after").isPositive();
    }

    @Test
    @DisplayName("random effects are keyed by the ray: the same ray gives the same colour, another ray other noise")
    void randomEffectsKeyedByTheRay() {
        Scene scene = new Scene("soft");
        scene.geometries.add(new Sphere(new Point(0, 0, -5), 1).setMaterial(new Material().setKd(0)),
                new geometries.Plane(new Point(0, 0, -10), new Vector(0, 0, 1)).setMaterial(new Material().setKd(1)));
        scene.lights.add(new PointLight(new Color(255, 255, 255), new Point(0, 0, 20)).setRadius(3));
        RayTracerBasic tracer = new RayTracerBasic(scene).setShadowSamples(3);
        // A ray into the penumbra of the sphere on the plane: its colour depends on the shadow samples.
        Ray penumbra = new Ray(new Point(1.1, 0, 10), new Vector(0, 0, -1));
        Color first = tracer.traceRay(penumbra);
        assertThat(tracer.traceRay(penumbra).toRgb()).isEqualTo(first.toRgb());
        boolean anyDifferent = false;
        for (int i = 1; i <= 20 && !anyDifferent; ++i)
            anyDifferent = tracer.traceRay(new Ray(new Point(1.1, i * 1e-9, 10), new Vector(0, 0, -1))).toRgb() != first.toRgb();
        assertThat(anyDifferent).as("nearby rays draw other shadow samples").isTrue();
    }

    @Test
    @DisplayName("a setting changed between direct calls applies from the next call on")
    void settingChangedBetweenCalls() {
        Scene scene = new Scene("soft");
        scene.geometries.add(new Sphere(new Point(0, 0, -5), 1).setMaterial(new Material().setKd(0)),
                new geometries.Plane(new Point(0, 0, -10), new Vector(0, 0, 1)).setMaterial(new Material().setKd(1)));
        scene.lights.add(new PointLight(new Color(255, 255, 255), new Point(0, 0, 20)).setRadius(3));
        Ray penumbra = new Ray(new Point(1.1, 0, 10), new Vector(0, 0, -1));
        RayTracerBasic tracer = new RayTracerBasic(scene).setShadowSamples(2);
        Color before = tracer.traceRay(penumbra);
        Color after = tracer.setShadowSamples(40).traceRay(penumbra);
        Color fresh = new RayTracerBasic(scene).setShadowSamples(40).traceRay(penumbra);
        assertThat(after.toRgb()).as("the penumbra's colour depends on the samples").isNotEqualTo(before.toRgb());
        assertThat(new double[] { after.getR(), after.getG(), after.getB() })
                .containsExactly(fresh.getR(), fresh.getG(), fresh.getB());
    }

    @Test
    @DisplayName("a light without attenuation (kC = kL = kQ = 0) fails the render before any pixel, naming the values")
    void badLightFailsBeforeRendering() {
        Scene scene = new Scene("bad light");
        scene.geometries.add(new Sphere(new Point(0, 0, -5), 1));
        scene.lights.add(new PointLight(new Color(255, 255, 255), new Point(0, 0, 5)).setKc(0));
        ImageWriter image = new ImageWriter("bad-light", 8, 8);
        Camera camera = TestScenes.camera(scene, image).setMultithreading(2).setSummary(false).build();
        org.assertj.core.api.Assertions.assertThatIllegalArgumentException().isThrownBy(camera::renderImage)
                .withMessageContaining("kC").withMessageContaining("kL").withMessageContaining("kQ");
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) assertThat(image.getRgb(x, y)).as("pixel (%d,%d) untouched", x, y).isZero();
    }

    @Test
    @DisplayName("no shadow ray is traced toward a light that cannot contribute (turned away, or kD = kS = 0)")
    void noShadowRayWithoutContribution() {
        Scene scene = new Scene("nothing to shadow");
        scene.geometries.add(new geometries.Plane(Point.ZERO, new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.5)),
                new Sphere(new Point(0, 0, -3), 1).setMaterial(new Material().setKr(0.5))); // a pure mirror
        // A spot light above the plane, pointing up: its beam never reaches the plane.
        scene.lights.add(new lighting.SpotLight(new Color(255, 255, 255), new Point(0, 0, 5), new Vector(0, 0, 1)));
        ImageWriter image = new ImageWriter("no-shadow-rays", 8, 8);
        RenderStats stats = TestScenes.camera(scene, image).setSummary(false).build().render();
        assertThat(stats.shadowRays()).isZero();

        // The same light turned toward the plane: now every lit pixel needs its shadow ray.
        scene.lights.set(0, new lighting.SpotLight(new Color(255, 255, 255), new Point(0, 0, 5), new Vector(0, 0, -1)));
        RenderStats lit = TestScenes.camera(scene, image).setSummary(false).build().render();
        assertThat(lit.shadowRays()).isPositive();
    }
}
