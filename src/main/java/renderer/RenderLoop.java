package renderer;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The one render loop. The image is cut into square tiles; workers claim tiles from an atomic
 * counter (no lock per pixel) and sample every pixel of a tile with their own
 * {@link PixelSampler} and {@link TraceContext}. Which worker renders a tile does not change its
 * pixels: every random number comes from streams keyed by the pixel, so images are identical
 * for any thread count.
 */
final class RenderLoop {
    private final Camera camera;
    private final ImageWriter image;
    /** The image's name in progress lines, thread names and messages. */
    private final String name;
    /** The rectangle rendered: columns [x0, x1), rows [y0, y1); the whole image unless a region was asked for. */
    private final int x0, y0, x1, y1;
    private final int tile;
    private final int tilesX;
    private final int tileCount;
    private final AtomicInteger nextTile = new AtomicInteger();
    private final AtomicBoolean cancelled = new AtomicBoolean();
    /** The first exception a worker failed with; the others then stop and it is rethrown. */
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    private final RenderStats.Counter counter = new RenderStats.Counter();

    /** A loop over the whole image; {@code name} labels its progress lines and worker threads. */
    RenderLoop(Camera camera, String name) {
        this(camera, name, 0, 0, camera.imageWriter().getNx(), camera.imageWriter().getNy());
    }

    /**
     * A loop over the rectangle of columns [x0, x1) and rows [y0, y1) only (the caller checked
     * that it lies in the image). Its tiles start at (x0, y0); a pixel's value does not depend on
     * the tiling (see {@link LatticeSampler}), so a rectangle renders exactly as it does within
     * the whole image.
     */
    RenderLoop(Camera camera, int x0, int y0, int x1, int y1) {
        this(camera, camera.imageWriter().getImageName(), x0, y0, x1, y1);
    }

    private RenderLoop(Camera camera, String name, int x0, int y0, int x1, int y1) {
        this.camera = camera;
        this.name = name;
        this.image = camera.imageWriter();
        this.x0 = x0;
        this.y0 = y0;
        this.x1 = x1;
        this.y1 = y1;
        this.tile = camera.tileSize();
        this.tilesX = (x1 - x0 + tile - 1) / tile;
        this.tileCount = tilesX * ((y1 - y0 + tile - 1) / tile);
    }

    /**
     * Renders every pixel into the image writer.
     *
     * @throws CancellationException when the calling thread is interrupted (its interrupt flag is
     *                               kept set); the workers stop within a ray of a beam or a soft
     *                               shadow (the library's tracer asks between them), or within a
     *                               tile for a tracer of another kind
     * @throws RuntimeException      the first exception a worker fails with (the tracer's); the
     *                               other workers stop within a tile
     */
    RenderStats run() {
        return run(true);
    }

    /**
     * As {@link #run()}; {@code prepare} false skips the tracer's preparation, for a caller that
     * prepared it once for several loops (see {@link RegionRenderer}, whose scene is its own).
     * A render that prepares notes the scene first ({@link SceneStamp}) and compares at the end:
     *
     * @throws java.util.ConcurrentModificationException when the scene changed during the render
     *                                                   (also when that made it fail otherwise)
     */
    RenderStats run(boolean prepare) {
        if (!prepare) return render(false);
        SceneStamp before = SceneStamp.of(camera.rayTracer().scene, image.getImageName());
        RenderStats stats;
        try {
            stats = render(true);
        } catch (CancellationException e) {
            throw e;
        } catch (RuntimeException | Error e) { // a list read while another thread adds to it, say
            before.requireUnchanged(image.getImageName(), e);
            throw e;
        }
        before.requireUnchanged(image.getImageName(), null);
        return stats;
    }

