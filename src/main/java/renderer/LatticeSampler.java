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
        // Keep the cache around 64K points whatever the depth.
        this.tile = Math.max(1, Math.min(16, 256 / perPixel));
        this.side = tile * perPixel + 1;
        cr = new double[side * side];
        cg = new double[side * side];
        cb = new double[side * side];
        stamp = new int[side * side];
    }

    @Override
    public int tileSize() {
        return tile;
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
     * Adds {@code weight ×} the colour of the square at (gx, gy) of side s to {@code sum}: each
     * quadrant is the mean of its corner and the centre, unless they differ by more than the
     * threshold and the depth allows a split, in which case the quadrant is sampled the same way.
     */
    private void square(int gx, int gy, int s, int level, double weight, double[] sum, TraceContext ctx) {
        int h = s / 2;
        int m = point(gx + h, gy + h, ctx);
        for (int q = 0; q < 4; ++q) {
            int qx = gx + (q & 1) * h, qy = gy + (q >> 1) * h; // the quadrant's top-left
            int corner = point(gx + (q & 1) * s, gy + (q >> 1) * s, ctx);
            double diff = Math.max(Math.abs(cr[corner] - cr[m]), Math.max(Math.abs(cg[corner] - cg[m]), Math.abs(cb[corner] - cb[m])));
            if (level < maxDepth && diff > threshold) {
                square(qx, qy, h, level + 1, weight / 4, sum, ctx);
            } else {
                double w = weight / 8;
                sum[0] += (cr[corner] + cr[m]) * w;
                sum[1] += (cg[corner] + cg[m]) * w;
                sum[2] += (cb[corner] + cb[m]) * w;
            }
        }
    }
}
