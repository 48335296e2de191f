package geometries;

import java.util.List;

import primitives.Ray;

/**
 * A flat shape that a ray's line crosses at most once (a plane, a convex polygon): its queries
 * all reduce to one distance, so they are written once here around {@link #distanceTo(Hit)}.
 */
abstract class SingleHitGeometry extends Geometry {
    /**
     * @param query the record holding the ray
     * @return the distance along the ray to its hit, or NaN when it misses; the callers apply the
     *         range rules, so a non-positive distance may be returned as is
     */
    abstract double distanceTo(Hit query);

    @Override
    boolean closestHit(Hit hit) {
        if (!answersInDoubles()) return super.closestHit(hit); // a subclass's own hook answers
        double t = distanceTo(hit);
        if (!inRange(t, hit.t)) return false;
        hit.set(t, this, 0);
        return true;
    }

    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        if (!answersInDoubles()) return super.visitHits(query, maxDistance, visitor);
        double t = distanceTo(query);
        return !within(t, maxDistance) || visitor.visit(this, t);
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        double t = distanceTo(Hit.of(ray));
        return within(t, maxDistance) ? List.of(new GeoPoint(this, ray.getPoint(t))) : null;
    }
}
