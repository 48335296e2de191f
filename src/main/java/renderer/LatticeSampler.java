package renderer;

import java.util.Arrays;
import java.util.function.Supplier;

import primitives.Rgb;

/**
 * {@link AntiAliasing#CORNERS} and {@link AntiAliasing#ADAPTIVE}: samples on a fixed lattice of
 * {@code R} points per pixel side, cached per tile so that a point shared by neighbouring pixels
 * or sub-pixels is traced once. A lattice point's colour depends only on its global coordinates
 * (its random stream is keyed by them), so a point on a tile border gets the same value from
 * either tile, and the image does not depend on the thread count: the pixel corners there are
 * traced once for the whole pass ({@link LatticeSeams}), the finer points there once by each
 * tile.
 *
 * <p>Pixel (x, y) spans lattice coordinates [x·R, (x+1)·R].
 * <ul>
 * <li>CORNERS: R = 2, the pixel's centre and its four corners, averaged. With a lens, each
 * point takes an independent lens point from its own stream. Stratifying them was tried and is
 * not kept: a shared corner can only take a stratum fixed by its place in the lattice (the corner
 * at (i, j) in lens quadrant (i mod 2, j mod 2) covers every pixel's four quadrants), which ties
 * the lens stratum to the corner's place in the pixel and biases the pixel more than it lowers
 * its noise: on the showcase with a lens, 32.85 dB against 33.27 (BENCHMARKS.md, depth of
 * field).</li>
 * <li>ADAPTIVE without a lens (with one, {@link NoiseAdaptiveSampler}): R = 2^depth. A square
 * (first the pixel) is traced at its four corners only; when
 * the corners disagree and the depth allows, it is cut into its four quadrants, each treated the
 * same way (which traces the centre and the four edge midpoints, the latter shared with the
 * neighbouring squares); otherwise the square counts as the mean of its corners. A smooth region
 * thus costs one camera ray per pixel (each corner is shared by four pixels); the rays go to the
 * edges. The corners disagree when they spread over more than threshold / w in some channel, w
 * being the square's share of the pixel (1, 1/4, 1/16, ...): leaving the square whole then costs
 * its pixel at most about the threshold, so small squares split only at strong edges.
 * <p>Each ADAPTIVE lattice point is traced at a random offset within its cell (±1/2 of the
 * lattice spacing, drawn from the point's own stream). Scenes are often built on round
 * coordinates that the regular lattice hits exactly: polygon seams, which a ray exactly on a
 * shared edge misses, or a horizontal edge on a pixel row, which would then be wrong across the
 * whole row. Jitter turns that aliasing into fine noise (measured on the showcase at 600×600:
 * +1.3 dB).</li>
 * </ul>
 */
final class LatticeSampler extends PixelSampler {
    private final boolean adaptive;
    private final int maxDepth;
    private final double threshold;
    private final int perPixel; // R
    // Cache over the current tile's lattice points: colour channels and a stamp saying "valid".
    private final int side;
    private final double[] cr, cg, cb;
    private final int[] stamp;
    private int generation;
    private int originX, originY; // global lattice coordinates of the tile's top-left point
    private final double[] sum = new double[3]; // the adaptive accumulator, reused per pixel
    private final Rgb pixel = new Rgb();
    /** The pass's pixel corners on its tiles' borders, traced once for all its workers; null: none. */
    private final LatticeSeams seams;

    /**
     * ADAPTIVE's threshold is the spread of a pixel's corners (0..255 scale, per channel, values
     * clamped to 255 as the image stores them) above which it is subdivided; a square of share w
     * of the pixel splits above threshold / w.
     *
     * @param tileSize the render loop's tile side in pixels: the cache covers one tile's lattice
     */
    private LatticeSampler(Plan plan, Estimator estimator, int tileSize, LatticeSeams seams) {
        super(plan.seed, plan.lens, estimator);
        this.seams = seams;
        this.adaptive = plan.adaptive;
        this.maxDepth = plan.depth;
        this.threshold = plan.threshold;
        this.perPixel = plan.pointsPerPixel();
        this.side = tileSize * perPixel + 1;
        cr = new double[side * side];
        cg = new double[side * side];
        cb = new double[side * side];
        stamp = new int[side * side];
    }

