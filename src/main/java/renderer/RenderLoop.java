package renderer;

import java.lang.ref.WeakReference;
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
import java.util.function.Supplier;

/**
 * The one render loop. The image is cut into square tiles; workers claim tiles from an atomic
 * counter (no lock per pixel) and sample every pixel of a tile with their own
 * {@link PixelSampler} (from the sampling's {@link SamplerPlan}) and {@link TraceContext} (from the tracer).
 * Which worker renders a tile does not change its pixels: every random number comes from streams
 * keyed by the pixel, so images are identical for any thread count. It reads its settings from
 * the values it is given, never from a camera; one loop serves any number of passes, and passes
 * may run at once (each has its own counters).
 */
final class RenderLoop {
    /**
     * A render with at least this many seconds left at its pace is long
     * ({@link PreparedTracer#expectLongRender}): the vector walk's warm-up costs 1.1–1.4 s of
     * processor time (its thread and the compiler's, measured), which the vector walk, about 12 %
     * faster in a whole render, pays back only after some 5 s of a 2-thread render (an estimate
     * from those two figures; BENCHMARKS.md, "The vector walk without asking"). On a host twice as
     * slow, the switch held a 2-thread render back by about 2 s, and the vector walk ran 25 %
     * faster after it: again about 8 s to break even (BENCHMARKS.md, issue 50, the closing session).
     */
    static final double LONG_RENDER_SECONDS = 8;
    /**
     * Seconds of render before its pace is measured, and then the shortest span it is measured
     * over ({@link Progress#remainingSecondsAfter}): the first tiles run while the code is still
     * compiled, so the pace from the start promises more time than the render takes.
     */
    static final double PACE_SECONDS = 1;

    private final SamplerPlan sampling;
    private final Execution execution;
    private final RayTracerBase tracer;
    /** Where whole-image passes write; null for a loop that renders regions only. */
    private final ImageWriter image;
    private final View.CameraRays rays;

    /**
     * @param image the image a whole-image pass writes, of the view's resolution; null when only
     *              regions are rendered
     */
    RenderLoop(View view, Sampling sampling, Execution execution, RayTracerBase tracer, ImageWriter image) {
        this.execution = execution;
        this.tracer = tracer;
        this.image = image;
        this.rays = view.cameraRays();
        this.sampling = sampling.plan(rays.hasLens());
    }

    /**
     * Renders every pixel into the image writer. The scene is stamped first ({@link SceneStamp}),
     * the tracer prepared for it, and the stamp compared at the end.
     *
     * @param name the image's name in progress lines and worker threads' names
     * @throws CancellationException when the calling thread is interrupted (its interrupt flag is
     *                               kept set); the workers stop within a ray of a beam or a soft
     *                               shadow (the library's tracer asks between them), or within a
     *                               tile for a tracer of another kind
     * @throws RuntimeException      the first exception a worker fails with (the tracer's); the
     *                               other workers stop within a tile
     * @throws java.util.ConcurrentModificationException when the scene changed during the render
     *                                                   (also when that made it fail otherwise)
     */
    RenderStats render(String name) {
        SceneStamp before = SceneStamp.of(tracer, image.getImageName());
        RenderStats stats;
        try {
            tracer.requireRayBudget(sampling); // the tracer's settings may have grown since the camera was built
            long t0 = System.nanoTime();
            PreparedTracer prepared = tracer.prepareFor(before);
            double prepareSeconds = (System.nanoTime() - t0) / 1e9;
            stats = new Pass(name, prepared, new Rect(0, 0, image.getNx(), image.getNy()), null).run(prepareSeconds);
        } catch (CancellationException e) {
            throw e;
        } catch (RuntimeException | Error e) { // a list read while another thread adds to it, say
            before.requireUnchanged(image.getImageName(), e);
            throw e;
        }
        before.requireUnchanged(image.getImageName(), null);
        return stats;
    }

