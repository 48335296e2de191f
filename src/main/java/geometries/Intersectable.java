package geometries;

import java.util.ArrayList;
import java.util.List;

import primitives.Point;
import primitives.Ray;
import primitives.Util;

/**
 * Anything a ray can hit. It has two faces:
 * <ul>
 * <li>the course's list API ({@link #findIntersections}, {@link #findGeoIntersections}) for scene
 * tests, returning {@code null} when nothing is hit;</li>
 * <li>the renderer's lean path: {@link #closestHit(Ray, Hit)} with a shrinking {@code tMax} and
 * the any-hit walk {@link #visitHits(Ray, double, HitVisitor)} for shadow rays, neither of which
 * builds a list.</li>
 * </ul>
 * Both faces accept a hit at distance {@code t} when {@code alignZero(t) > 0}, so the two always
 * agree. A subclass written by a user only needs {@link #findGeoIntersectionsHelper}; the lean
 * path then falls back to it (correct, but allocating).
 */
public abstract class Intersectable {

    /** A hit point together with the geometry it lies on. Value equality on both fields. */
    public static class GeoPoint {
        /** The geometry that was hit. */
        public final Geometry geometry;
        /** The hit point. */
        public final Point point;

        public GeoPoint(Geometry geometry, Point point) {
            this.geometry = geometry;
            this.point = point;
        }

        @Override
        public boolean equals(Object obj) {
            if (this == obj) return true;
            return obj instanceof GeoPoint other && geometry == other.geometry && point.equals(other.point);
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(geometry);
        }

        @Override
        public String toString() {
            return "GeoPoint{" + geometry.getClass().getSimpleName() + " " + point + "}";
        }
    }

    /** @return the intersection points, or null when there are none */
    public final List<Point> findIntersections(Ray ray) {
        List<GeoPoint> geoPoints = findGeoIntersections(ray);
        if (geoPoints == null) return null;
        List<Point> points = new ArrayList<>(geoPoints.size());
        for (GeoPoint gp : geoPoints) points.add(gp.point);
        return points;
    }

    /** @return the intersections with their geometries, or null when there are none */
    public final List<GeoPoint> findGeoIntersections(Ray ray) {
        return findGeoIntersections(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * @param maxDistance intersections farther than this from the ray head are ignored
     * @return the intersections within {@code maxDistance}, or null when there are none
     */
    public final List<GeoPoint> findGeoIntersections(Ray ray, double maxDistance) {
        List<GeoPoint> result = findGeoIntersectionsHelper(ray, maxDistance);
        return result == null || result.isEmpty() ? null : result;
    }

    /**
     * Every intersection at distance {@code t} with {@code alignZero(t) > 0} and
     * {@code alignZero(t - maxDistance) <= 0}.
     *
     * @return the intersections, or null (or an empty list) when there are none
     */
    protected abstract List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance);

    /**
     * The lean closest-hit query. {@code hit.t} is the current upper bound: a hit nearer than it
     * (and with {@code alignZero(t) > 0}) replaces the record.
     *
     * @return true when {@code hit} was updated
     */
    public boolean closestHit(Ray ray, Hit hit) {
        List<GeoPoint> list = findGeoIntersectionsHelper(ray, hit.t);
        if (list == null) return false;
        boolean found = false;
        Point head = ray.getHead();
        for (GeoPoint gp : list) {
            double t = gp.point.distance(head);
            if (t < hit.t) {
                hit.set(t, gp.geometry, 0);
                found = true;
            }
        }
        return found;
    }

    /**
     * The any-hit walk: calls {@code visitor} for every intersection with {@code alignZero(t) > 0}
     * and {@code alignZero(t - maxDistance) <= 0}, in no particular order, until it returns false.
     *
     * @return false when the visitor stopped the walk
     */
    public boolean visitHits(Ray ray, double maxDistance, HitVisitor visitor) {
        List<GeoPoint> list = findGeoIntersectionsHelper(ray, maxDistance);
        if (list == null) return true;
        Point head = ray.getHead();
        for (GeoPoint gp : list)
            if (!visitor.visit(gp.geometry, gp.point.distance(head))) return false;
        return true;
    }

    /** @return the axis-aligned box enclosing this shape, or null when it is unbounded */
    public BoundingBox getBoundingBox() {
        return null;
    }

    /**
     * Adds to {@code out} the leaves an acceleration structure should index: the intersectable
     * itself by default; containers add their children's leaves.
     */
    void collectLeaves(List<Intersectable> out) {
        out.add(this);
    }

    /** How many independently bounded primitives this leaf holds (a mesh: its triangles). */
    int primitiveCount() {
        return 1;
    }

    /** The bounds of primitive {@code prim}; the whole box by default. */
    BoundingBox primitiveBounds(int prim) {
        return getBoundingBox();
    }

    /** {@link #closestHit(Ray, Hit)} restricted to primitive {@code prim}. */
    boolean closestHit(int prim, Ray ray, Hit hit) {
        return closestHit(ray, hit);
    }

    /** {@link #visitHits(Ray, double, HitVisitor)} restricted to primitive {@code prim}. */
    boolean visitHits(int prim, Ray ray, double maxDistance, HitVisitor visitor) {
        return visitHits(ray, maxDistance, visitor);
    }

    /** @return true when {@code t} is a valid hit distance below the strict bound {@code tMax} */
    static boolean inRange(double t, double tMax) {
        return Util.alignZero(t) > 0 && t < tMax;
    }

    /** @return true when {@code t} is a valid hit distance within {@code maxDistance} (course rule) */
    static boolean within(double t, double maxDistance) {
        return Util.alignZero(t) > 0 && Util.alignZero(t - maxDistance) <= 0;
    }
}