    /**
     * CORNERS ({@link #corners}) or ADAPTIVE without a lens ({@link #adaptive}).
     *
     * @param seed      the render's seed
     * @param lens      whether the view has a lens (CORNERS only: each point takes a lens point)
     * @param adaptive  ADAPTIVE's subdivision, or CORNERS' five fixed points
     * @param depth     ADAPTIVE's deepest subdivision, 1..6; 0 for CORNERS
     * @param threshold ADAPTIVE's corner spread that subdivides; unused by CORNERS
     */
    record Plan(long seed, boolean lens, boolean adaptive, int depth, double threshold) implements SamplerPlan {
        static Plan corners(long seed, boolean lens) {
            return new Plan(seed, lens, false, 0, 0);
        }

        static Plan adaptive(long seed, int depth, double threshold) {
            return new Plan(seed, false, true, depth, threshold);
        }

        /** ADAPTIVE's words, with or without a lens. */
        static String adaptiveWords(int depth, double threshold) {
            return "ADAPTIVE depth " + depth + " threshold " + threshold;
        }

        /** R: lattice points per pixel side. */
        int pointsPerPixel() {
            return adaptive ? 1 << depth : 2;
        }

        @Override
        public AntiAliasing mode() {
            return adaptive ? AntiAliasing.ADAPTIVE : AntiAliasing.CORNERS;
        }

        /**
         * The most camera rays a pixel takes: CORNERS' five points (the centre and the corners), or
         * ADAPTIVE's whole lattice of (R + 1)² points, every square split down to the deepest
         * level. With a lens (CORNERS only), each point traces one ray.
         */
        @Override
        public long maxSamplesPerPixel() {
            if (!adaptive) return 5;
            long side = (1L << depth) + 1;
            return side * side;
        }

        /**
         * @return one for ADAPTIVE (a smooth region traces its lattice's corners only, each shared
         *         by four pixels), two for CORNERS (the centre, and one corner's share)
         */
        @Override
        public long leastSamplesPerPixel() {
            return adaptive ? 1 : 2;
        }

        /**
         * The tile side, in pixels: 64, fewer for lattices above 4 points per pixel side so that the
         * per-tile cache stays at most 257² points (2.1 MB). Large tiles matter less since the pixel
         * corners on a tile's border are traced once for the pass ({@link LatticeSeams}): the finer
         * points there are still traced by both tiles.
         */
        @Override
        public int tileSize() {
            return Math.max(1, Math.min(64, 256 / pointsPerPixel()));
        }

        /** The workers' samplers share the pass's {@link LatticeSeams}. */
        @Override
        public Supplier<PixelSampler> samplers(Estimator estimator, int tileSize, int x0, int y0, int x1, int y1) {
            LatticeSeams seams = LatticeSeams.of(x0, y0, x1, y1, tileSize);
            return () -> new LatticeSampler(this, estimator, tileSize, seams);
        }

        @Override
        public String describe() {
            return adaptive ? adaptiveWords(depth, threshold) : "CORNERS";
        }
    }

    @Override
    void beginTile(int x0, int y0, int x1, int y1) {
        if (++generation == 0) { // wrapped after 4 billion tiles: start the stamps afresh
            Arrays.fill(stamp, 0);
            generation = 1;
        }
        originX = x0 * perPixel;
        originY = y0 * perPixel;
    }

    /** The colour at global lattice point (gx, gy), traced on first use within the tile. */
    private int point(int gx, int gy, TraceContext ctx) {
        int i = (gy - originY) * side + (gx - originX);
        if (stamp[i] != generation) {
            // a pixel corner on a border between tiles: traced once for the pass (R is a power of two)
            int s = seams != null && ((gx | gy) & (perPixel - 1)) == 0 ? seams.index(gx / perPixel, gy / perPixel) : -1;
            if (s < 0) {
                traceInto(i, gx, gy, ctx);
            } else if (seams.claim(s)) {
                try {
                    traceInto(i, gx, gy, ctx);
                } catch (RuntimeException | Error e) {
                    seams.release(s); // another worker traces it, unless the render stops
                    throw e;
                }
                seams.publish(s, cr[i], cg[i], cb[i]);
            } else {
                cr[i] = seams.red(s);
                cg[i] = seams.green(s);
                cb[i] = seams.blue(s);
            }
            stamp[i] = generation;
        }
        return i;
    }

    /** Traces global lattice point (gx, gy) into cache slot {@code i}. */
    private void traceInto(int i, int gx, int gy, TraceContext ctx) {
        SampleStream rnd = ctx.random;
        rnd.reset(seed, gx, gy, -perPixel);
        Rgb c;
        if (adaptive) { // jittered within its cell of the lattice: see the class comment
            double jx = rnd.nextDouble() - 0.5, jy = rnd.nextDouble() - 0.5;
            c = trace((gx + jx) / perPixel, (gy + jy) / perPixel, ctx);
        } else {
            c = trace((double) gx / perPixel, (double) gy / perPixel, ctx);
        }
        cr[i] = c.r();
        cg[i] = c.g();
        cb[i] = c.b();
    }

