package geometries;

import java.util.List;

import primitives.Ray;

/**
 * What a {@link Bvh} asks of the leaves it indexes, and only a tree asks: how many primitives a
 * leaf holds and their boxes, whether the tree may keep a primitive as packed numbers, and the
 * two queries restricted to one primitive. The package-private superclass of
 * {@link Intersectable}, so that every intersectable is a leaf without the protocol showing in
 * the class course users read and extend (as {@code AbstractStringBuilder} sits under
 * {@code StringBuilder}). The dispatch is the same virtual call it was.
 *
 * <p>The defaults make a leaf one primitive, its own box, asked through its own queries: right
 * for every shape, a user's included. A mesh overrides the counts and the per-primitive queries;
 * the library's sphere and triangle the packing.
 */
abstract class BvhLeaf {
    /** {@link #packedKind()}: not packed, a tree calls this leaf's own queries. */
    static final byte OWN = 0;
    /** {@link #packedKind()}: a sphere, packed as its centre (x, y, z) and its radius squared. */
    static final byte SPHERE = 1;
    /** {@link #packedKind()}: a triangle, packed as its first vertex and its two edges from it. */
    static final byte TRIANGLE = 2;
    /** Doubles per packed primitive. */
    static final int PACKED = 9;

    BvhLeaf() {
    }

    /** {@code Intersectable.closestHit(Hit)}, which the defaults below ask. */
    abstract boolean closestHit(Hit hit);

    /** {@code Intersectable.visitHits(Hit, double, HitVisitor)}, which the defaults below ask. */
    abstract boolean visitHits(Hit query, double maxDistance, HitVisitor visitor);

    /**
     * The axis-aligned box enclosing this leaf, or null when it is unbounded (the default: a
     * user's own shape is kept beside the tree). Declared here, not on {@link Intersectable}, so
     * that a student's class of their own BVH that has a {@code getBoundingBox()} clashes with
     * this internal class, which {@code migrate} names as the library's insides.
     */
    BoundingBox getBoundingBox() {
        return null;
    }

    /**
     * Adds to {@code out} the leaves an acceleration structure should index: this leaf itself by
     * default (the only subclass is {@link Intersectable}); containers add their children's leaves.
     */
    void collectLeaves(List<Intersectable> out) {
        out.add((Intersectable) this);
    }

    /** How many independently bounded primitives this leaf holds (a mesh: its triangles). */
    int primitiveCount() {
        return 1;
    }

    /**
     * The bounds of primitive {@code prim} of a leaf of several ({@link #primitiveCount()} &gt; 1).
     * A leaf of one primitive is its own box: the builder uses the {@link #getBoundingBox()} it
     * has already asked for (a shape may compute its box on every call), which for a mesh of one
     * triangle is that triangle's box, the same numbers.
     */
    BoundingBox primitiveBounds(int prim) {
        return getBoundingBox();
    }

    /**
     * How a tree may keep this leaf's primitives: {@link #OWN} (the default: it calls the
     * queries), or a kind it tests from {@link #pack packed} numbers with the same arithmetic as
     * the queries, so with the same hits, bit for bit, without reaching the object. Only the
     * library's own shapes (a sphere, a triangle, a mesh's triangles) are packed, and never a
     * subclass, which may override the queries ({@link Geometry#isLibraryShape()}).
     */
    byte packedKind() {
        return OWN;
    }

    /** Writes primitive {@code prim}'s numbers of its {@link #packedKind()} into {@code out[at..at + PACKED)}. */
    void pack(int prim, double[] out, int at) {
        throw new UnsupportedOperationException(getClass().getName() + " is not packed");
    }

    /** {@link #closestHit(Hit)} restricted to primitive {@code prim}. */
    boolean closestHit(int prim, Hit hit) {
        return closestHit(hit);
    }

    /** {@link #visitHits(Hit, double, HitVisitor)} restricted to primitive {@code prim}. */
    boolean visitHits(int prim, Hit query, double maxDistance, HitVisitor visitor) {
        return visitHits(query, maxDistance, visitor);
    }

    /** {@link #closestHit(int, Hit)} with the ray as an object (for tests). */
    final boolean closestHit(int prim, Ray ray, Hit hit) {
        return closestHit(prim, hit.setRay(ray));
    }

    /** {@link #visitHits(int, Hit, double, HitVisitor)} with the ray as an object (for tests). */
    final boolean visitHits(int prim, Ray ray, double maxDistance, HitVisitor visitor) {
        return visitHits(prim, Hit.of(ray), maxDistance, visitor);
    }
}
