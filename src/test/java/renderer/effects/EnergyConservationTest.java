package renderer.effects;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.function.Supplier;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Geometry;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * A beam averages its rays, so it must neither gain nor lose light: a perfect glossy mirror
 * (kR 1) or perfect diffuse glass (kT 1) with nothing around it but a uniform background shows
 * exactly that background, at every pixel, including grazing angles where part of the beam
 * would leave on the wrong side of the surface. No lights, no ambient light, no emission: any
 * pixel that is not the background colour is light created or destroyed by the beam.
 */
@DisplayName("Glossy and diffuse beams conserve energy under a uniform background")
class EnergyConservationTest {
    private static final Color BACKGROUND = new Color(100, 150, 200);
    private static final double SPREAD = 0.3;
    private static final int SIZE = 100;

    static Stream<Arguments> surfaces() {
        Material glossyMirror = new Material().setKr(1).setReflectionSpread(SPREAD);
        Material diffuseGlass = new Material().setKt(1).setTransmissionSpread(SPREAD);
        Point sphereView = new Point(0, 0, 300), floorView = new Point(0, 15, 300);
        return Stream.of(
                Arguments.of("glossy mirror sphere (silhouette grazing)", sphereView,
                        (Supplier<Geometry>) () -> new Sphere(Point.ZERO, 40).setMaterial(glossyMirror)),
                Arguments.of("glossy mirror floor seen up to the horizon", floorView,
                        (Supplier<Geometry>) () -> new Plane(Point.ZERO, Vector.AXIS_Y).setMaterial(glossyMirror)),
                Arguments.of("diffuse glass sphere (two refractions)", sphereView,
                        (Supplier<Geometry>) () -> new Sphere(Point.ZERO, 40).setMaterial(diffuseGlass)),
                Arguments.of("diffuse glass pane seen obliquely", sphereView,
                        (Supplier<Geometry>) () -> new Polygon(new Point(-60, -60, 30), new Point(60, -60, -30),
                                new Point(60, 60, -30), new Point(-60, 60, 30)).setMaterial(diffuseGlass)));
    }

    @ParameterizedTest(name = "{0}: every pixel is the background within 1 step")
    @MethodSource("surfaces")
    void beamKeepsTheBackground(String name, Point location, Supplier<Geometry> surface) {
        Scene scene = new Scene(name).setBackground(BACKGROUND);
        Geometry geometry = surface.get();
        scene.geometries.add(geometry);
        ImageWriter image = new ImageWriter("effects-energy", SIZE, SIZE);
        Camera camera = Camera.getBuilder().setLocation(location).setDirection(Point.ZERO, Vector.AXIS_Y)
                .setVpSize(150, 150).setVpDistance(300).setImageWriter(image)
                .setRayTracer(new RayTracerBasic(scene).setBeamSize(16)).setSummary(false).build();
        camera.renderImage();

        // The check means something only where the surface is seen: count those pixels independently.
        int covered = 0;
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x)
                if (geometry.findIntersections(camera.constructRay(SIZE, SIZE, x, y)) != null) ++covered;
        assertThat(covered).as("pixels showing the surface").isGreaterThan(SIZE * SIZE / 5);

        int expected = BACKGROUND.toRgb();
        int worst = 0, worstX = -1, worstY = -1, worstRgb = expected;
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x) {
                int rgb = image.getRgb(x, y);
                int diff = Math.max(Math.abs(((rgb >> 16) & 0xFF) - ((expected >> 16) & 0xFF)),
                        Math.max(Math.abs(((rgb >> 8) & 0xFF) - ((expected >> 8) & 0xFF)),
                                Math.abs((rgb & 0xFF) - (expected & 0xFF))));
                if (diff > worst) {
                    worst = diff;
                    worstX = x;
                    worstY = y;
                    worstRgb = rgb;
                }
            }
        assertThat(worst).as("largest channel difference from the background, at pixel (%d,%d) = #%06x",
                worstX, worstY, worstRgb).isLessThanOrEqualTo(1);
    }
}
