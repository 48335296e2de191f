package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.MissingResourceException;
import java.util.function.Consumer;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * The camera builder's contract: every bad value is rejected with an IllegalArgumentException
 * naming it (at once by most setters, by {@code build()} for the view plane and the resolution),
 * a missing location or direction fails {@code build()} with a MissingResourceException whose key
 * names the part, a missing view plane with an IllegalArgumentException, a missing image or tracer
 * is defaulted, and a reused builder gives independent cameras.
 */
class CameraBuilderTest {
    private static Camera.Builder complete() {
        return Camera.getBuilder()
                .setLocation(Point.ZERO)
                .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(4, 4).setVpDistance(10)
                .setImageWriter(new ImageWriter("builder", 4, 4))
                .setRayTracer(new RayTracerBasic(new Scene("builder")))
                .setSummary(false);
    }

    @Nested
    @DisplayName("view settings")
    class View {
        @Test
        @DisplayName("non-orthogonal 'to' and 'up' are rejected, naming both")
        void nonOrthogonal() {
            Vector to = new Vector(0, 0, -1), up = new Vector(0, 1, 0.1);
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setDirection(to, up))
                    .withMessageContaining("orthogonal").withMessageContaining(to.toString())
                    .withMessageContaining(up.toString());
        }

        @ParameterizedTest(name = "width {0}, height {1}")
        @CsvSource({"0, 4, 0.0", "-2, 4, -2.0", "4, 0, 0.0", "4, -0.5, -0.5", "NaN, 4, NaN", "4, Infinity, Infinity"})
        @DisplayName("a view-plane size that is not a positive finite number is rejected by build()")
        void vpSize(double width, double height, String named) {
            Camera.Builder builder = complete().setVpSize(width, height);
            assertThatIllegalArgumentException().isThrownBy(builder::build)
                    .withMessageContaining("view plane").withMessageContaining(named);
        }

        @ParameterizedTest(name = "distance {0}")
        @ValueSource(doubles = {0, -1, Double.NaN})
        @DisplayName("a view-plane distance that is not positive is rejected by build()")
        void vpDistance(double distance) {
            Camera.Builder builder = complete().setVpDistance(distance);
            assertThatIllegalArgumentException().isThrownBy(builder::build)
                    .withMessageContaining("view plane distance").withMessageContaining(String.valueOf(distance));
        }

        @ParameterizedTest(name = "{0}x{1}")
        @CsvSource({"0, 4", "4, 0", "-1, 1"})
        @DisplayName("a resolution that is not positive is rejected by build(), naming it")
        void resolution(int nX, int nY) {
            Camera.Builder builder = complete().setResolution(nX, nY);
            assertThatIllegalArgumentException().isThrownBy(builder::build).withMessageContaining(nX + "x" + nY);
        }

