package geometries;

/**
 * The binned surface-area heuristic of {@link BvhBuilder}: one task's bins, reused for every node
 * the task splits. Per searched axis, {@link #BINS} counts and boxes, filled in one pass over a
 * node's range; the cheapest split is then found by sweeping each axis from both ends.
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
    /** Per axis, the bins {@link #bin} filled, as bits; the search empties them again. */
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

    BvhBinner() {
        for (int k = 0; k < 3 * BINS; ++k) BuildBoxes.empty(binBox, k * BuildBoxes.BOX_SIZE);
    }

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
            sweep(base, mask, false, rightArea);
            sweep(base, mask, true, leftArea);
            int leftCount = 0;
            for (int m = mask; ; ) {
                int k = Integer.numberOfTrailingZeros(m);
                m &= m - 1;
                if (m == 0) break; // the last occupied bin leaves no right part
                leftCount += binCount[base + k];
                consider(sahCost(leftArea[k], leftCount, rightArea[Integer.numberOfTrailingZeros(m)], n - leftCount,
                        parentArea), k, a);
            }
            for (int m = mask; m != 0; m &= m - 1) {
                int k = base + Integer.numberOfTrailingZeros(m);
                binCount[k] = 0;
                BuildBoxes.empty(binBox, k * BuildBoxes.BOX_SIZE);
            }
        }
    }

    /**
     * The union sweep of one axis, whose bins start at {@code base}: grows a box over the
     * occupied bins ({@code mask}'s bits) from the low end ({@code fromLow}) or the high end,
     * and leaves in {@code area[k]} the half area of the union of bin k and those before it
     * in the sweep (bins 0 … k from the low end, k … BINS − 1 from the high end). The union is
     * grown in locals: in the array, each bin's six updates waited for the previous bin's stores.
     */
    private void sweep(int base, int mask, boolean fromLow, double[] area) {
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        double[] box = binBox;
        for (int m = mask; m != 0; ) {
            int k = fromLow ? Integer.numberOfTrailingZeros(m) : 31 - Integer.numberOfLeadingZeros(m);
            m ^= 1 << k;
            int o = (base + k) * BuildBoxes.BOX_SIZE;
            x0 = Math.min(box[o + BuildBoxes.LOW], x0);
            y0 = Math.min(box[o + BuildBoxes.LOW + 1], y0);
            z0 = Math.min(box[o + BuildBoxes.LOW + 2], z0);
            x1 = Math.max(box[o + BuildBoxes.HIGH], x1);
            y1 = Math.max(box[o + BuildBoxes.HIGH + 1], y1);
            z1 = Math.max(box[o + BuildBoxes.HIGH + 2], z1);
            area[k] = BuildBoxes.halfArea(x1 - x0, y1 - y0, z1 - z0);
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
            int lower = k0 < k1 ? start : start + 1;
            consider(sahCost(BuildBoxes.halfArea(bounds, lower * BuildBoxes.BOX_SIZE), 1,
                    BuildBoxes.halfArea(bounds, (2 * start + 1 - lower) * BuildBoxes.BOX_SIZE), 1, parentArea),
                    Math.min(k0, k1), a);
            return;
        }
    }

    private void consider(double cost, int bin, int axis) {
        if (cost < bestCost) {
            bestCost = cost;
            bestBin = bin;
            bestAxis = axis;
        }
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
     * Fills the searched axes' bins, which are empty, from slots [start, end), in one pass
     * over the range (each slot's bounds are read once for all axes).
     */
    private void bin(double[] bounds, double[] centroid, int start, int end, double[] lowOf, double[] extentOf) {
        boolean sx = searched[0], sy = searched[1], sz = searched[2];
        double lx = lowOf[0], ly = lowOf[1], lz = lowOf[2];
        double kx = BINS / extentOf[0], ky = BINS / extentOf[1], kz = BINS / extentOf[2];
        int mx = 0, my = 0, mz = 0;
        for (int i = start; i < end; ++i) {
            int c = i * 3;
            if (sx) mx |= add(binOf(centroid[c], lx, kx), 0, bounds, i);
            if (sy) my |= add(binOf(centroid[c + 1], ly, ky), BINS, bounds, i);
            if (sz) mz |= add(binOf(centroid[c + 2], lz, kz), 2 * BINS, bounds, i);
        }
        occupied[0] = mx;
        occupied[1] = my;
        occupied[2] = mz;
    }

    /** Adds slot {@code i} to bin {@code k} of the axis whose bins start at {@code base}; @return k's bit */
    private int add(int k, int base, double[] bounds, int i) {
        binCount[base + k]++;
        BuildBoxes.grow(binBox, (base + k) * BuildBoxes.BOX_SIZE, bounds, i * BuildBoxes.BOX_SIZE);
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
