package geometries;

import primitives.Ray;

/**
 * The renderer's way into a shape beside the course's list queries: the closest-hit query and the
 * any-hit walk, which build no list, the bounding box, and whether a shape is one of the library's
 * own. Static, and apart from {@link Intersectable}, so that a student completing
 * {@code sphere.} sees the course's methods only; the members these call are package-private, so
 * the library's shapes override them and a user's own shape inherits the defaults, which answer
 * through its course hook. Each method is one call, which the JIT inlines: the renderer's inner
 * loop pays nothing for the indirection.
 *
 * @hidden internal: the renderer's queries of a shape; a scene test asks findIntersections or findGeoIntersections
 */
public final class LeanQueries {
    private LeanQueries() {
    }

    /**
     * Told, before any of its rays is traced, that a render of about {@code cameraRays} camera rays
     * starts: a tree of {@code world} large enough takes the vector walk from the first ray when
     * the render is long ({@link Bvh#expectCameraRays}); otherwise nothing.
     *
     * @param world      the render's geometry, a tree or not
     * @param cameraRays the camera rays the render traces at least (pixels times the fewest a pixel takes)
     */
    public static void expectCameraRays(Intersectable world, long cameraRays) {
        if (world instanceof Bvh tree) tree.expectCameraRays(cameraRays);
    }

    /**
     * @param world the render's geometry, a tree or not
     * @return the words of the walk {@code world} takes now, when it is a tree ({@link Bvh#walkDescription()})
     */
    public static String walkDescription(Intersectable world) {
        return world instanceof Bvh tree ? tree.describeWalk() : Bvh.walkDescription();
    }

    /**
     * Told that a render will walk {@code world} for seconds more: when it is a tree with wide
     * nodes whose vector walk this JVM has not compiled yet, that walk is warmed on a thread of
     * its own ({@link Bvh#expectLongWalk}); otherwise nothing.
     *
     * @param world the render's geometry, a tree or not
     */
    public static void expectLongWalk(Intersectable world) {
        if (world instanceof Bvh tree) tree.expectLongWalk();
    }

    /**
     * The closest hit of the ray {@code hit} carries (see {@link Hit#reset(double)} for its bound):
     * a hit at distance {@code t} with {@code alignZero(t) > 0} and {@code t} below {@code hit}'s
     * current distance replaces the record. No object is made for a library shape.
     *
     * @param shape the shape, list or tree asked
     * @param hit   the record holding the query ray; its {@code t} is the strict upper bound
     * @return true when {@code hit} was updated
     */
    public static boolean closestHit(Intersectable shape, Hit hit) {
        return shape.closestHit(hit);
    }

    /**
     * {@link #closestHit(Intersectable, Hit)} of {@code ray}, which is loaded into {@code hit}.
     *
     * @param shape the shape, list or tree asked
     * @param ray   the ray to intersect
     * @param hit   the record to update; its {@code t} is the strict upper bound
     * @return true when {@code hit} was updated
     */
    public static boolean closestHit(Intersectable shape, Ray ray, Hit hit) {
        return shape.closestHit(ray, hit);
    }

    /**
     * The any-hit walk of the ray {@code query} carries: calls {@code visitor} for every hit at
     * distance {@code t} with {@code alignZero(t) > 0} and {@code alignZero(t - maxDistance) <= 0}
     * (the course's inclusive bound), in no particular order, until it returns false. Only the ray
     * of {@code query} is read.
     *
     * @param shape       the shape, list or tree asked
     * @param query       the record holding the query ray
     * @param maxDistance the largest distance from the ray head that counts, in scene units
     * @param visitor     called with each hit's geometry and distance
     * @return false when the visitor stopped the walk
     */
    public static boolean visitHits(Intersectable shape, Hit query, double maxDistance, HitVisitor visitor) {
        return shape.visitHits(query, maxDistance, visitor);
    }

