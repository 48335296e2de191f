package geometries;

/**
 * The binned surface-area heuristic of {@link BvhBuilder}: one task's bins, reused for every node
 * the task splits. Per searched axis, {@link #BINS} counts and boxes, filled in one pass over a
 * node's range; the cheapest split is then found by sweeping each axis from both ends.
 * The sweeps' unions are the boxes of the parts a split makes, exactly (a minimum or maximum is
 * the same whatever the order it is taken in): the chosen split's two are kept in
 * {@link #bestBoxes}, so that the partition need not grow them again.
 *
 * <p>A split's cost is {@link #sahCost}, relative to testing the parent's primitives, from the
 * children's {@link BuildBoxes#halfArea(double, double, double) half areas}: the one formula of every search, the direct one of a
 * two-primitive node included, so that both searches choose the same split.
 */
final class BvhBinner {
    /** Bins per axis. */
    static final int BINS = 16;
    /** Cost of visiting a node relative to testing one primitive, for the SAH. */
    private static final double TRAVERSAL_COST = 1.0;

    /** Per axis, whether the node being split is searched along it (set by the builder per node). */
    final boolean[] searched = new boolean[3];
    /** The node being split: per axis, its centroids' lowest value and their extent. */
    final double[] lowOf = new double[3];
    final double[] extentOf = new double[3];
    private final int[] binCount = new int[3 * BINS];
    private final double[] binBox = new double[3 * BINS * BuildBoxes.BOX_SIZE];
    /** Per bin of the axis being searched: the half area of the bins up to it, and from it on. */
    private final double[] leftArea = new double[BINS];
    private final double[] rightArea = new double[BINS];
    /** Per bin of the axis being searched: the union box ({@link BuildBoxes} layout) of the bins up to it, and from it on. */
    private final double[] leftUnion = new double[BINS * BuildBoxes.BOX_SIZE];
    private final double[] rightUnion = new double[BINS * BuildBoxes.BOX_SIZE];
    /**
     * The cheapest split's two boxes, left part then right part: the unions of their primitives'
     * boxes, the very doubles the partition would find growing them primitive by primitive.
     */
    final double[] bestBoxes = new double[2 * BuildBoxes.BOX_SIZE];
    /**
     * Per axis, the bins {@link #bin} filled, as bits; the search clears them again. Only these
     * bins' counts and boxes mean anything: a bin's first run of a node writes them, so a bin
     * left over from an earlier node is never read and never needs emptying.
     */
    private final int[] occupied = new int[3];
    /** The cheapest split a search found: its cost, last left bin (−1 for none) and axis. */
    double bestCost;
    int bestBin;
    int bestAxis;
    /**
     * Per level of this task's recursion, the box and centroid bounds of the two children
     * split there ({@link BuildBoxes#BOUNDS} doubles each, left then right); grown on demand.
     */
    double[] levels = new double[16 * 2 * BuildBoxes.BOUNDS];

    /**
     * The binned SAH over the searched axes of slots [start, end): fills the bins in one pass,
     * sweeps each axis from both ends, and leaves the cheapest split in {@link #bestCost},
     * {@link #bestBin} (the last bin of the left part) and {@link #bestAxis}.
     */
    void searchBinned(double[] bounds, double[] centroid, int start, int end, double[] lowOf, double[] extentOf,
                      double parentArea) {
        bin(bounds, centroid, start, end, lowOf, extentOf);
        int n = end - start;
        bestCost = Double.POSITIVE_INFINITY;
        bestBin = -1;
        bestAxis = -1;
        for (int a = 0; a < 3; ++a) {
            if (!searched[a]) continue;
            int base = a * BINS, mask = occupied[a];
            occupied[a] = 0;
            // Only the occupied bins are swept. An empty bin changes neither part's box nor
            // count: the areas and costs are the numbers a sweep over every bin computes, and an
            // empty bin's split costs exactly what its left neighbour's does, which cannot beat
            // it. (Small nodes, most of a tree, occupy few bins.)
            sweep(base, mask);
            int leftCount = 0;
            for (int m = mask; ; ) {
                int k = Integer.numberOfTrailingZeros(m);
                m &= m - 1;
                if (m == 0) break; // the last occupied bin leaves no right part
                leftCount += binCount[base + k];
                int next = Integer.numberOfTrailingZeros(m);
                if (consider(sahCost(leftArea[k], leftCount, rightArea[next], n - leftCount, parentArea), k, a)) {
                    System.arraycopy(leftUnion, k * BuildBoxes.BOX_SIZE, bestBoxes, 0, BuildBoxes.BOX_SIZE);
                    System.arraycopy(rightUnion, next * BuildBoxes.BOX_SIZE, bestBoxes, BuildBoxes.BOX_SIZE, BuildBoxes.BOX_SIZE);
                }
            }
        }
    }