    private RenderStats render(boolean prepare) {
        camera.requireRayBudget(); // the tracer's settings may have grown since the camera was built
        long t0 = System.nanoTime();
        if (prepare) camera.rayTracer().prepare();
        double prepareSeconds = (System.nanoTime() - t0) / 1e9;
        long pixels = (long) (x1 - x0) * (y1 - y0);
        // The clock of the render starts here, after the preparation (timed on its own).
        Progress progress = new Progress("render " + name, pixels, camera.debugPrint(),
                camera.output());
        int threads = camera.threads();
        if (threads == 0) {
            worker(progress).run();
        } else {
            ExecutorService pool = Executors.newFixedThreadPool(threads, r -> {
                Thread t = new Thread(r, "render-" + name);
                t.setDaemon(true);
                return t;
            });
            try {
                List<Future<?>> futures = new ArrayList<>(threads);
                for (int i = 0; i < threads; ++i) futures.add(pool.submit(worker(progress)));
                for (Future<?> f : futures) f.get();
            } catch (InterruptedException e) {
                cancelled.set(true);
                Thread.currentThread().interrupt();
                throw interrupted();
            } catch (ExecutionException e) {
                cancelled.set(true);
                // Not necessarily this future's exception: a worker stopped by another's failure
                // ends with a CancellationException, and the failure is what the caller needs.
                Throwable cause = failure.get() != null ? failure.get() : e.getCause();
                if (cause instanceof RuntimeException re) throw re;
                if (cause instanceof Error err) throw err;
                throw new IllegalStateException("render worker failed: " + cause, cause);
            } finally {
                pool.shutdownNow();
                awaitQuietly(pool);
            }
        }
        return counter.stats(progress.elapsedSeconds(), pixels, threads, prepareSeconds);
    }

    /** Waits for the workers to stop so that none writes pixels after the call returns. */
    private static void awaitQuietly(ExecutorService pool) {
        boolean interrupted = false;
        while (true) {
            try {
                if (pool.awaitTermination(1, TimeUnit.MINUTES)) break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
    }

    /**
     * Samples every pixel of tile {@code t} into {@code tilePixels} (row after row), then writes
     * them into the image. A method of its own so that the JIT compiles it as
     * an ordinary call, the same code for every render, instead of replacing the worker's long
     * loop on the stack (OSR) again in each render's new worker.
     *
     * @return the number of pixels rendered
     */
    private long renderTile(int t, PixelSampler sampler, TraceContext ctx, int[] tilePixels) {
        int tx0 = x0 + (t % tilesX) * tile, ty0 = y0 + (t / tilesX) * tile;
        int tx1 = Math.min(x1, tx0 + tile), ty1 = Math.min(y1, ty0 + tile);
        sampler.beginTile(tx0, ty0, tx1, ty1);
        int done = 0;
        for (int y = ty0; y < ty1; ++y)
            for (int x = tx0; x < tx1; ++x) {
                tilePixels[done++] = sampler.sample(x, y, ctx).packed();
            }
        // Into the image once the tile is done, not pixel by pixel: the workers' stores on the
        // cache lines that neighbouring tiles share made 2-thread renders a few per cent slower,
        // and in some processes 10 % (ImageWriter.writeTile, BENCHMARKS.md).
        image.writeTile(tx0, ty0, tx1 - tx0, ty1 - ty0, tilePixels);
        return done;
    }

    private CancellationException interrupted() {
        return new CancellationException("render of " + name + " was interrupted");
    }

    private Runnable worker(Progress progress) {
        return () -> {
            PixelSampler sampler = camera.newSampler();
            // One tile's pixels, written into the image when the tile is done.
            int[] tilePixels = new int[tile * tile];
            TraceContext ctx = new TraceContext(RayTracerBasic.MAX_CALC_COLOR_LEVEL, RayTracerBasic.MIN_CALC_COLOR_K);
            ctx.interruptible = true;
            try {
                for (int t = nextTile.getAndIncrement(); t < tileCount; t = nextTile.getAndIncrement()) {
                    if (cancelled.get() || Thread.currentThread().isInterrupted()) throw interrupted();
                    progress.advance(renderTile(t, sampler, ctx, tilePixels));
                }
            } catch (CancellationException e) {
                // From the tile loop, or from the tracer within a pixel: the others stop too.
                cancelled.set(true);
                throw interrupted();
            } catch (RuntimeException | Error e) {
                // Stop the other workers at their next tile instead of finishing the image.
                failure.compareAndSet(null, e);
                cancelled.set(true);
                throw e;
            } finally {
                ctx.addTo(counter);
            }
        };
    }
}