    @Override
    Rgb sample(int x, int y, TraceContext ctx) {
        int gx = x * perPixel, gy = y * perPixel;
        if (!adaptive) {
            int m = point(gx + 1, gy + 1, ctx);
            int a = point(gx, gy, ctx), b = point(gx + 2, gy, ctx), c = point(gx, gy + 2, ctx), d = point(gx + 2, gy + 2, ctx);
            return pixel.set((cr[m] + cr[a] + cr[b] + cr[c] + cr[d]) / 5,
                    (cg[m] + cg[a] + cg[b] + cg[c] + cg[d]) / 5,
                    (cb[m] + cb[a] + cb[b] + cb[c] + cb[d]) / 5);
        }
        sum[0] = sum[1] = sum[2] = 0;
        square(gx, gy, perPixel, 0, 1.0, ctx);
        return pixel.set(sum[0], sum[1], sum[2]);
    }

    /**
     * Adds {@code weight ×} the colour of the square at (gx, gy) of side s (lattice units) to
     * {@link #sum}: the mean of its corners, or, when they disagree (spread over more than
     * threshold / weight) and the depth allows, the mean of its four quadrants, each computed the
     * same way.
     */
    private void square(int gx, int gy, int s, int level, double weight, TraceContext ctx) {
        int c0 = point(gx, gy, ctx), c1 = point(gx + s, gy, ctx), c2 = point(gx, gy + s, ctx), c3 = point(gx + s, gy + s, ctx);
        if (level < maxDepth && disagree(c0, c1, c2, c3, threshold / weight)) {
            int h = s / 2;
            double w = weight / 4;
            square(gx, gy, h, level + 1, w, ctx);
            square(gx + h, gy, h, level + 1, w, ctx);
            square(gx, gy + h, h, level + 1, w, ctx);
            square(gx + h, gy + h, h, level + 1, w, ctx);
        } else {
            double w = weight / 4;
            sum[0] += (cr[c0] + cr[c1] + cr[c2] + cr[c3]) * w;
            sum[1] += (cg[c0] + cg[c1] + cg[c2] + cg[c3]) * w;
            sum[2] += (cb[c0] + cb[c1] + cb[c2] + cb[c3]) * w;
        }
    }

    /**
     * Whether the four cached points spread over more than {@code threshold} in some channel.
     * Values are clamped to 255 first: differences the image cannot show (two over-exposed
     * highlights) are no reason to trace more.
     */
    private boolean disagree(int a, int b, int c, int d, double threshold) {
        return spreads(cr, a, b, c, d, threshold) || spreads(cg, a, b, c, d, threshold) || spreads(cb, a, b, c, d, threshold);
    }

    /**
     * Whether {@code ch}'s values at a, b, c and d, each clamped to 255, spread over more than
     * {@code threshold}: never when one of them is NaN. The answer of
     * {@code max(min(va, 255), ...) - min(min(va, 255), ...) > threshold} with {@link Math#min}
     * and {@link Math#max}, for every input (the tests check it on NaN, infinities and signed
     * zeros), written with one comparison per step: the quick compiler (C1) inlines those two
     * methods as their NaN and -0.0 rules are written, three or four comparisons each, and an
     * ADAPTIVE render made ten of them per channel of every square it looked at. Clamping the
     * largest and the smallest value gives the clamped values' largest and smallest, as clamping
     * keeps the order; the sign of a zero cannot change a comparison's outcome.
     */
    static boolean spreads(double[] ch, int a, int b, int c, int d, double threshold) {
        double va = ch[a], vb = ch[b], vc = ch[c], vd = ch[d];
        double hi = va, lo = va; // a NaN is never taken below: only va can make them NaN, and then no spread
        if (vb > hi) hi = vb;
        else if (vb < lo) lo = vb;
        if (vc > hi) hi = vc;
        else if (vc < lo) lo = vc;
        if (vd > hi) hi = vd;
        else if (vd < lo) lo = vd;
        if (hi > 255) hi = 255;
        if (lo > 255) lo = 255;
        if (!(hi - lo > threshold)) return false;
        // Math.min and max give NaN for a NaN corner, and then no spread: asked only here, as C1
        // builds x != x as a three-way result tested after, four branches each
        return va == va && vb == vb && vc == vc && vd == vd;
    }
}
