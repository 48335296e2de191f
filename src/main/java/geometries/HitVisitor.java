package geometries;

/**
 * Receives the intersections of an any-hit walk; see {@link LeanQueries#visitHits(Intersectable, Hit, double, HitVisitor)}.
 *
 * @hidden internal: the renderer's any-hit walk, public for package renderer
 */
@FunctionalInterface
public interface HitVisitor {
    /**
     * @param geometry the geometry hit
     * @param t        the hit distance from the ray head
     * @return true to go on visiting, false to stop the walk
     */
    boolean visit(Geometry geometry, double t);
}