    /**
     * Renders the rectangle of columns [x0, x1) and rows [y0, y1) only (the caller checked that
     * it lies in the image, and prepared the tracer: {@code prepared}). Its tiles start at (x0, y0); a pixel's
     * value does not depend on the tiling (see {@link LatticeSampler}), so a rectangle renders
     * exactly as it does within the whole image.
     *
     * @param name the label of progress lines and worker threads
     * @return the rectangle's pixels, packed 0xRRGGBB row by row, and what the render did
     */
    RegionRenderer.Pixels region(String name, PreparedTracer prepared, int x0, int y0, int x1, int y1) {
        tracer.requireRayBudget(sampling);
        int[] rgb = new int[(x1 - x0) * (y1 - y0)];
        RenderStats stats = new Pass(name, prepared, new Rect(x0, y0, x1, y1), rgb).run(0);
        return new RegionRenderer.Pixels(rgb, stats);
    }

    /**
     * @return the first number from ⌈0.618 · count⌉ up that is coprime with {@code count} (1 for a
     *         count of 1 or 2), so that k ↦ k · stride mod count visits every tile once
     */
    static int spreadingStride(int count) {
        int stride = Math.max(1, (int) Math.ceil(0.6180339887498949 * count));
        while (gcd(stride, count) != 1) ++stride;
        return stride;
    }

    private static int gcd(int a, int b) {
        while (b != 0) {
            int r = a % b;
            a = b;
            b = r;
        }
        return a;
    }

    /** Columns [x0, x1) and rows [y0, y1). */
    private record Rect(int x0, int y0, int x1, int y1) {
        int width() {
            return x1 - x0;
        }

        long pixels() {
            return (long) (x1 - x0) * (y1 - y0);
        }
    }

    /** One pass over a rectangle: its tiles, the workers' shared counters, and where its pixels go. */
    private final class Pass {
        private final String name;
        /** The colour of a camera sample: the view's camera ray, traced by the tracer as this render prepared it. */
        private final Estimator estimator;
        private final PreparedTracer prepared;
        private final Rect rect;
        /** The rectangle's pixels, row by row; null: the tiles go into the image. */
        private final int[] out;
        private final int tile = execution.tileSize();
        private final int tilesX;
        private final int tileCount;
        private final AtomicInteger nextTile = new AtomicInteger();
        /**
         * The order tiles are claimed in: the k-th claim renders tile (k · stride) mod tileCount, a
         * stride coprime with the count near 0.618 of it, so that the claims spread over the whole
         * image from the start. In row order the first seconds of an outdoor scene are its sky: the
         * pace then promised 4 s left of a 21 s render (BENCHMARKS.md, issue 50, night session), for
         * the ETA of the progress lines and for the long-render check alike. Which tile a claim
         * gets never changes its pixels.
         */
        private final int stride;
        private final AtomicBoolean cancelled = new AtomicBoolean();
        /** The first exception a worker failed with; the others then stop and it is rethrown. */
        private final AtomicReference<Throwable> failure = new AtomicReference<>();
        private final RenderStats.Counter counter = new RenderStats.Counter();
        /** Each worker's sampler (and a worker's new one after a collection): what they share is the pass's. */
        private final Supplier<PixelSampler> samplers;

        Pass(String name, PreparedTracer prepared, Rect rect, int[] out) {
            this.name = name;
            this.estimator = (px, py, u, v, ctx) -> {
                rays.generate(px, py, u, v, ctx);
                return prepared.traceRay(ctx);
            };
            this.prepared = prepared;
            this.rect = rect;
            this.out = out;
            this.tilesX = (rect.x1 - rect.x0 + tile - 1) / tile;
            this.tileCount = tilesX * ((rect.y1 - rect.y0 + tile - 1) / tile);
            this.stride = spreadingStride(tileCount);
            this.samplers = sampling.samplers(estimator, tile, rect.x0, rect.y0, rect.x1, rect.y1);
        }

