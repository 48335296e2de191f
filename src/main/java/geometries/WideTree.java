package geometries;

/**
 * What the vector walk reads of a {@link Bvh} beside its binary nodes: the walk, the wide nodes
 * ({@link WideNodes}) and a copy of the packed numbers with its triangle leaves laid out in lanes
 * ({@link TriangleLanes}). A copy, so that the scalar walk, which reads the tree's own packed
 * numbers, is never disturbed: a tree gets its wide part while a render walks it (once the
 * vector walk is compiled, {@link Bvh#expectLongWalk}), and the render's threads take the vector
 * walk from their next ray. Immutable once made; the tree publishes it whole (a volatile field),
 * so a thread sees either none or all of it.
 *
 * @param walk  the vector walk that reads it
 * @param nodes the wide nodes, collapsed from the tree's binary ones
 * @param lanes the tree's packed numbers, its lane leaves transposed; the same length
 */
record WideTree(WideWalk walk, WideNodes nodes, double[] lanes) {
    /** @return the wide part of the binary tree {@code node} ({@code nodes} records) over {@code kind} and {@code packed} */
    static WideTree of(WideWalk walk, float[] node, int nodes, byte[] kind, double[] packed) {
        WideNodes wide = WideNodes.collapse(node, nodes, walk.width(), kind, walk.leafLanes());
        double[] lanes = packed.clone();
        if (lanes.length > 0) TriangleLanes.arrange(wide, lanes);
        return new WideTree(walk, wide, lanes);
    }

    /** @return the bytes it adds to the tree: the wide nodes and the copy of the packed numbers (padding excluded) */
    long bytes(int primitives) {
        return nodes.bytes() + (lanes.length == 0 ? 0 : primitives * (long) BvhLeaf.PACKED * Double.BYTES);
    }
}
