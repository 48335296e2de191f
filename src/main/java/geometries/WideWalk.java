package geometries;

/**
 * The walks of a {@link Bvh}'s {@link WideNodes}, as {@link Vectorization} provides them: the
 * vector implementation when the JVM can run it, none otherwise (the tree then keeps its binary
 * nodes and walks them in scalar code). An interface so that the tree never names the class that
 * needs {@code jdk.incubator.vector}.
 */
interface WideWalk {
    /** @return children per wide node, as this walk reads them */
    int width();

    /** @return the most triangles a lane leaf holds ({@link TriangleLanes}): what the leaf test takes in one vector step, 4 or 8 */
    int leafLanes();

    /** @return how many primitives a tree must index to be walked this way (smaller ones keep the scalar walk) */
    int minPrimitives();

    /** @return what runs, for the render summary: the width and the smallest tree it takes */
    String description();

    /**
     * The closest hit below {@code hit}'s bound among the primitives under the wide root (whose
     * box the caller has tested), by the tree's tie rule.
     *
     * @param lanes  the tree's packed numbers with its lane leaves transposed ({@link WideTree#lanes})
     * @param stack  room for {@link WideNodes#stackSize()} children, owned by this walk
     * @param stackT their entry distances
     * @return whether a primitive was hit (the record then holds it)
     */
    boolean closestHit(Bvh tree, float[] node, double[] lanes, Hit hit, int[] stack, double[] stackT);

    /**
     * Every hit within {@code maxDistance} below the wide root, to {@code visitor}, in the scalar
     * walk's order (the tree's leaf order).
     *
     * @param lanes the tree's packed numbers with its lane leaves transposed ({@link WideTree#lanes})
     * @param limit the distance up to which boxes are entered (a little past maxDistance)
     * @param stack room for {@link WideNodes#stackSize()} children, owned by this walk
     * @return false when the visitor stopped the walk
     */
    boolean visitHits(Bvh tree, float[] node, double[] lanes, Hit query, double limit, double maxDistance, HitVisitor visitor,
                      int[] stack);
}