        @Test
        @DisplayName("nulls are rejected, naming the part")
        void nulls() {
            assertThatThrownBy(() -> Camera.getBuilder().setLocation(null)).hasMessageContaining("location");
            assertThatThrownBy(() -> Camera.getBuilder().setImageWriter(null)).hasMessageContaining("image writer");
            assertThatThrownBy(() -> Camera.getBuilder().setRayTracer(null)).hasMessageContaining("ray tracer");
        }
    }

    @Nested
    @DisplayName("a missing part fails build() naming it")
    class Missing {
        static Stream<Arguments> parts() {
            // Each case sets everything but one part (build() checks them in this order).
            return Stream.of(
                    Arguments.of("location", (Consumer<Camera.Builder>) b -> {}),
                    Arguments.of("direction", (Consumer<Camera.Builder>) b -> b.setLocation(Point.ZERO)));
        }

        @ParameterizedTest(name = "missing {0}")
        @MethodSource("parts")
        void missingPart(String key, Consumer<Camera.Builder> setEverythingElse) {
            Camera.Builder builder = Camera.getBuilder();
            setEverythingElse.accept(builder);
            assertThatThrownBy(builder::build).isInstanceOfSatisfying(MissingResourceException.class, e -> {
                assertThat(e.getKey()).isEqualTo(key);
                assertThat(e.getClassName()).isEqualTo("Camera");
            });
        }

        @Test
        @DisplayName("a missing view-plane size or distance is an IllegalArgumentException naming it")
        void viewPlane() {
            Camera.Builder noSize = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(0, 0, -1));
            assertThatIllegalArgumentException().isThrownBy(noSize::build).withMessageContaining("view plane size");
            Camera.Builder noDistance = noSize.setVpSize(1, 1);
            assertThatIllegalArgumentException().isThrownBy(noDistance::build).withMessageContaining("view plane distance");
        }

        @Test
        @DisplayName("without an image writer or tracer the camera gets a 1x1 image and a SimpleRayTracer")
        void defaults() {
            Camera camera = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(0, 0, -1))
                    .setVpSize(1, 1).setVpDistance(1).build();
            assertThat(camera.imageWriter().getNx()).isEqualTo(1);
            assertThat(camera.imageWriter().getNy()).isEqualTo(1);
            assertThat(camera.rayTracer()).isExactlyInstanceOf(SimpleRayTracer.class);
        }

        @Test
        @DisplayName("the complete builder builds")
        void complete() {
            assertThat(CameraBuilderTest.complete().build()).isNotNull();
        }
    }

    @Nested
    @DisplayName("builder reuse")
    class Reuse {
        @Test
        @DisplayName("a camera does not change when its builder is changed and built again")
        void independentCameras() {
            Camera.Builder builder = complete();
            Camera first = builder.build();
            Ray firstRay = first.constructRay(3, 3, 0, 0);
            Camera second = builder.setLocation(new Point(1, 2, 3)).setVpSize(9, 9)
                    .setDirection(new Vector(1, 0, 0), new Vector(0, 0, 1)).build();

            assertThat(second).isNotSameAs(first);
            assertThat(first.getLocation()).isEqualTo(Point.ZERO);
            assertThat(first.getVTo()).isEqualTo(new Vector(0, 0, -1));
            assertThat(first.constructRay(3, 3, 0, 0)).isEqualTo(firstRay);
            assertThat(second.getLocation()).isEqualTo(new Point(1, 2, 3));
            assertThat(second.getVTo()).isEqualTo(new Vector(1, 0, 0));
            assertThat(second.constructRay(3, 3, 0, 0)).isNotEqualTo(firstRay);
        }

        @Test
        @DisplayName("sampling settings are copied at build() too")
        void samplingCopied() {
            Camera.Builder builder = complete();
            Camera plain = builder.build();
            builder.setAntiAliasing(AntiAliasing.RANDOM, 3, 2).setDepthOfField(5, 0.5).setSeed(7);
            Camera fancy = builder.build();
            assertThat(plain.sampling()).isEqualTo(Sampling.DEFAULT);
            assertThat(plain.view().lens()).isEqualTo(renderer.View.Lens.PINHOLE);
            assertThat(fancy.sampling()).isEqualTo(Sampling.DEFAULT.withAntiAliasing(AntiAliasing.RANDOM).withGrid(3, 2).withSeed(7));
            assertThat(fancy.view().lens()).isEqualTo(new renderer.View.Lens(0.5, 5));
        }
    }

    @Nested
    @DisplayName("sampling and execution settings")
    class Settings {
        @ParameterizedTest(name = "grid {0}x{1}")
        @CsvSource({"0, 3", "3, 0", "-1, 4", "0, 0"})
        @DisplayName("an anti-aliasing grid below 1x1 is rejected")
        void grid(int columns, int rows) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setAntiAliasingGrid(columns, rows))
                    .withMessageContaining(columns + "x" + rows);
            assertThatIllegalArgumentException()
                    .isThrownBy(() -> Camera.getBuilder().setAntiAliasing(AntiAliasing.RANDOM, columns, rows))
                    .withMessageContaining(columns + "x" + rows);
        }

        @ParameterizedTest(name = "{0}")
        @EnumSource(value = AntiAliasing.class, names = "RANDOM", mode = EnumSource.Mode.EXCLUDE)
        @DisplayName("a grid with a mode other than RANDOM is rejected, naming the mode")
        void gridOnlyForRandom(AntiAliasing mode) {
            assertThatIllegalArgumentException()
                    .isThrownBy(() -> Camera.getBuilder().setAntiAliasing(mode, 2, 2))
                    .withMessageContaining("RANDOM").withMessageContaining(mode.name());
        }

        @ParameterizedTest(name = "depth {0}")
        @ValueSource(ints = {0, -1, 7, 10})
        @DisplayName("an adaptive depth outside 1..6 is rejected")
        void adaptiveDepth(int depth) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setAdaptive(depth, 8))
                    .withMessageContaining("adaptive depth").withMessageContaining("got " + depth);
        }

        @ParameterizedTest(name = "depth {0}")
        @ValueSource(ints = {1, 6})
        @DisplayName("adaptive depths 1 and 6 are accepted")
        void adaptiveDepthBounds(int depth) {
            assertThat(complete().setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(depth, 0).build().sampling().adaptive())
                    .isEqualTo(new Sampling.Adaptive(depth, 0));
        }

        @ParameterizedTest(name = "threshold {0}")
        @ValueSource(doubles = {-1, -0.001, Double.NaN})
        @DisplayName("a negative adaptive threshold is rejected")
        void adaptiveThreshold(double threshold) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setAdaptive(3, threshold))
                    .withMessageContaining("adaptive threshold").withMessageContaining(String.valueOf(threshold));
        }

        @ParameterizedTest(name = "aperture {0}")
        @ValueSource(doubles = {-0.5, -1e-9, Double.NaN})
        @DisplayName("a negative aperture is rejected")
        void aperture(double aperture) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setDepthOfField(10, aperture))
                    .withMessageContaining("aperture").withMessageContaining(String.valueOf(aperture));
        }

        @ParameterizedTest(name = "focal distance {0}")
        @ValueSource(doubles = {0, -3, Double.NaN, Double.POSITIVE_INFINITY})
        @DisplayName("a focal distance that is not a positive finite number is rejected")
        void focalDistance(double focal) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setDepthOfField(focal, 1))
                    .withMessageContaining("focal distance").withMessageContaining(String.valueOf(focal));
        }

        @ParameterizedTest(name = "samples {0}")
        @ValueSource(ints = {0, -4})
        @DisplayName("fewer than one lens sample is rejected")
        void lensSamples(int samples) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setDepthOfFieldSamples(samples))
                    .withMessageContaining("got " + samples);
        }

        @ParameterizedTest(name = "threads {0}")
        @ValueSource(ints = {-3, -100})
        @DisplayName("thread counts below -2 are rejected")
        void threads(int threads) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setMultithreading(threads))
                    .withMessageContaining("got " + threads);
        }

        @ParameterizedTest(name = "threads {0}")
        @ValueSource(ints = {0, 1, 3, -2, -1})
        @DisplayName("thread counts 0, positive, -2 (all cores) and -1 (the course's parallel streams: all cores) are accepted")
        void threadsAccepted(int threads) {
            assertThat(complete().setMultithreading(threads).build()).isNotNull();
        }

        @ParameterizedTest(name = "step {0}")
        @ValueSource(doubles = {100.5, 101, -1, -0.1, Double.NaN})
        @DisplayName("a debug-print step outside [0, 100] percent is rejected")
        void debugPrint(double step) {
            assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setDebugPrint(step))
                    .withMessageContaining("got " + step);
        }

        @Test
        @DisplayName("null mode or output are rejected")
        void nulls() {
            assertThatThrownBy(() -> Camera.getBuilder().setAntiAliasing(null)).hasMessageContaining("anti-aliasing");
            assertThatThrownBy(() -> Camera.getBuilder().setOutput(null)).hasMessageContaining("output");
        }
    }

    @Nested
    @DisplayName("tracer settings")
    class Tracer {
        @ParameterizedTest(name = "{0}")
        @ValueSource(ints = {0, -1})
        void beamAndShadowSamplesAtLeastOne(int n) {
            RayTracerBasic tracer = new RayTracerBasic(new Scene("tracer"));
            assertThatIllegalArgumentException().isThrownBy(() -> tracer.setBeamSize(n)).withMessageContaining("got " + n);
            assertThatIllegalArgumentException().isThrownBy(() -> tracer.setShadowSamples(n))
                    .withMessageContaining("got " + n);
        }

        @Test
        void nullSceneRejected() {
            assertThatThrownBy(() -> new RayTracerBasic(null)).hasMessageContaining("scene");
        }
    }
}