        RenderStats run(double prepareSeconds) {
            long pixels = rect.pixels();
            // The clock of the render starts here, after the preparation (timed on its own).
            Progress progress = new Progress("render " + name, pixels, execution.progressStep(), execution.output());
            int threads = execution.threads();
            prepared.expectCameraRays(pixels * sampling.leastSamplesPerPixel());
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

        /**
         * Samples every pixel of the tile the {@code claim}-th claim gets ({@link #stride}) into
         * {@code tilePixels} (row after row), then writes them out. A method of its own so that
         * the JIT compiles it as an ordinary call, the same code for every render, instead of
         * replacing the worker's long loop on the stack (OSR) again in each render's new worker.
         *
         * @return the number of pixels rendered
         */
        private long renderTile(int claim, PixelSampler sampler, TraceContext ctx, int[] tilePixels) {
            int t = (int) ((long) claim * stride % tileCount);
            int tx0 = rect.x0 + (t % tilesX) * tile, ty0 = rect.y0 + (t / tilesX) * tile;
            int tx1 = Math.min(rect.x1, tx0 + tile), ty1 = Math.min(rect.y1, ty0 + tile);
            sampler.beginTile(tx0, ty0, tx1, ty1);
            int done = 0;
            for (int y = ty0; y < ty1; ++y)
                for (int x = tx0; x < tx1; ++x) {
                    ctx.beginPixel(x, y);
                    tilePixels[done++] = sampler.sample(x, y, ctx).packed();
                }
            // Out once the tile is done, not pixel by pixel: the workers' stores on the cache
            // lines that neighbouring tiles share made 2-thread renders a few per cent slower,
            // and in some processes 10 % (ImageWriter.writeTile, BENCHMARKS.md).
            int w = tx1 - tx0, h = ty1 - ty0;
            if (out == null) image.writeTile(tx0, ty0, w, h, tilePixels);
            else for (int row = 0; row < h; ++row)
                System.arraycopy(tilePixels, row * w, out, (ty0 - rect.y0 + row) * rect.width() + (tx0 - rect.x0), w);
            return done;
        }

        /** A worker's trace context: its own scratch records, stopped by an interrupt. */
        private TraceContext newContext() {
            TraceContext ctx = tracer.newContext();
            ctx.interruptible = true;
            return ctx;
        }

        private CancellationException interrupted() {
            return new CancellationException("render of " + name + " was interrupted");
        }

        private Runnable worker(Progress progress) {
            return () -> {
                PixelSampler sampler = samplers.get();
                // One tile's pixels, written out when the tile is done.
                int[] tilePixels = new int[tile * tile];
                TraceContext ctx = newContext();
                // Cleared by the next garbage collection: see below.
                WeakReference<Object> noCollectionSince = new WeakReference<>(new Object());
                try {
                    for (int t = nextTile.getAndIncrement(); t < tileCount; t = nextTile.getAndIncrement()) {
                        if (cancelled.get() || Thread.currentThread().isInterrupted()) throw interrupted();
                        // A collection copies the workers' records (the context, its hits, their
                        // walk stacks and lanes) into shared regions, in whatever order it walks
                        // them: a record of this worker can land on a cache line with one of
                        // another's, and each write of one then takes the line from the other's
                        // core. Where that happened, a whole render on the vector walk took 1.2-1.7x
                        // its time (about one in four, at random; never once the collections stopped:
                        // BENCHMARKS.md, issue 50, fourth session of 2026-11-29). So after each
                        // collection the worker makes its records anew, in its own allocation
                        // buffer, where no other thread allocates. Also with one worker, or on the
                        // calling thread: other renders may run beside this one (a Spark
                        // executor's tasks, each on the thread that calls it; tests run in
                        // parallel). Nothing else changes: every random number is keyed by the
                        // pixel, and the shadow cache is exact.
                        if (noCollectionSince.get() == null) {
                            ctx.addTo(counter);
                            ctx = newContext();
                            sampler = samplers.get();
                            tilePixels = new int[tile * tile];
                            noCollectionSince = new WeakReference<>(new Object());
                        }
                        progress.advance(renderTile(t, sampler, ctx, tilePixels));
                        // Only at the pace after the first tiles, which include the code's warm-up
                        // (NaN until it is known: not long).
                        if (progress.remainingSecondsAfter(PACE_SECONDS) >= LONG_RENDER_SECONDS)
                            prepared.expectLongRender();
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
}
