package renderer.effects;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * The beam's cost policy (a full beam at the first glossy bounce, one ray per beam ray below it)
 * must not change what the image converges to. A glossy floor reflects a glossy ball and both
 * reflect a striped wall, so most pixels go through two glossy bounces. As the beam grows, the
 * image must approach a 256-ray reference (the per-pixel error shrinking about like 1/√rays) and
 * its mean brightness must not drift: a policy that dropped or double-counted the deeper bounces
 * would converge to a different image.
 */
@DisplayName("Glossy beams converge to the same image as the beam grows")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class BeamConvergenceTest {
    private static final int SIZE = 64;
    private static final int[] BEAMS = { 1, 4, 16, 64 };
    private static final int REFERENCE_BEAM = 256;

    private double[] reference;
    private final double[][] images = new double[BEAMS.length][];

    private static Scene scene() {
        Scene scene = new Scene("two glossy bounces").setBackground(new Color(10, 10, 20))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.05));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(10, 10, 10))
                        .setMaterial(new Material().setKr(0.8).setReflectionSpread(0.12)),
                new Sphere(new Point(0, 30, 0), 30).setEmission(new Color(20, 10, 10))
                        .setMaterial(new Material().setKr(0.85).setReflectionSpread(0.15)));
        // Alternating bright and dark vertical stripes on a wall behind and one in front (behind the camera).
        for (int k = -6; k < 6; ++k) {
            Color c = k % 2 == 0 ? new Color(240, 220, 160) : new Color(30, 60, 140);
            double x = 30 * k;
            scene.geometries.add(new Polygon(new Point(x, 0, -120), new Point(x + 30, 0, -120),
                    new Point(x + 30, 150, -120), new Point(x, 150, -120)).setEmission(c));
            scene.geometries.add(new Polygon(new Point(x, 0, 320), new Point(x, 150, 320),
                    new Point(x + 30, 150, 320), new Point(x + 30, 0, 320)).setEmission(c));
        }
        return scene;
    }

    private static double[] render(int beam) {
        ImageWriter image = new ImageWriter("effects-convergence", SIZE, SIZE);
        Camera.getBuilder().setLocation(new Point(0, 50, 250)).setDirection(new Point(0, 20, 0), Vector.AXIS_Y)
                .setVpSize(100, 100).setVpDistance(250).setImageWriter(image)
                .setRayTracer(new RayTracerBasic(scene()).setBeamSize(beam)).setSummary(false).build().renderImage();
        double[] luma = new double[SIZE * SIZE];
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x) luma[y * SIZE + x] = Profiles.luma(image, x, y);
        return luma;
    }

    @BeforeAll
    void renderAll() {
        reference = render(REFERENCE_BEAM);
        for (int i = 0; i < BEAMS.length; ++i) images[i] = render(BEAMS[i]);
    }

    private double rmsError(double[] image) {
        double sum = 0;
        for (int i = 0; i < image.length; ++i) sum += (image[i] - reference[i]) * (image[i] - reference[i]);
        return Math.sqrt(sum / image.length);
    }

    @Test
    @DisplayName("the per-pixel error shrinks with every 4× larger beam, by at least a third")
    void errorShrinks() {
        double previous = Double.POSITIVE_INFINITY;
        for (int i = 0; i < BEAMS.length; ++i) {
            double error = rmsError(images[i]);
            assertThat(error).as("RMS error (0..255 luma) of beam %d vs %d rays; previous beam %.2f", BEAMS[i],
                    REFERENCE_BEAM, previous).isLessThan(previous * 2 / 3);
            previous = error;
        }
    }

    @Test
    @DisplayName("the mean brightness is the same for every beam size (no bias from the deeper bounces)")
    void meanDoesNotDrift() {
        double target = Profiles.mean(reference, 0, reference.length);
        assertThat(target).as("reference mean brightness").isGreaterThan(40);
        for (int i = 0; i < BEAMS.length; ++i) {
            // Noise alone moves the mean by about its standard error, RMS error / √pixels; allow three.
            double tolerance = 3 * rmsError(images[i]) / Math.sqrt(images[i].length);
            assertThat(Profiles.mean(images[i], 0, images[i].length))
                    .as("mean brightness with a beam of %d (tolerance %.2f)", BEAMS[i], tolerance)
                    .isCloseTo(target, offset(tolerance));
        }
    }
}
