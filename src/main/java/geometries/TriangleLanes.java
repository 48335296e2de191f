package geometries;

/**
 * The leaf layout a tree with wide nodes gives its leaves of triangles, so that the vector walk
 * ({@code VectorWalk}) tests a leaf's triangles in one vector step, a triangle per lane. The
 * numbers are the ones a scalar leaf holds ({@link BvhLeaf#PACKED} doubles per triangle, the
 * kernel's arguments of {@code Triangle.intersect}: first vertex, edge 1, edge 2), in a copy of
 * the tree's {@code packed} array ({@link WideTree#lanes}) at the same place, only transposed: for
 * a leaf of {@code c} triangles whose first is {@code first}, number {@code r} (0 … 8) of its
 * triangle {@code j} is at {@code first · 9 + r · c + j}. So number {@code r} of all its
 * triangles loads as one vector of {@link #LANES} doubles from {@code first · 9 + r · c}; the
 * lanes at {@code j ≥ c} read whatever follows (the next number, the next leaf, or the
 * {@link #PADDING} at the array's end) and are ignored.
 *
 * <p>Which leaves: those of triangles only ({@link BvhLeaf#TRIANGLE}, the library's own, packed)
 * of at most {@link #LANES}, which with the builder's leaves of at most four is every leaf of a
 * mesh. A leaf with a sphere, a user's shape or a polygon keeps the scalar layout and test.
 * {@link WideNodes#collapse} marks the lane leaves (a negative count), {@link #arrange} lays them
 * out; both ask {@link #fits}, so the two always agree. The tree's own {@code packed} array is
 * never arranged: the scalar walk reads it while a render's threads may switch to the copy.
 */
final class TriangleLanes {
    /** Triangles per vector step: four doubles, a 256-bit vector (AVX2). */
    static final int LANES = 4;
    /** Doubles after the last packed record, so that a vector load of a leaf's last number stays in the array. */
    static final int PADDING = LANES - 1;

    private TriangleLanes() {
    }

    /** @return whether the leaf of primitives [first, first + count) is tested in lanes: triangles only, at most {@link #LANES} */
    static boolean fits(byte[] kind, int first, int count) {
        if (count > LANES) return false;
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
        double[] leaf = new double[LANES * BvhLeaf.PACKED];
        int shift = Integer.numberOfTrailingZeros(wide.width);
        for (int item = 0, end = wide.count * wide.width; item < end; ++item) {
            int count = -WideNodes.count(wide.node, item, shift);
            if (count <= 0) continue;
            int first = WideNodes.link(wide.node, item, shift);
            int at = first * BvhLeaf.PACKED;
            System.arraycopy(packed, at, leaf, 0, count * BvhLeaf.PACKED);
            for (int j = 0; j < count; ++j)
                for (int r = 0; r < BvhLeaf.PACKED; ++r)
                    packed[row(first, count, r) + j] = leaf[j * BvhLeaf.PACKED + r];
        }
    }
}
