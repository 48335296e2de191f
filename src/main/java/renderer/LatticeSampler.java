package renderer;

import java.util.Arrays;

import primitives.Color;

/**
 * {@link AntiAliasing#CORNERS} and {@link AntiAliasing#ADAPTIVE}: samples on a fixed lattice of
 * {@code 2^(depth+1)} points per pixel side, cached per tile so that a corner shared by
 * neighbouring pixels or sub-pixels is traced once. A lattice point's colour depends only on its
 * global coordinates (its random stream is keyed by them), so a point on a tile border, traced
 * again by the next tile, gets the same value.
 *
 * <p>Pixel (x, y) spans lattice coordinates [x·R, (x+1)·R] with R = 2^(depth+1); a square of side
 * s (in lattice units) has its centre at +s/2. CORNERS is depth 0 (R = 2: corners and centre).
 */
final class LatticeSampler implements PixelSampler {
    private final Camera camera;
    private final boolean adaptive;
    private final int maxDepth;
    private final double threshold;
    private final int perPixel; // R
    private final int tile;
    // Cache over the current tile's lattice points: colour channels and a stamp saying "valid".
    private final int side;
    private final double[] cr, cg, cb;
    private final int[] stamp;
    private int generation;
    private int originX, originY; // global lattice coordinates of the tile's top-left point
    private final double[] sum = new double[3]; // the adaptive accumulator, reused per pixel

    /**
     * @param maxDepth  0 for CORNERS; the adaptive subdivision depth otherwise
     * @param threshold the colour distance (0..255 scale, largest channel difference) above which a
     *                  quadrant is subdivided
     */
    LatticeSampler(Camera camera, boolean adaptive, int maxDepth, double threshold) {
        this.camera = camera;
        this.adaptive = adaptive;
        this.maxDepth = adaptive ? maxDepth : 0;
        this.threshold = threshold;
        this.perPixel = 1 << (this.maxDepth + 1);
        this.tile = tileSize(this.maxDepth);
        this.side = tile * perPixel + 1;
        cr = new double[side * side];
        cg = new double[side * side];
        cb = new double[side * side];
        stamp = new int[side * side];
    }

    /**
     * The tile side, in pixels, for a lattice of 2^(depth+1) points per pixel side: 16 pixels,
     * fewer at depths above 3 so that the per-tile cache stays at most 257² points (1.8 MB).
     */
    static int tileSize(int depth) {
        return Math.max(1, Math.min(16, 256 >> (depth + 1)));
    }

    @Override
    public void beginTile(int x0, int y0, int x1, int y1) {
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
            ctx.random.reset(camera.seed(), gx, gy, -perPixel);
            Color c = camera.trace((double) gx / perPixel, (double) gy / perPixel, ctx);
            cr[i] = c.getR();
            cg[i] = c.getG();
            cb[i] = c.getB();
            stamp[i] = generation;
        }
        return i;
    }

    @Override
    public Color sample(int x, int y, TraceContext ctx) {
        int gx = x * perPixel, gy = y * perPixel;
        if (!adaptive) {
            int m = point(gx + 1, gy + 1, ctx);
            int a = point(gx, gy, ctx), b = point(gx + 2, gy, ctx), c = point(gx, gy + 2, ctx), d = point(gx + 2, gy + 2, ctx);
            return new Color((cr[m] + cr[a] + cr[b] + cr[c] + cr[d]) / 5, (cg[m] + cg[a] + cg[b] + cg[c] + cg[d]) / 5,
                    (cb[m] + cb[a] + cb[b] + cb[c] + cb[d]) / 5);
        }
        sum[0] = sum[1] = sum[2] = 0;
        square(gx, gy, perPixel, 0, 1.0, sum, ctx);
        return new Color(sum[0], sum[1], sum[2]);
    }

    /**
     * Adds {@code weight ×} the colour of the square at (gx, gy) of side s to {@code sum}. When a
     * corner differs from the centre by more than the threshold and the depth allows, all four
     * quadrants are sampled the same way; otherwise each quadrant counts as the mean of its
     * corner and the centre.
     *
     * <p>Why all four: an edge crossing the square always separates some corner from the centre,
     * but it may cross a quadrant without separating that quadrant's corner from the centre (it
     * cuts off the quadrant's corner on a side of the square, which the square does not sample).
     * Splitting only the quadrants whose corner differs misses such an edge entirely, with an
     * error up to half the contrast.
     */
    private void square(int gx, int gy, int s, int level, double weight, double[] sum, TraceContext ctx) {
        int h = s / 2;
        int m = point(gx + h, gy + h, ctx);
        int c0 = point(gx, gy, ctx), c1 = point(gx + s, gy, ctx), c2 = point(gx, gy + s, ctx), c3 = point(gx + s, gy + s, ctx);
        if (level < maxDepth && (differs(c0, m) || differs(c1, m) || differs(c2, m) || differs(c3, m))) {
            double w = weight / 4;
            square(gx, gy, h, level + 1, w, sum, ctx);
            square(gx + h, gy, h, level + 1, w, sum, ctx);
            square(gx, gy + h, h, level + 1, w, sum, ctx);
            square(gx + h, gy + h, h, level + 1, w, sum, ctx);
        } else {
            double w = weight / 8;
            sum[0] += (cr[c0] + cr[c1] + cr[c2] + cr[c3] + 4 * cr[m]) * w;
            sum[1] += (cg[c0] + cg[c1] + cg[c2] + cg[c3] + 4 * cg[m]) * w;
            sum[2] += (cb[c0] + cb[c1] + cb[c2] + cb[c3] + 4 * cb[m]) * w;
        }
    }

    /** Whether cached points i and j differ by more than the threshold in some channel. */
    private boolean differs(int i, int j) {
        return Math.abs(cr[i] - cr[j]) > threshold || Math.abs(cg[i] - cg[j]) > threshold
                || Math.abs(cb[i] - cb[j]) > threshold;
    }
}
