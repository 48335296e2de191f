package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.function.UnaryOperator;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import primitives.Color;
import scene.Scene;

/**
 * {@link NoiseAdaptiveSampler}, ADAPTIVE with depth of field: a pixel takes 8 samples, then 8 more
 * at a time while the standard error its samples show is above the threshold, up to 4^depth.
 * On {@link DepthOfFieldTest}'s boards: a white board at the focal distance (its edge sharp) and
 * one 30 behind it (its edge blurred over about 15 pixels), on black.
 */
class NoiseAdaptiveSamplerTest {
    private static final int SIZE = 40;

    private static Scene boards() {
        return DepthOfFieldTest.boards();
    }

    private record Render(ImageWriter image, RenderStats stats) {
    }

    private static Render render(Scene scene, UnaryOperator<Camera.Builder> settings) {
        ImageWriter image = new ImageWriter("noise-adaptive", SIZE, SIZE);
        RenderStats stats = settings.apply(TestScenes.camera(scene, image)).setDepthOfField(10, 1).setMultithreading(2)
                .build().render();
        return new Render(image, stats);
    }

    private static UnaryOperator<Camera.Builder> adaptive(int depth, double threshold) {
        return b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(depth, threshold);
    }

    @Nested
    @DisplayName("where the rays go")
    class Rays {
        @Test
        @DisplayName("a smooth image stops every pixel at its first test: 8 camera rays a pixel")
        void smoothStopsAtFirst() {
            Scene flat = new Scene("flat");
            flat.setBackground(new Color(40, 90, 200));
            assertThat(render(flat, adaptive(3, 8)).stats().cameraRays()).isEqualTo(8L * SIZE * SIZE);
        }

        @Test
        @DisplayName("the blurred edge takes more than the smooth parts, and never more than 4^depth a pixel")
        void blurTakesMore() {
            long rays = render(boards(), adaptive(3, 2)).stats().cameraRays();
            assertThat(rays).isGreaterThan(8L * SIZE * SIZE).isLessThanOrEqualTo(64L * SIZE * SIZE);
        }

        @Test
        @DisplayName("depth 1 caps a pixel at 4 samples, taken at once")
        void depthCaps() {
            assertThat(render(boards(), adaptive(1, 0)).stats().cameraRays()).isEqualTo(4L * SIZE * SIZE);
        }
    }

    @Nested
    @DisplayName("the threshold trades rays for error")
    class Threshold {
        @Test
        @DisplayName("a lower threshold spends more rays and lands closer to 256 lens samples a pixel")
        void lowerIsCloser() {
            ImageWriter reference = render(boards(), b -> b.setAntiAliasing(AntiAliasing.RANDOM, 16, 16)).image();
            Render fine = render(boards(), adaptive(3, 2)), coarse = render(boards(), adaptive(3, 16));
            assertThat(fine.stats().cameraRays()).isGreaterThan(coarse.stats().cameraRays());
            double fineError = Pixels.rmse(fine.image(), reference), coarseError = Pixels.rmse(coarse.image(), reference);
            assertThat(fineError).as("RMS error at threshold 2 (threshold 16: %.2f)", coarseError).isLessThan(coarseError);
        }

        @Test
        @DisplayName("the focal plane's edge stays sharp: no pixel between 10 % and 90 % on a row that sees only the near board")
        void focalPlaneSharp() {
            ImageWriter image = render(boards(), adaptive(3, 8)).image();
            for (int x = 0; x < SIZE; ++x) {
                int r = Pixels.red(image.getRgb(x, 5));
                assertThat(r).as("pixel (%d,5)", x).satisfiesAnyOf(v -> assertThat(v).isLessThanOrEqualTo(25),
                        v -> assertThat(v).isGreaterThanOrEqualTo(230));
            }
        }
    }
}
