package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.function.UnaryOperator;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Sphere;
import geometries.Triangle;
import primitives.Color;
import primitives.Point;
import scene.Scene;

/**
 * Anti-aliasing converges toward the true pixel averages. The reference is a RANDOM 16×16
 * render (256 jittered samples per pixel, another seed) of a 48×48 scene of flat-coloured shapes
 * with sharp, slanted and curved edges on a black background: large flat areas, where every mode
 * is exact, and edges, where they differ.
 */
class AntiAliasingQualityTest {
    private static final int SIZE = 48;
    private static ImageWriter reference;

    private static Scene scene() {
        Scene scene = new Scene("edges");
        scene.geometries.add(
                new Sphere(new Point(-0.8, 0.6, 0), 1.2).setEmission(new Color(255, 200, 50)),
                new Triangle(new Point(0.2, -2.1, 0), new Point(2.2, -1.5, 0), new Point(1.1, 2.1, 0))
                        .setEmission(new Color(50, 120, 255)));
        return scene;
    }

    private record Result(ImageWriter image, RenderStats stats) {
        double rmse() {
            return Pixels.rmse(image, reference);
        }
    }

    private static Result render(UnaryOperator<Camera.Builder> mode, long seed) {
        ImageWriter image = new ImageWriter("aa-quality", SIZE, SIZE);
        RenderStats stats = mode.apply(TestScenes.camera(scene(), image)).setSeed(seed).setMultithreading(2)
                .build().render();
        return new Result(image, stats);
    }

    @BeforeAll
    static void renderReference() {
        reference = render(b -> b.setAntiAliasing(AntiAliasing.RANDOM, 16, 16), 999).image();
    }

    @Test
    @DisplayName("RMSE falls from NONE to CORNERS to RANDOM 4x4 to RANDOM 8x8")
    void errorFallsWithMoreSamples() {
        Result none = render(b -> b, 1);
        Result corners = render(b -> b.setAntiAliasing(AntiAliasing.CORNERS), 1);
        Result random4 = render(b -> b.setAntiAliasing(AntiAliasing.RANDOM, 4, 4), 1);
        Result random8 = render(b -> b.setAntiAliasing(AntiAliasing.RANDOM, 8, 8), 1);

        assertThat(none.stats().cameraRays()).isEqualTo(SIZE * SIZE);
        assertThat(random4.stats().cameraRays()).isEqualTo(16 * SIZE * SIZE);
        assertThat(random8.stats().cameraRays()).isEqualTo(64 * SIZE * SIZE);
        // Corners are shared with the neighbours: well under the 5 rays per pixel of a naive count.
        assertThat(corners.stats().cameraRays()).isLessThan(3L * SIZE * SIZE);

        assertThat(none.rmse()).as("NONE").isGreaterThan(corners.rmse());
        assertThat(corners.rmse()).as("CORNERS").isGreaterThan(random4.rmse());
        assertThat(random4.rmse()).as("RANDOM 4x4").isGreaterThan(random8.rmse());
        // And the reference is a good one: RANDOM 8x8 is already close to it.
        assertThat(random8.rmse()).as("RANDOM 8x8").isLessThan(2);
    }

    @Test
    @DisplayName("ADAPTIVE depth 3 gets within 1.5x the error of RANDOM 8x8 with at least 4x fewer camera rays")
    void adaptiveIsCheapAndGood() {
        Result random8 = render(b -> b.setAntiAliasing(AntiAliasing.RANDOM, 8, 8), 1);
        Result adaptive = render(b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 8), 1);

        assertThat(adaptive.rmse()).as("ADAPTIVE RMSE vs RANDOM 8x8's %.3f", random8.rmse())
                .isLessThanOrEqualTo(1.5 * random8.rmse());
        assertThat(adaptive.stats().cameraRays()).as("ADAPTIVE camera rays")
                .isLessThanOrEqualTo(random8.stats().cameraRays() / 4);
    }

    @Test
    @DisplayName("ADAPTIVE does not subdivide a flat image, even with threshold 0: one ray per pixel corner")
    void adaptiveOnFlatImage() {
        Scene flat = new Scene("flat").setBackground(new Color(30, 60, 90));
        ImageWriter adaptiveImage = new ImageWriter("flat-adaptive", SIZE, SIZE);
        long adaptive = TestScenes.camera(flat, adaptiveImage).setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 0)
                .build().render().cameraRays();
        // Each pixel corner once, those on the borders between tiles too (LatticeSeams).
        assertThat(SIZE).as("more than one tile").isGreaterThan(LatticeSampler.Plan.adaptive(0, 3, 0).tileSize());
        assertThat(adaptive).isEqualTo((long) (SIZE + 1) * (SIZE + 1));
        assertThat(Pixels.of(adaptiveImage)).containsOnly(0x1E3C5A);
    }
}
