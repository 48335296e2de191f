package geometries;

/**
 * The leaf layout a tree with wide nodes gives its leaves of triangles, so that the vector walk
 * ({@code VectorWalk}) tests a leaf's triangles in one vector step, a triangle per lane. The
 * numbers are the ones a scalar leaf holds ({@link BvhLeaf#PACKED} doubles per triangle, the
 * kernel's arguments of {@code Triangle.intersect}: first vertex, edge 1, edge 2), in a copy of
 * the tree's {@code packed} array ({@link WideTree#lanes}) at the same place, only transposed: for
 * a leaf of {@code c} triangles whose first is {@code first}, number {@code r} (0 … 8) of its
 * triangle {@code j} is at {@code first · 9 + r · c + j}. So number {@code r} of all its
 * triangles loads as one vector from {@code first · 9 + r · c}; the lanes at {@code j ≥ c} read
 * whatever follows (the next number, the next leaf, or the {@link #PADDING} at the array's end)
 * and are ignored.
 *
 * <p>Which leaves: a lane leaf is a whole subtree of the binary tree (a binary leaf, or an inner
 * node and everything below it) of triangles only ({@link BvhLeaf#TRIANGLE}, the library's own,
 * packed), at most as many as the walk's leaf test takes in one step ({@link WideWalk#leafLanes},
 * 4 or 8). A subtree's primitives are contiguous in leaf order, so the lane leaf holds the same
 * primitives in the same order as the binary leaves it replaces, and the tie rule (the first in
 * leaf order) picks the same one. A leaf with a sphere, a user's shape or a polygon keeps the
 * scalar layout and test. {@link WideNodes#collapse} chooses the lane leaves (a negative count,
 * asking {@link #fits}), {@link #arrange} lays out the leaves it chose. The tree's own
 * {@code packed} array is never arranged: the scalar walk reads it while a render's threads may
 * switch to the copy.
 */
final class TriangleLanes {
    /** The most triangles a leaf test takes in one step: eight doubles, a 512-bit vector (AVX-512). */
    static final int MAX_LANES = 8;
    /** Doubles after the last packed record, so that a vector load of a leaf's last number stays in the array. */
    static final int PADDING = MAX_LANES - 1;

    private TriangleLanes() {
    }

    /**
     * @param lanes the triangles the walk's leaf test takes in one step
     * @return whether primitives [first, first + count) may be a lane leaf: triangles only, at most {@code lanes}
     */
    static boolean fits(byte[] kind, int first, int count, int lanes) {
        if (count > lanes) return false;
        for (int k = first; k < first + count; ++k)
            if (kind[k] != BvhLeaf.TRIANGLE) return false;
        return true;
    }

    /** @return where number {@code r} of the lane leaf of {@code count} triangles from {@code first} starts */
    static int row(int first, int count, int r) {
        return first * BvhLeaf.PACKED + r * count;
    }

    /**
     * Transposes, in place in {@code packed} (a tree's copy, {@link WideTree#of}), every lane leaf
     * of the wide nodes {@code wide} (a negative count) from the scalar layout (a triangle's nine
     * numbers together) into lanes.
     */
    static void arrange(WideNodes wide, double[] packed) {
        double[] scratch = new double[MAX_LANES * BvhLeaf.PACKED];
        for (int c = 0, end = wide.count * wide.width; c < end; ++c) {
            int slot = wide.slot(c), count = -WideNodes.count(wide.node, slot, wide.width);
            if (count > 0) arrange(packed, WideNodes.link(wide.node, slot, wide.width), count, scratch);
        }
    }

    /**
     * Transposes the leaf of {@code count} triangles from {@code first} into lanes, in place.
     *
     * @param scratch room for {@link #MAX_LANES} triangles' numbers
     */
    static void arrange(double[] packed, int first, int count, double[] scratch) {
        int at = first * BvhLeaf.PACKED;
        System.arraycopy(packed, at, scratch, 0, count * BvhLeaf.PACKED);
        for (int j = 0; j < count; ++j)
            for (int r = 0; r < BvhLeaf.PACKED; ++r)
                packed[row(first, count, r) + j] = scratch[j * BvhLeaf.PACKED + r];
    }
}