    /**
     * The union sweeps of one axis, whose bins start at {@code base}: grows one box over the
     * occupied bins ({@code mask}'s bits) from the low end and one from the high end, and leaves
     * in {@link #leftArea}[k] and {@link #leftUnion} the half area and box of the union of bins
     * 0 … k, in {@link #rightArea}[k] and {@link #rightUnion} those of bins k … BINS − 1. The
     * unions are grown in locals: in the array, each bin's six updates waited for the previous
     * bin's stores; and both in one loop, as two chains of minima the processor overlaps.
     */
    private void sweep(int base, int mask) {
        double lx0 = Double.POSITIVE_INFINITY, ly0 = lx0, lz0 = lx0, hx0 = lx0, hy0 = lx0, hz0 = lx0;
        double lx1 = Double.NEGATIVE_INFINITY, ly1 = lx1, lz1 = lx1, hx1 = lx1, hy1 = lx1, hz1 = lx1;
        double[] box = binBox;
        // Each sweep stops one occupied bin short of the far end: the last occupied bin leaves no
        // right part, so no split needs its left union, nor the first one's right union.
        for (int low = mask, high = mask; (low & (low - 1)) != 0; ) {
            int k = Integer.numberOfTrailingZeros(low);
            int j = 31 - Integer.numberOfLeadingZeros(high);
            low &= low - 1;
            high ^= 1 << j;
            int o = (base + k) * BuildBoxes.BOX_SIZE, p = (base + j) * BuildBoxes.BOX_SIZE;
            lx0 = Math.min(box[o], lx0);
            ly0 = Math.min(box[o + 1], ly0);
            lz0 = Math.min(box[o + 2], lz0);
            lx1 = Math.max(box[o + 3], lx1);
            ly1 = Math.max(box[o + 4], ly1);
            lz1 = Math.max(box[o + 5], lz1);
            hx0 = Math.min(box[p], hx0);
            hy0 = Math.min(box[p + 1], hy0);
            hz0 = Math.min(box[p + 2], hz0);
            hx1 = Math.max(box[p + 3], hx1);
            hy1 = Math.max(box[p + 4], hy1);
            hz1 = Math.max(box[p + 5], hz1);
            leftArea[k] = BuildBoxes.halfArea(lx1 - lx0, ly1 - ly0, lz1 - lz0);
            BuildBoxes.set(leftUnion, k * BuildBoxes.BOX_SIZE, lx0, ly0, lz0, lx1, ly1, lz1);
            rightArea[j] = BuildBoxes.halfArea(hx1 - hx0, hy1 - hy0, hz1 - hz0);
            BuildBoxes.set(rightUnion, j * BuildBoxes.BOX_SIZE, hx0, hy0, hz0, hx1, hy1, hz1);
        }
    }

    /**
     * {@link #searchBinned} for the two primitives at {@code start}, without bins: every axis
     * on which their bins differ offers the same split, one primitive on each side, at the
     * same cost (a sum of two terms in either order is the same double), so the first such
     * axis is the one chosen, as the binned search (which replaces its best only by a
     * strictly cheaper split) chooses it.
     */
    void searchPair(double[] bounds, double[] centroid, int start, double[] lowOf, double[] extentOf,
                    double parentArea) {
        bestCost = Double.POSITIVE_INFINITY;
        bestBin = -1;
        bestAxis = -1;
        for (int a = 0; a < 3; ++a) {
            if (!searched[a]) continue;
            double scale = BINS / extentOf[a];
            int k0 = binOf(centroid[start * 3 + a], lowOf[a], scale);
            int k1 = binOf(centroid[(start + 1) * 3 + a], lowOf[a], scale);
            if (k0 == k1) continue;
            int lower = k0 < k1 ? start : start + 1, upper = 2 * start + 1 - lower;
            consider(sahCost(BuildBoxes.halfArea(bounds, lower * BuildBoxes.BOX_SIZE), 1,
                    BuildBoxes.halfArea(bounds, upper * BuildBoxes.BOX_SIZE), 1, parentArea),
                    Math.min(k0, k1), a);
            System.arraycopy(bounds, lower * BuildBoxes.BOX_SIZE, bestBoxes, 0, BuildBoxes.BOX_SIZE);
            System.arraycopy(bounds, upper * BuildBoxes.BOX_SIZE, bestBoxes, BuildBoxes.BOX_SIZE, BuildBoxes.BOX_SIZE);
            return;
        }
    }

    private boolean consider(double cost, int bin, int axis) {
        if (!(cost < bestCost)) return false;
        bestCost = cost;
        bestBin = bin;
        bestAxis = axis;
        return true;
    }

    /** @return where the bounds of the {@code side} (0 left, 1 right) child at {@code level} are */
    int place(int level, int side) {
        int at = (2 * level + side) * BuildBoxes.BOUNDS;
        if (at + BuildBoxes.BOUNDS > levels.length) levels = java.util.Arrays.copyOf(levels, Math.max(2 * levels.length, at + 2 * BuildBoxes.BOUNDS));
        return at;
    }

    /** @return {@link #levels}, with room for both children at {@code level} */
    double[] levels(int level) {
        place(level, 1);
        return levels;
    }

