package renderer;

/**
 * A sampling strategy: the colour of one pixel from as many camera samples as it chooses. For
 * each sample it chooses a film point (in pixels from the image's top-left corner) and, with a
 * lens, a lens point drawn from the sample's stream; the view makes the ray and the tracer
 * colours it. One instance per worker thread (it may keep scratch state); the render loop calls
 * {@link #beginTile} before the pixels of each tile.
 */
abstract class PixelSampler {
    /** The render's seed: every sample's stream is keyed by it, the pixel and the sample index. */
    final long seed;
    private final View.CameraRays rays;
    private final RayTracerBase tracer;
    /** Whether each camera sample draws a lens point (the view has an aperture). */
    private final boolean lens;

    PixelSampler(Sampling sampling, View.CameraRays rays, RayTracerBase tracer) {
        this.seed = sampling.seed();
        this.rays = rays;
        this.tracer = tracer;
        this.lens = rays.hasLens();
    }

    /** Announces the tile of columns [x0, x1) and rows [y0, y1) about to be sampled. */
    void beginTile(int x0, int y0, int x1, int y1) {
    }

    /** Samples pixel (column x, row y) and leaves its colour in {@code ctx.r, ctx.g, ctx.b}. */
    abstract void sample(int x, int y, TraceContext ctx);

    /**
     * Traces one camera sample through film point (px, py) (pixel (x, y)'s centre is
     * (x + 0.5, y + 0.5)) and leaves the colour seen in {@code ctx.r, ctx.g, ctx.b}. With a lens,
     * its point is the next two numbers of {@code ctx.random}, which the caller has positioned
     * for this sample; the tracer's own numbers follow them.
     */
    final void trace(double px, double py, TraceContext ctx) {
        ctx.cameraRays++;
        double u = 0, v = 0;
        if (lens) {
            u = ctx.random.nextDouble();
            v = ctx.random.nextDouble();
        }
        rays.generate(px, py, u, v, ctx);
        tracer.traceRay(ctx);
    }
}
