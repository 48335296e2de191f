package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Plane;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * {@link Sampling}: the budget it states is the rays its samplers spend. For every mode, with and
 * without a lens, a one-pixel render at its worst case traces exactly
 * {@link Sampling#maxSamplesPerPixel} camera rays, the one figure the builder and the scene files
 * ({@link RayBudget#require(Sampling, boolean, int, int, java.util.Collection)}) hold a pixel to.
 */
class SamplingTest {
    /**
     * A lit plane filling the view with a gradient: a point light close to it makes every lattice
     * point of a pixel a different colour (below 255), so that ADAPTIVE at threshold 0 splits every
     * square down to its deepest level.
     */
    private static Scene gradient() {
        Scene scene = new Scene("gradient");
        scene.geometries.add(new Plane(new Point(0, 0, -2), new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.5)));
        scene.lights.add(new PointLight(new Color(200, 150, 100), new Point(0.3, 0.2, -1.5)));
        return scene;
    }

    /** A one-pixel camera seeing 2×2 scene units of the gradient. */
    private static Camera.Builder onePixel() {
        return Camera.getBuilder().setLocation(new Point(0, 0, 10)).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(2, 2).setVpDistance(12).setResolution(1, 1).setRayTracer(new RayTracerBasic(gradient()))
                .setSummary(false);
    }

    static Stream<Arguments> modes() {
        return Stream.of(
                Arguments.of("NONE", (UnaryOperator<Camera.Builder>) b -> b),
                Arguments.of("RANDOM 3x2", (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.RANDOM, 3, 2)),
                Arguments.of("CORNERS", (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.CORNERS)),
                Arguments.of("ADAPTIVE depth 1, threshold 0", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(1, 0)),
                Arguments.of("ADAPTIVE depth 3, threshold 0", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 0)),
                Arguments.of("ADAPTIVE depth 4, threshold 0", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(4, 0)));
    }

    @Nested
    @DisplayName("the budget is the camera rays a worst-case pixel traces")
    class Budget {
        @ParameterizedTest(name = "{0}, pinhole")
        @MethodSource("renderer.SamplingTest#modes")
        void pinhole(String name, UnaryOperator<Camera.Builder> mode) {
            assertBudgetIsTraced(mode.apply(onePixel()).build());
        }

        @ParameterizedTest(name = "{0}, depth of field with 7 lens samples")
        @MethodSource("renderer.SamplingTest#modes")
        void lens(String name, UnaryOperator<Camera.Builder> mode) {
            assertBudgetIsTraced(mode.apply(onePixel()).setDepthOfField(12, 0.3).setDepthOfFieldSamples(7).build());
        }

        private void assertBudgetIsTraced(Camera camera) {
            Sampling s = camera.sampling();
            boolean lens = !camera.view().lens().isPinhole();
            long budget = s.maxSamplesPerPixel(lens);
            assertThat(camera.render().cameraRays()).as("camera rays traced for the pixel").isEqualTo(budget);
        }

        @Test
        @DisplayName("ADAPTIVE depth 3 takes at most 81 camera rays a pixel, (2^3 + 1)²")
        void adaptiveFigure() {
            assertThat(onePixel().setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 8).build().sampling()
                    .maxSamplesPerPixel(false)).isEqualTo(81);
        }

        @Test
        @DisplayName("ADAPTIVE depth 3 with a lens takes at most 64 camera rays a pixel, 4^3")
        void adaptiveLensFigure() {
            assertThat(onePixel().setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 8).build().sampling()
                    .maxSamplesPerPixel(true)).isEqualTo(64);
        }
    }

    /** The test is "more than the threshold": at 0, corners that agree exactly are not subdivided. */
    @Nested
    @DisplayName("ADAPTIVE at threshold 0 subdivides where the corners differ, not where they agree")
    class ThresholdZero {
        private long cameraRays(Scene scene, boolean lens) {
            Camera.Builder b = onePixel().setRayTracer(new RayTracerBasic(scene)).setAntiAliasing(AntiAliasing.ADAPTIVE)
                    .setAdaptive(3, 0);
            if (lens) b.setDepthOfField(12, 0.3);
            return b.build().render().cameraRays();
        }

        @ParameterizedTest(name = "lens: {0}")
        @ValueSource(booleans = { false, true })
        @DisplayName("a flat background: the first corners (or samples) agree, nothing more is traced")
        void flat(boolean lens) {
            long traced = cameraRays(new Scene("flat background"), lens);
            assertThat(traced).as("camera rays of a flat pixel").isEqualTo(lens ? 8 : 4)
                    .isLessThan(onePixel().setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 0).build().sampling()
                            .maxSamplesPerPixel(lens));
        }

        @Test
        @DisplayName("a gradient: every square is subdivided down to the deepest level")
        void gradientSplits() {
            assertThat(cameraRays(SamplingTest.gradient(), false)).isEqualTo(81);
        }
    }

    @Nested
    @DisplayName("the value's checks are the builder's")
    class Checks {
        @Test
        @DisplayName("a grid below 1x1 or above 65536 cells, a depth outside 1..6, a negative threshold, lens samples out of range")
        void refused() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Sampling.Grid(0, 3))
                    .withMessage("anti-aliasing grid must be at least 1x1, got 0x3");
            assertThatIllegalArgumentException().isThrownBy(() -> new Sampling.Grid(257, 256))
                    .withMessage("anti-aliasing grid 257x256 has 65792 samples per pixel, more than the limit of 65536");
            assertThatIllegalArgumentException().isThrownBy(() -> new Sampling.Adaptive(7, 8))
                    .withMessage("adaptive depth must be in 1..6, got 7");
            assertThatIllegalArgumentException().isThrownBy(() -> new Sampling.Adaptive(3, -1))
                    .withMessageContaining("adaptive threshold");
            assertThatIllegalArgumentException().isThrownBy(() -> new Sampling(AntiAliasing.NONE, Sampling.DEFAULT.grid(), Sampling.DEFAULT.adaptive(), 0, 0))
                    .withMessage("depth-of-field samples must be from 1 to 65536, got 0");
        }
    }
}