    /**
     * Fills the searched axes' bins, none occupied, from slots [start, end), in one pass
     * over the range (each slot's bounds are read once for all axes).
     */
    private void bin(double[] bounds, double[] centroid, int start, int end, double[] lowOf, double[] extentOf) {
        boolean sx = searched[0], sy = searched[1], sz = searched[2];
        double lx = lowOf[0], ly = lowOf[1], lz = lowOf[2];
        double kx = BINS / extentOf[0], ky = BINS / extentOf[1], kz = BINS / extentOf[2];
        int mx = 0, my = 0, mz = 0;
        // Consecutive slots are most often neighbours in space (a mesh lists its triangles strip
        // by strip, and the stable partitions keep that order), so they often fall in the same bin
        // on every searched axis: such a run is united in locals and added to its bins once, in
        // place of three read-modify-writes of six bounds per slot, each waiting for the last
        // slot's stores to the same bin. A minimum is the same whatever the order it is taken in,
        // so the bins hold the same boxes to the bit. A run starts as its first slot's box (most
        // runs in small nodes are one slot long) and grows only when a bound is beyond it, a
        // branch that is mostly not taken; Math.min there keeps −0.0 before +0.0.
        int px = -1, py = -1, pz = -1, run = 0;
        double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
        for (int i = start; i < end; ++i) {
            int c = i * 3, o = i * BuildBoxes.BOX_SIZE;
            int bx = sx ? binOf(centroid[c], lx, kx) : 0;
            int by = sy ? binOf(centroid[c + 1], ly, ky) : 0;
            int bz = sz ? binOf(centroid[c + 2], lz, kz) : 0;
            if (bx == px && by == py && bz == pz) {
                ++run;
                double v;
                if ((v = bounds[o]) <= x0) x0 = Math.min(v, x0);
                if ((v = bounds[o + 1]) <= y0) y0 = Math.min(v, y0);
                if ((v = bounds[o + 2]) <= z0) z0 = Math.min(v, z0);
                if ((v = bounds[o + 3]) >= x1) x1 = Math.max(v, x1);
                if ((v = bounds[o + 4]) >= y1) y1 = Math.max(v, y1);
                if ((v = bounds[o + 5]) >= z1) z1 = Math.max(v, z1);
                continue;
            }
            if (run > 0) {
                if (sx) mx |= add(px, 0, mx, run, x0, y0, z0, x1, y1, z1);
                if (sy) my |= add(py, BINS, my, run, x0, y0, z0, x1, y1, z1);
                if (sz) mz |= add(pz, 2 * BINS, mz, run, x0, y0, z0, x1, y1, z1);
            }
            px = bx;
            py = by;
            pz = bz;
            run = 1;
            x0 = bounds[o];
            y0 = bounds[o + 1];
            z0 = bounds[o + 2];
            x1 = bounds[o + 3];
            y1 = bounds[o + 4];
            z1 = bounds[o + 5];
        }
        if (run > 0) {
            if (sx) mx |= add(px, 0, mx, run, x0, y0, z0, x1, y1, z1);
            if (sy) my |= add(py, BINS, my, run, x0, y0, z0, x1, y1, z1);
            if (sz) mz |= add(pz, 2 * BINS, mz, run, x0, y0, z0, x1, y1, z1);
        }
        occupied[0] = mx;
        occupied[1] = my;
        occupied[2] = mz;
    }

    /**
     * Adds a run of {@code run} slots whose box is (x0, y0, z0)–(x1, y1, z1) to bin {@code k} of
     * the axis whose bins start at {@code base} and of which {@code occupied} (bits) hold slots
     * already: the first run sets the bin, the next ones grow it.
     *
     * @return k's bit
     */
    private int add(int k, int base, int occupied, int run, double x0, double y0, double z0, double x1, double y1, double z1) {
        int o = (base + k) * BuildBoxes.BOX_SIZE;
        double[] b = binBox;
        if ((occupied & 1 << k) == 0) {
            binCount[base + k] = run;
            b[o] = x0;
            b[o + 1] = y0;
            b[o + 2] = z0;
            b[o + 3] = x1;
            b[o + 4] = y1;
            b[o + 5] = z1;
            return 1 << k;
        }
        binCount[base + k] += run;
        b[o] = Math.min(x0, b[o]);
        b[o + 1] = Math.min(y0, b[o + 1]);
        b[o + 2] = Math.min(z0, b[o + 2]);
        b[o + 3] = Math.max(x1, b[o + 3]);
        b[o + 4] = Math.max(y1, b[o + 4]);
        b[o + 5] = Math.max(z1, b[o + 5]);
        return 1 << k;
    }

    /** @return the bin (0 … BINS − 1) of centroid coordinate {@code c} on an axis whose centroids start at {@code lo}, BINS per extent */
    static int binOf(double c, double lo, double scale) {
        int k = (int) ((c - lo) * scale);
        return k < 0 ? 0 : Math.min(k, BINS - 1);
    }

    /** The SAH cost of a split, relative to testing the parent's primitives: the one formula of both searches. */
    private static double sahCost(double leftArea, int leftCount, double rightArea, int rightCount, double parentArea) {
        return TRAVERSAL_COST + (leftArea * leftCount + rightArea * rightCount) / parentArea;
    }
}
