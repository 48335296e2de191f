package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/** The render loop's handling of a tracer that fails part-way through a render. */
class RenderLoopTest {
    /** Fails on its {@code failAt}-th call; counts every call, from any thread. */
    private static final class FailingTracer extends RayTracerBase {
        final AtomicInteger calls = new AtomicInteger();
        private final int failAt;

        FailingTracer(int failAt) {
            super(new Scene("failing"));
            this.failAt = failAt;
        }

        @Override
        public Color traceRay(Ray ray) {
            if (calls.incrementAndGet() == failAt) throw new IllegalStateException("tracer failed on purpose");
            return Color.BLACK;
        }
    }

    @ParameterizedTest(name = "{0} threads")
    @ValueSource(ints = {0, 1, 2, 4})
    @DisplayName("a failing tracer fails the render with its own exception, and the other workers stop too")
    void failureStopsTheRender(int threads) {
        int size = 256; // 256 tiles of 16x16
        FailingTracer tracer = new FailingTracer(100);
        Camera camera = Camera.getBuilder()
                .setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(1, 1).setVpDistance(1)
                .setImageWriter(new ImageWriter("failing", size, size)).setRayTracer(tracer)
                .setMultithreading(threads).setSummary(false)
                .build();
        assertThatThrownBy(camera::renderImage).isInstanceOf(IllegalStateException.class)
                .hasMessage("tracer failed on purpose");
        // Each other worker may finish the tile it is on, but claims no new one: a few tiles of
        // 256 rays, not the 65 536 of the whole image.
        assertThat(tracer.calls.get()).as("rays traced").isLessThanOrEqualTo(100 + threads * 2 * 256);
    }
}
