package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Rgb;
import primitives.Vector;
import scene.Scene;

/**
 * The render loop tells its prepared tracer how many camera rays the render traces at least,
 * before any of them ({@link PreparedTracer#expectCameraRays}), and that the render is long
 * ({@link PreparedTracer#expectLongRender}, where the scene's tree warms its vector walk) once its
 * pace, measured after its first {@link RenderLoop#PACE_SECONDS} over at least as long, leaves
 * {@link RenderLoop#LONG_RENDER_SECONDS} or more of work; a short render never does, even one whose
 * first tiles were slow.
 */
@DisplayName("a render says when it is long, and a short one never does")
class LongRenderTest {
    /** A tracer whose camera samples take {@code nanosPerSample} each until it is told the render is long. */
    private static final class Paced extends RayTracerBase {
        final AtomicInteger told = new AtomicInteger();
        final AtomicInteger samples = new AtomicInteger();
        /** The camera rays the render announced, and how many samples had been traced by then (−1: none announced). */
        final AtomicLong announced = new AtomicLong(-1), samplesBefore = new AtomicLong(-1);
        volatile long nanosPerSample;

        Paced(long nanosPerSample) {
            super(new Scene("paced"));
            this.nanosPerSample = nanosPerSample;
        }

        @Override
        public Color traceRay(Ray ray) {
            return Color.BLACK;
        }

        @Override
        PreparedTracer prepare() {
            return new PreparedTracer() {
                @Override
                public Rgb traceRay(TraceContext ctx) {
                    samples.incrementAndGet();
                    long nanos = nanosPerSample;
                    if (nanos > 0) LockSupport.parkNanos(nanos);
                    return ctx.cameraColour().set(Color.BLACK);
                }

                @Override
                public void expectCameraRays(long cameraRays) {
                    samplesBefore.set(samples.get());
                    announced.set(cameraRays);
                }

                @Override
                public void expectLongRender() {
                    told.incrementAndGet();
                    nanosPerSample = 0; // told: the rest of the render runs at once
                }
            };
        }
    }

    private static Camera.Builder builder(Paced tracer) {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(1, 1).setVpDistance(1).setResolution(100, 100).setRayTracer(tracer).setMultithreading(0)
                .setSummary(false);
    }

    private static Camera camera(Paced tracer) {
        return builder(tracer).build();
    }

    @ParameterizedTest(name = "{0} {1}x{1}: {2} camera rays")
    @CsvSource({ "NONE, 1, 10000", "RANDOM, 4, 160000", "CORNERS, 1, 20000", "ADAPTIVE, 1, 10000" })
    @DisplayName("before its first sample, a render announces its camera rays: pixels times the fewest a pixel takes")
    void announcesItsSize(AntiAliasing mode, int grid, long expected) {
        Paced tracer = new Paced(0);
        Camera.Builder b = builder(tracer);
        if (mode != AntiAliasing.RANDOM) b.setAntiAliasing(mode);
        else b.setAntiAliasing(mode, grid, grid);
        b.build().render();
        assertThat(tracer.announced.get()).isEqualTo(expected);
        assertThat(tracer.samplesBefore.get()).as("samples traced before the announcement").isZero();
        assertThat(tracer.samples.get()).as("samples traced").isGreaterThanOrEqualTo((int) expected);
    }

    @Test
    @DisplayName("10,000 samples of 2 ms each (a 20 s render): told once its pace promises 8 s more")
    void long_() {
        Paced tracer = new Paced(2_000_000);
        camera(tracer).render();
        assertThat(tracer.told.get()).as("calls once the pace promised 8 s more").isPositive();
    }

    @Test
    @DisplayName("slow for its first 1.2 s, then 0.4 s of work: never told (the pace from the start promised 20 s more)")
    void slowOnlyWhileWarmingUp() {
        Paced tracer = new Paced(2_000_000);
        long fastFrom = System.nanoTime() + 1_200_000_000L;
        Camera camera = builder(tracer).build();
        Thread warmedUp = new Thread(() -> {
            LockSupport.parkNanos(fastFrom - System.nanoTime());
            tracer.nanosPerSample = 40_000; // as the code's compilation ends
        });
        warmedUp.start();
        camera.render();
        assertThat(tracer.told.get()).isZero();
        assertThat(tracer.nanosPerSample).as("the render outlasted its warm-up").isEqualTo(40_000);
    }

    @Test
    @DisplayName("the same render at once: never told")
    void short_() {
        Paced tracer = new Paced(0);
        camera(tracer).render();
        assertThat(tracer.told.get()).isZero();
    }
}
