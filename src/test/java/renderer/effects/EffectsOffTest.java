package renderer.effects;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Plane;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * With every spread and radius at 0, the effects are off whatever the beam size and shadow
 * sample count: the image is byte for byte the plain Whitted render. The scene has what the
 * effects touch (a mirror, glass, a point and a spot light casting shadows) and jittered
 * anti-aliasing, so an effect that drew random numbers while "off" would also shift every later
 * sample of the pixel and show.
 */
@DisplayName("Spread 0 and radius 0 reproduce the plain render exactly")
class EffectsOffTest {
    private static final int SIZE = 100;

    /**
     * What a test changes on the plain scene: the spreads and the light radius it sets explicitly
     * (null: the setter is not called, the default stays) and the tracer's settings.
     */
    record Variant(Double reflectionSpread, Double transmissionSpread, Double lightRadius,
                   UnaryOperator<RayTracerBasic> tracer) {
    }

    private static final Variant PLAIN = new Variant(null, null, null, t -> t);

    static Stream<Arguments> variants() {
        return Stream.of(
                Arguments.of("reflection spread set to 0, beam 1000",
                        new Variant(0.0, null, null, t -> t.setBeamSize(1000))),
                Arguments.of("transmission spread set to 0, beam 1000",
                        new Variant(null, 0.0, null, t -> t.setBeamSize(1000))),
                Arguments.of("light radius set to 0, 1000 shadow samples",
                        new Variant(null, null, 0.0, t -> t.setShadowSamples(1000))),
                Arguments.of("all zeros, beam 1 and 1 shadow sample",
                        new Variant(0.0, 0.0, 0.0, t -> t.setBeamSize(1).setShadowSamples(1))));
    }

    private static Scene scene(Variant v) {
        Scene scene = new Scene("effects off").setBackground(new Color(20, 30, 50))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        Material mirror = new Material().setKd(0.3).setKs(0.4).setShininess(50).setKr(0.6);
        Material glass = new Material().setKd(0.2).setKs(0.5).setShininess(80).setKt(0.7);
        if (v.reflectionSpread() != null) {
            mirror.setReflectionSpread(v.reflectionSpread());
            glass.setReflectionSpread(v.reflectionSpread());
        }
        if (v.transmissionSpread() != null) {
            mirror.setTransmissionSpread(v.transmissionSpread());
            glass.setTransmissionSpread(v.transmissionSpread());
        }
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(30, 30, 30)).setMaterial(mirror),
                new Sphere(new Point(-25, 25, 0), 25).setEmission(new Color(20, 40, 120)).setMaterial(glass),
                new Sphere(new Point(30, 20, -20), 20).setEmission(new Color(120, 30, 20)).setMaterial(mirror));
        PointLight point = new PointLight(new Color(300, 280, 250), new Point(60, 120, 80)).setKl(0.002);
        SpotLight spot = new SpotLight(new Color(400, 400, 500), new Point(-80, 100, 60), new Vector(1, -1, -1))
                .setKl(0.001).setNarrowBeam(4);
        if (v.lightRadius() != null) {
            point.setRadius(v.lightRadius());
            spot.setRadius(v.lightRadius());
        }
        scene.lights.add(point);
        scene.lights.add(spot);
        return scene;
    }

    private static ImageWriter render(Variant v) {
        ImageWriter image = new ImageWriter("effects-off", SIZE, SIZE);
        Camera.getBuilder().setLocation(new Point(0, 60, 200)).setDirection(new Point(0, 15, 0), Vector.AXIS_Y)
                .setVpSize(120, 120).setVpDistance(200).setAntiAliasing(AntiAliasing.RANDOM, 2, 2).setSeed(7)
                .setImageWriter(image).setRayTracer(v.tracer().apply(new RayTracerBasic(scene(v))))
                .setSummary(false).build().renderImage();
        return image;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void sameBytesAsThePlainRender(String name, Variant variant, @TempDir Path dir) throws IOException {
        ImageWriter plain = render(PLAIN), zeros = render(variant);
        assertThat(Profiles.pixels(zeros)).as("pixels with %s vs the plain render", name)
                .isEqualTo(Profiles.pixels(plain));
        plain.writeToImage(dir.resolve("plain.png"));
        zeros.writeToImage(dir.resolve("zeros.png"));
        assertThat(Files.readAllBytes(dir.resolve("zeros.png"))).as("PNG bytes")
                .isEqualTo(Files.readAllBytes(dir.resolve("plain.png")));
    }
}
