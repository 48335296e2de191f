package renderer;

import primitives.Rgb;

/**
 * A sampling strategy: the colour of one pixel from as many camera samples as it chooses. For
 * each sample it chooses a film point (in pixels from the image's top-left corner) and, with a
 * lens, a lens point (drawn from the sample's stream, or stratified over the pixel's samples by
 * {@link SobolPoints}); its {@link Estimator}, from the render loop, colours the sample. One
 * instance per worker thread (it may keep scratch state); the render loop calls
 * {@link #beginTile} before the pixels of each tile.
 */
abstract class PixelSampler {
    /**
     * The stream index that keys a pixel's own numbers (its {@link SobolPoints} seeds), apart from
     * its samples' streams (indices 0, 1, …) and from the lattice points' (index −R, R ≥ 2).
     */
    static final int PIXEL_KEY = -1;
    /** The render's seed: every sample's stream is keyed by it, the pixel and the sample index. */
    final long seed;
    private final Estimator estimator;
    /** Whether each camera sample draws a lens point (the view has an aperture). */
    private final boolean lens;

    /**
     * @param seed      the render's seed
     * @param lens      whether each camera sample draws a lens point (the view has an aperture)
     * @param estimator the colour of a camera sample
     */
    PixelSampler(long seed, boolean lens, Estimator estimator) {
        this.seed = seed;
        this.estimator = estimator;
        this.lens = lens;
    }

    /** Announces the tile of columns [x0, x1) and rows [y0, y1) about to be sampled. */
    void beginTile(int x0, int y0, int x1, int y1) {
    }

    /** Samples pixel (column x, row y): @return its colour, valid until the next call */
    abstract Rgb sample(int x, int y, TraceContext ctx);

    /**
     * Traces one camera sample through film point (px, py) (pixel (x, y)'s centre is
     * (x + 0.5, y + 0.5)) and returns the colour seen (the context's, valid until its next
     * trace). With a lens, its point is the next two numbers of {@code ctx.random}, which the
     * caller has positioned for this sample; the tracer's own numbers follow them.
     */
    final Rgb trace(double px, double py, TraceContext ctx) {
        double u = 0, v = 0;
        if (lens) {
            u = ctx.random.nextDouble();
            v = ctx.random.nextDouble();
        }
        return trace(px, py, u, v, ctx);
    }

    /**
     * Traces one camera sample through film point (px, py) and lens point (u, v) of the unit
     * square (ignored by a pinhole), chosen by the caller (stratified: {@link SobolPoints}). The
     * tracer draws its own numbers from {@code ctx.random} as positioned by the caller.
     */
    final Rgb trace(double px, double py, double u, double v, TraceContext ctx) {
        ctx.cameraRays++;
        return estimator.estimate(px, py, u, v, ctx);
    }

    /** @return whether each camera sample takes a lens point (the view has an aperture) */
    final boolean hasLens() {
        return lens;
    }

    /**
     * The pixel's scramble seeds: two independent 32-bit numbers from the stream of (seed, x, y,
     * {@link #PIXEL_KEY}), as one long (film points: its high half, lens points: its low half).
     */
    final long pixelSeeds(int x, int y, TraceContext ctx) {
        return ctx.random.reset(seed, x, y, PIXEL_KEY).nextLong();
    }
}
