package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.time.Duration;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import scene.Scene;

/**
 * The Java API's ray budget: a camera whose pixel would take more than
 * {@link RayBudget#MAX_RAYS_PER_PIXEL} rays is refused, as a scene file is; and a render
 * interrupted in the middle of a pixel of millions of rays stops within a bounded time.
 */
class RayBudgetTest {
    /** A camera on {@link TestScenes#EYE} of side × side pixels with {@code tracer}. */
    private static Camera.Builder camera(RayTracerBasic tracer, int side) {
        return Camera.getBuilder().setLocation(TestScenes.EYE)
                .setDirection(new primitives.Vector(0, 0, -1), new primitives.Vector(0, 1, 0))
                .setVpSize(side / 10.0, side / 10.0).setVpDistance(10).setResolution(side, side)
                .setRayTracer(tracer).setSummary(false);
    }

    @Nested
    @DisplayName("build() holds a camera to 2^24 rays per pixel, naming the factors")
    class Build {
        @ParameterizedTest(name = "{0} × beam {1} × {2} shadow samples")
        @CsvSource({
                "1, 1000000000, 16, NONE sampling with 1 samples per pixel × beam size 1000000000 × 16 shadow samples is 16000000000 rays per pixel",
                "1, 16, 1000000000, NONE sampling with 1 samples per pixel × beam size 16 × 1000000000 shadow samples is 16000000000 rays per pixel",
                "256, 4096, 4096, RANDOM sampling with 65536 samples per pixel × beam size 4096 × 4096 shadow samples is 1099511627776 rays per pixel" })
        void refused(int grid, int beam, int shadows, String message) {
            Camera.Builder builder = camera(new RayTracerBasic(new Scene("s")).setBeamSize(beam).setShadowSamples(shadows), 1);
            if (grid > 1) builder.setAntiAliasing(AntiAliasing.RANDOM, grid, grid);
            assertThatThrownBy(builder::build).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage(message + ", more than the limit of 16777216");
        }

        @Test
        @DisplayName("requireRayBudget() checks the sampling, lens and tracer alone: no view, no image needed")
        void withoutAView() {
            Camera.Builder noView = Camera.getBuilder()
                    .setRayTracer(new RayTracerBasic(new Scene("s")).setBeamSize(1_000_000_000));
            assertThatThrownBy(noView::requireRayBudget).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("NONE sampling with 1 samples per pixel × beam size 1000000000 × 16 shadow samples"
                            + " is 16000000000 rays per pixel, more than the limit of 16777216");
            Camera.Builder fits = Camera.getBuilder().setRayTracer(new RayTracerBasic(new Scene("s")))
                    .setAntiAliasing(AntiAliasing.ADAPTIVE);
            assertThat(fits.requireRayBudget()).isSameAs(fits);
        }

        @Test
        @DisplayName("refused before the image is allocated: a 40000x40000 resolution costs nothing")
        void beforeTheImage() {
            Camera.Builder builder = camera(new RayTracerBasic(new Scene("s")).setBeamSize(1_000_000_000), 1)
                    .setResolution(40_000, 40_000);
            assertThatThrownBy(builder::build).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("more than the limit of 16777216");
        }

        @Test
        @DisplayName("ADAPTIVE counts its lattice, (2^depth + 1)² points: depth 6 × 256 × 16 is over")
        void adaptive() {
            Camera.Builder builder = camera(new RayTracerBasic(new Scene("s")).setBeamSize(256).setShadowSamples(16), 1)
                    .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(6, 8);
            assertThatThrownBy(builder::build).hasMessage("ADAPTIVE sampling with 4225 samples per pixel × beam size 256"
                    + " × 16 shadow samples is 17305600 rays per pixel, more than the limit of 16777216");
            builder.setRayTracer(new RayTracerBasic(new Scene("s")).setBeamSize(248).setShadowSamples(16));
            assertThat(builder.build()).isNotNull(); // 4225 × 248 × 16 = 16,772,800
        }

        @Test
        @DisplayName("exactly the budget is accepted")
        void atTheLimit() {
            assertThat(camera(new RayTracerBasic(new Scene("s")).setBeamSize(4096).setShadowSamples(4096), 1).build())
                    .isNotNull();
        }

        @Test
        @DisplayName("a tracer raised after build() is refused when the render starts")
        void raisedLater() {
            RayTracerBasic tracer = new RayTracerBasic(new Scene("s"));
            Camera built = camera(tracer, 1).build();
            tracer.setShadowSamples(1 << 30);
            assertThatThrownBy(built::renderImage).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("× 1073741824 shadow samples is");
        }
    }

    @Nested
    @DisplayName("an interrupt stops a render inside a pixel of 2^24 rays")
    class Interrupt {
        @ParameterizedTest(name = "{0} threads")
        @ValueSource(ints = { 0, 2 })
        void stopsWithinAPixel(int threads) {
            // Beams of 4096 glossy rays, each shaded under two lights of 4096 shadow rays: seconds
            // per pixel, minutes for the image before the tracer asked within a pixel.
            RayTracerBasic tracer = new RayTracerBasic(TestScenes.everyEffect()).setBeamSize(4096).setShadowSamples(4096);
            Camera camera = camera(tracer, 16).setMultithreading(threads).build();
            AtomicReference<Throwable> thrown = new AtomicReference<>();
            CountDownLatch started = new CountDownLatch(1);
            Thread renderer = new Thread(() -> {
                started.countDown();
                try {
                    camera.renderImage();
                } catch (Throwable t) {
                    thrown.set(t);
                }
            }, "budget-render");
            assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
                renderer.start();
                started.await();
                TimeUnit.MILLISECONDS.sleep(300);
                renderer.interrupt();
                renderer.join();
            });
            assertThat(thrown.get()).isInstanceOf(CancellationException.class).hasMessageContaining("was interrupted");
        }
    }
}
