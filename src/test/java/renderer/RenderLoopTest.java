package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.BitSet;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/** The render loop: where each pixel lands, and a tracer that fails part-way through a render. */
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

    /**
     * Paints each camera ray with the pixel it passes through, read back from its direction: the
     * camera sits at the origin looking down −z at a view plane 10 away, one unit per pixel, so a
     * ray through the centre of pixel (x, y) crosses the plane at (x + 0.5 − nX/2, nY/2 − y − 0.5).
     */
    private static final class PixelOfRay extends RayTracerBase {
        private final int nX, nY;

        PixelOfRay(int nX, int nY) {
            super(new Scene("pixel of ray"));
            this.nX = nX;
            this.nY = nY;
        }

        @Override
        public Color traceRay(Ray ray) {
            Vector d = ray.getDirection();
            double s = 10 / -d.getZ();
            int x = (int) Math.floor(d.getX() * s + nX / 2.0), y = (int) Math.floor(nY / 2.0 - d.getY() * s);
            return new Color(x, y, 99);
        }
    }

    @ParameterizedTest(name = "{0}x{1} pixels, {2} threads")
    @CsvSource({"37, 23, 0", "37, 23, 1", "37, 23, 2", "37, 23, 3", "16, 16, 2", "5, 40, 2", "100, 3, 4"})
    @DisplayName("every pixel lands where its ray points, on any thread count, with tiles cut at the image's edges")
    void pixelsLandWhereTheirRaysPoint(int nX, int nY, int threads) {
        ImageWriter image = new ImageWriter("pixel-of-ray", nX, nY);
        Camera.getBuilder()
                .setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(nX, nY).setVpDistance(10)
                .setImageWriter(image).setRayTracer(new PixelOfRay(nX, nY))
                .setMultithreading(threads).setSummary(false)
                .build().renderImage();
        for (int y = 0; y < nY; ++y)
            for (int x = 0; x < nX; ++x)
                assertThat(image.getRgb(x, y)).as("pixel (%d,%d)", x, y).isEqualTo(x << 16 | y << 8 | 99);
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
        // Each other worker may finish the tile it is on, but claims no new one once the failure
        // is recorded: a few tiles of 256 rays, not the 65 536 of the whole image. How many
        // depends on the scheduler (on two cores under load, the failing worker was once
        // descheduled between its throw and the record while three others traced 27 tiles), so
        // the bound is half the image, which workers that ignored the failure would pass.
        assertThat(tracer.calls.get()).as("rays traced").isLessThan(size * size / 2);
    }

    @ParameterizedTest(name = "{0} tiles")
    @ValueSource(ints = { 1, 2, 3, 4, 6, 36, 100, 1444, 1445 })
    @DisplayName("tiles are claimed in a spread order that renders every tile exactly once")
    void everyTileOnce(int count) {
        int stride = RenderLoop.spreadingStride(count);
        BitSet seen = new BitSet(count);
        for (int k = 0; k < count; ++k) seen.set((int) ((long) k * stride % count));
        assertThat(seen.cardinality()).isEqualTo(count);
    }

    @Test
    @DisplayName("the first tenth of the claims reaches every tenth of a 38×38-tile image's rows (600×600 in 16-pixel tiles)")
    void firstClaimsSpread() {
        int side = 38, count = side * side, stride = RenderLoop.spreadingStride(count);
        BitSet bands = new BitSet(10);
        for (int k = 0; k < count / 10; ++k) bands.set((int) ((long) k * stride % count) / side * 10 / side);
        assertThat(bands.cardinality()).isEqualTo(10);
    }

    @ParameterizedTest(name = "{0} threads")
    @ValueSource(ints = { 0, 2 })
    @DisplayName("collections during a render, after each of which every worker makes its records anew, change no pixel and no ray count")
    void collectionsChangeNothing(int threads) throws InterruptedException {
        ImageWriter quiet = new ImageWriter("collections", 64, 48), collected = new ImageWriter("collections", 64, 48);
        RenderStats expected = TestScenes.camera(TestScenes.everyEffect(), quiet).setMultithreading(threads).build().render();
        // Collections as often as the machine allows while the same render runs: each clears
        // the workers' weak reference, so that each worker makes its records anew at its next tile.
        AtomicInteger collections = new AtomicInteger();
        AtomicBoolean rendering = new AtomicBoolean(true);
        Thread collector = new Thread(() -> {
            while (rendering.get()) {
                System.gc();
                collections.incrementAndGet();
            }
        });
        collector.start();
        RenderStats stats;
        try {
            stats = TestScenes.camera(TestScenes.everyEffect(), collected).setMultithreading(threads).build().render();
        } finally {
            rendering.set(false);
            collector.join();
        }
        assertThat(collections.get()).as("collections during the render").isGreaterThan(1);
        assertThat(new long[] { stats.cameraRays(), stats.shadowRays(), stats.secondaryRays() })
                .as("camera, shadow and secondary rays")
                .containsExactly(expected.cameraRays(), expected.shadowRays(), expected.secondaryRays());
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x)
                assertThat(collected.getRgb(x, y)).as("pixel (%d,%d)", x, y).isEqualTo(quiet.getRgb(x, y));
    }
}