    /**
     * The light buffer of a point light at (x, y, z) over {@code world}: its shadow rays are then
     * proved clear from a few leaves ({@link ShadowIndex#clear}).
     *
     * @param world the scene as the render traces it
     * @param x     the light's position, x coordinate
     * @param y     its y coordinate
     * @param z     its z coordinate
     * @return the index, or null where it would not pay or cannot be exact (a world that is not a
     *         tree, a user's shape without a box in it, a tree too large for its cells)
     */
    public static ShadowIndex shadowIndexFrom(Intersectable world, double x, double y, double z) {
        return world instanceof Bvh tree ? ShadowIndex.fromPoint(tree, x, y, z) : null;
    }

    /**
     * The light buffer of a directional light whose shadow rays go along the unit vector
     * (dx, dy, dz), bit for bit as the shadow rays' own direction.
     *
     * @param world the scene as the render traces it
     * @param dx    the shadow rays' direction (toward the light), x component
     * @param dy    its y component
     * @param dz    its z component
     * @return the index, or null as {@link #shadowIndexFrom}
     */
    public static ShadowIndex shadowIndexAlong(Intersectable world, double dx, double dy, double dz) {
        return world instanceof Bvh tree ? ShadowIndex.along(tree, dx, dy, dz) : null;
    }

    /** The probe's visitor: one crossing is the answer, so the walk stops at the first. */
    static final HitVisitor FIRST_CROSSING = (geometry, t) -> false;

    /**
     * Whether {@code shape} crosses the ray {@code query} carries at a distance the any-hit walk
     * accepts (the rule of {@link #visitHits(Intersectable, Hit, double, HitVisitor)}): a shadow
     * cache's probe of the shape that stopped the previous shadow ray.
     *
     * <p>A call site of its own rather than {@code visitHits}: the JIT profiles the receiver's
     * class at each call site, and one site shared by the render's tree and the probed shapes
     * told C2 "a tree and a sphere" early in a render, then a plane, then a polygon; each new
     * class threw away the compiled shadow-ray code that had inlined the site (up to eight
     * times a launch of the Sunflow scene; BENCHMARKS.md, issue 50, twelfth session).
     *
     * @param shape       the shape asked, one primitive
     * @param query       the record holding the query ray
     * @param maxDistance the largest distance from the ray head that counts, in scene units
     * @return true when the shape crosses the ray within {@code maxDistance}
     */
    public static boolean crosses(Geometry shape, Hit query, double maxDistance) {
        return !shape.visitHits(query, maxDistance, FIRST_CROSSING);
    }

    /**
     * {@link #visitHits(Intersectable, Hit, double, HitVisitor)} of {@code ray}.
     *
     * @param shape       the shape, list or tree asked
     * @param ray         the ray to intersect
     * @param maxDistance the largest distance from the ray head that counts, in scene units
     * @param visitor     called with each hit's geometry and distance
     * @return false when the visitor stopped the walk
     */
    public static boolean visitHits(Intersectable shape, Ray ray, double maxDistance, HitVisitor visitor) {
        return shape.visitHits(ray, maxDistance, visitor);
    }

    /**
     * @param shape a shape, list or tree
     * @return the axis-aligned box enclosing it, or null when it is unbounded (a plane, an
     *         infinite tube, a user's own shape)
     */
    public static BoundingBox boundingBox(Intersectable shape) {
        return shape.getBoundingBox();
    }

    /**
     * Whether {@code g} is one of the library's own shapes, not a subclass of one: its geometry is
     * fixed when it is made and its queries have no side effects, so what a renderer learnt of it
     * holds from one ray or render to the next. A user's class may move its shape or count its
     * calls, so nothing is kept for it.
     *
     * @param g a geometry
     * @return true for an instance of exactly one of the library's shape classes
     */
    public static boolean isLibraryShape(Geometry g) {
        return g.isLibraryShape();
    }

    /**
     * Whether {@code g} is a {@link #isLibraryShape library shape} whose queries are one
     * intersection test (all but a mesh, which loops over its triangles), so that asking it again
     * costs no more than a tree's test of one primitive: the renderer's shadow cache keeps only these.
     *
     * @param g a geometry
     * @return true for an instance of exactly one of the library's shape classes other than {@link TriangleMesh}
     */
    public static boolean isLibraryPrimitive(Geometry g) {
        return g.isLibraryPrimitive();
    }
}
