package geometries;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import lighting.LightSource;
import primitives.CourseClassGuard;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * Anything a ray can hit: what you extend to write a shape of your own. Override the one
 * intersection hook your course year names, with {@code maxDistance} (or in the one-argument form
 * of the courses before it):
 * <ul>
 * <li>2023&ndash;24 (5784): {@link #findGeoIntersectionsHelper}, answering {@link GeoPoint}s;</li>
 * <li>2024&ndash;25 (5785): {@link #calculateIntersectionsHelper}, answering {@link Intersection}s;</li>
 * <li>2025&ndash;26 (5786): {@link #calcIntersectionsHelper}, answering {@link Intersection}s.</li>
 * </ul>
 * Every year's query ({@link #findIntersections}, {@link #findGeoIntersections},
 * {@link #calculateIntersections}, {@link #calcIntersections}) then asks your hook, and returns
 * {@code null} when nothing is hit; so does the renderer (correct, but allocating). A subclass of
 * a library shape that overrides a hook is asked through it too.
 *
 * <p>Under the course's face, the engine. Intersection has two faces:
 * <ul>
 * <li>the course's list API ({@link #findIntersections}, {@link #findGeoIntersections}) for scene
 * tests, returning {@code null} when nothing is hit;</li>
 * <li>the renderer's lean path: a closest-hit query with a shrinking {@code tMax} and an any-hit
 * walk for shadow rays, neither of which builds a list, asked of a ray held as doubles (no
 * {@link Ray} object per ray). These are package-private, out of a student's code completion;
 * the renderer reaches them through {@link LeanQueries}.</li>
 * </ul>
 * The two forms of each lean query are joined here, once: the library's shapes implement the
 * doubles form, and their {@code Ray} form loads the ray into a record and asks it; a user's own
 * shape is asked through its course hook, and its doubles form makes the {@code Ray} and asks
 * that. Both faces accept a hit at distance {@code t} when {@code alignZero(t) > 0}, so the two
 * always agree. A subclass written by a user only needs one of the three course years' hooks
 * ({@link #findGeoIntersectionsHelper}, {@link #calculateIntersectionsHelper},
 * {@link #calcIntersectionsHelper}), with {@code maxDistance} or in the one-argument form of the
 * courses before it; every year's query method and the lean path then fall back to it (correct,
 * but allocating).
 */
public abstract class Intersectable extends BvhLeaf {
    /**
     * Whether this object's doubles forms of the lean queries answer for its course hooks
     * ({@link HookCheck#answersInDoubles}): a library shape, or a user's subclass of one that
     * overrides no hook, answers the {@code Ray} forms and the render through them; any other
     * (a user's shape written on {@link Geometry}, or a subclass that overrides a hook) through
     * its course hook. Fixed per class, read once at construction.
     */
    private final boolean answersInDoubles = HookCheck.answersInDoubles(getClass());
    /** The hook the lean queries ask when the doubles forms do not answer: the lowest a class declares. */
    private final HookCheck.Hook lowestHook = HookCheck.lowestHook(getClass());

    /**
     * A hit point together with the geometry it lies on (the 2023–24 course's hit record). Value
     * equality: two GeoPoints are equal when their geometries are {@code equals} (the same
     * instance, unless a user's geometry defines its own equality) and their points are equal. A
     * GeoPoint is never equal to an {@link Intersection}, whose rule is stricter: each record keeps
     * its own year's rule, and equality stays symmetric.
     */
    public static class GeoPoint {
        /** The geometry that was hit. */
        public final Geometry geometry;
        /** The hit point. */
        public final Point point;

        /**
         * @param geometry the geometry hit
         * @param point    the hit point on it
         */
        public GeoPoint(Geometry geometry, Point point) {
            this.geometry = geometry;
            this.point = point;
        }

        @Override
        public boolean equals(Object obj) {
            if (this == obj) return true;
            return obj != null && obj.getClass() == getClass() && Objects.equals(geometry, ((GeoPoint) obj).geometry)
                    && Objects.equals(point, ((GeoPoint) obj).point);
        }

        /** The geometry's hash only: points are compared with a tolerance, which no hash can follow. */
        @Override
        public int hashCode() {
            return Objects.hashCode(geometry);
        }

        @Override
        public String toString() {
            return getClass().getSimpleName() + "{" + geometry.getClass().getSimpleName() + " " + point + "}";
        }
    }

    /**
     * The hit record of the 2024–25 and 2025–26 courses: a {@link GeoPoint} that also carries the
     * geometry's material and the shading quantities a course tracer fills in per light. The
     * library's own tracer does not read the mutable fields; they are there for users' code.
     * Two Intersections are equal when they refer to the same geometry instance and equal
     * points; the mutable fields take no part.
     */
    public static class Intersection extends GeoPoint {
        /** The material of {@link #geometry} when the record was made. */
        public final Material material;
        /** The unit surface normal at the point (filled in by the tracer that uses the record). */
        public Vector normal;
        /** The direction of the ray that made the hit. */
        public Vector v;
        /** normal · v. */
        public double vNormal;
        /** The light currently being shaded. */
        public LightSource light;
        /** The direction from {@link #light} to the point. */
        public Vector l;
        /** normal · l. */
        public double lNormal;

        /**
         * @param geometry the geometry hit; its material becomes {@link #material}
         * @param point    the hit point on it
         * @throws NullPointerException when geometry or point is null
         */
        public Intersection(Geometry geometry, Point point) {
            super(Objects.requireNonNull(geometry, "geometry"), Objects.requireNonNull(point, "point"));
            this.material = geometry.getMaterial();
        }

        /** Equal for the same geometry instance (never merely an equal one) and equal points. */
        @Override
        public boolean equals(Object obj) {
            if (this == obj) return true;
            return obj instanceof Intersection other && geometry == other.geometry && point.equals(other.point);
        }

        /** The geometry's identity only, as {@link #equals} compares the geometry by identity. */
        @Override
        public int hashCode() {
            return System.identityHashCode(geometry);
        }
    }

    /**
     * Checks that the concrete class answers intersection queries: it overrides one of the three
     * years' hooks (or is a library shape, which overrides {@link #findGeoIntersectionsHelper}).
     * Without one, the three default hooks would only call each other.
     *
     * @throws IllegalStateException when the class overrides none of the hooks
     */
    protected Intersectable() {
        CourseClassGuard.check();
        if (!HookCheck.overridesAHook(getClass()))
            throw new IllegalStateException(getClass().getName() + " overrides none of findGeoIntersectionsHelper, "
                    + "calculateIntersectionsHelper or calcIntersectionsHelper(Ray, double) (or their forms without "
                    + "maxDistance, (Ray)): override the one of your course year");
        String unasked = HookCheck.unaskedOneArgumentHook(getClass());
        if (unasked != null)
            throw new IllegalStateException(unasked + ", so it would never be asked: override the form with maxDistance");
    }

    /**
     * @param ray the ray to intersect
     * @return the intersection points, or null when there are none
     */
    public final List<Point> findIntersections(Ray ray) {
        return findIntersections(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * The points of {@link #findGeoIntersections(Ray, double)} (a form some 2023–24 and 2024–25
     * cohorts use; same inclusive bound).
     *
     * @param ray         the ray to intersect
     * @param maxDistance intersections farther than this from the ray head are ignored (a hit at
     *                    exactly this distance counts)
     * @return the intersection points within {@code maxDistance}, or null when there are none
     */
    public final List<Point> findIntersections(Ray ray, double maxDistance) {
        List<GeoPoint> geoPoints = findGeoIntersections(ray, maxDistance);
        if (geoPoints == null) return null;
        List<Point> points = new ArrayList<>(geoPoints.size());
        for (GeoPoint gp : geoPoints) points.add(gp.point);
        return points;
    }

    /**
     * @param ray the ray to intersect
     * @return the intersections with their geometries, or null when there are none
     */
    public final List<GeoPoint> findGeoIntersections(Ray ray) {
        return findGeoIntersections(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * @param ray         the ray to intersect
     * @param maxDistance intersections farther than this from the ray head are ignored (a hit at
     *                    exactly this distance counts)
     * @return the intersections within {@code maxDistance}, or null when there are none
     */
    public final List<GeoPoint> findGeoIntersections(Ray ray, double maxDistance) {
        return nullWhenEmpty(findGeoIntersectionsHelper(ray, maxDistance));
    }

    /**
     * The 2024–25 spelling of {@link #findGeoIntersections(Ray)}.
     *
     * @param ray the ray to intersect
     * @return the intersections as {@link Intersection} records, or null when there are none
     */
    public final List<Intersection> calculateIntersections(Ray ray) {
        return calculateIntersections(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * The 2024–25 spelling of {@link #findGeoIntersections(Ray, double)} (same inclusive bound).
     *
     * @param ray         the ray to intersect
     * @param maxDistance intersections farther than this from the ray head are ignored
     * @return the intersections within {@code maxDistance}, or null when there are none
     */
    public final List<Intersection> calculateIntersections(Ray ray, double maxDistance) {
        return nullWhenEmpty(calculateIntersectionsHelper(ray, maxDistance));
    }

    /**
     * The 2025–26 spelling of {@link #findGeoIntersections(Ray)}.
     *
     * @param ray the ray to intersect
     * @return the intersections as {@link Intersection} records, or null when there are none
     */
    public final List<Intersection> calcIntersections(Ray ray) {
        return calcIntersections(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * The 2025–26 spelling of {@link #findGeoIntersections(Ray, double)} (same inclusive bound).
     *
     * @param ray         the ray to intersect
     * @param maxDistance intersections farther than this from the ray head are ignored
     * @return the intersections within {@code maxDistance}, or null when there are none
     */
    public final List<Intersection> calcIntersections(Ray ray, double maxDistance) {
        return nullWhenEmpty(calcIntersectionsHelper(ray, maxDistance));
    }

    private static <T> List<T> nullWhenEmpty(List<T> list) {
        return list == null || list.isEmpty() ? null : list;
    }

    /*
     * The three years' hooks. Each default calls the next one round the circle
     * findGeo… → calculate… → calc… → findGeo…, so a class overriding any one of them answers
     * every year's query (and the renderer's lean path, whose defaults call findGeo…); the
     * constructor rejects a class overriding none, which would only go round.
     *
     * The one-argument hooks (Ray only, the courses' form before maxDistance) sit outside the
     * circle: each default asks its year's two-argument hook with no bound. A class that overrides
     * only a one-argument hook is entered at findGeo…(Ray, double)'s default, which asks that hook
     * (HookCheck names it) and keeps the hits within maxDistance; so that default is the one place
     * both families meet, and no default calls back into a default.
     */

    /**
     * Every intersection at distance {@code t} with {@code alignZero(t) > 0} and
     * {@code alignZero(t - maxDistance) <= 0}. The 2023–24 hook: the library's shapes override
     * this one. With no hit in range every library hook returns {@code null}, as the course's
     * do; a user's override may return an empty list instead, and the queries and the default
     * hooks then answer {@code null} as well.
     *
     * @param ray         the ray to intersect
     * @param maxDistance the largest distance from the ray head that counts
     * @return the intersections, or null when there are none
     */
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        HookCheck.Hook oneArgument = HookCheck.oneArgumentHook(getClass());
        if (oneArgument != null) return oneArgumentHits(oneArgument, ray, maxDistance);
        List<Intersection> found = calculateIntersectionsHelper(ray, maxDistance);
        if (found == null || found.isEmpty()) return null;
        List<GeoPoint> result = new ArrayList<>(found.size());
        for (GeoPoint gp : found) result.add(gp.getClass() == GeoPoint.class ? gp : new GeoPoint(gp.geometry, gp.point));
        return result;
    }

    /**
     * The 2024–25 hook: same contract as {@link #findGeoIntersectionsHelper}, with
     * {@link Intersection} records.
     *
     * @param ray         the ray to intersect
     * @param maxDistance the largest distance from the ray head that counts
     * @return the intersections, or null when there are none
     */
    protected List<Intersection> calculateIntersectionsHelper(Ray ray, double maxDistance) {
        return nullWhenEmpty(calcIntersectionsHelper(ray, maxDistance));
    }

    /**
     * The 2025–26 hook: same contract as {@link #findGeoIntersectionsHelper}, with
     * {@link Intersection} records.
     *
     * @param ray         the ray to intersect
     * @param maxDistance the largest distance from the ray head that counts
     * @return the intersections, or null when there are none
     */
    protected List<Intersection> calcIntersectionsHelper(Ray ray, double maxDistance) {
        List<GeoPoint> found = findGeoIntersectionsHelper(ray, maxDistance);
        if (found == null || found.isEmpty()) return null;
        List<Intersection> result = new ArrayList<>(found.size());
        for (GeoPoint gp : found)
            result.add(gp instanceof Intersection i ? i : new Intersection(gp.geometry, gp.point));
        return result;
    }

    /**
     * The 2023–24 hook without {@code maxDistance} (the course's form before it): every
     * intersection at distance {@code t} with {@code alignZero(t) > 0}, or null when there are
     * none. Override it alone, and every year's query asks it and keeps the hits within their
     * bound. The default asks {@link #findGeoIntersectionsHelper(Ray, double)} with no bound.
     *
     * @param ray the ray to intersect
     * @return the intersections, or null when there are none
     */
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray) {
        return findGeoIntersectionsHelper(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * The 2024–25 hook without {@code maxDistance}: same contract as
     * {@link #findGeoIntersectionsHelper(Ray)}, with {@link Intersection} records. The default
     * asks {@link #calculateIntersectionsHelper(Ray, double)} with no bound.
     *
     * @param ray the ray to intersect
     * @return the intersections, or null when there are none
     */
    protected List<Intersection> calculateIntersectionsHelper(Ray ray) {
        return calculateIntersectionsHelper(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * The 2025–26 hook without {@code maxDistance}: same contract as
     * {@link #findGeoIntersectionsHelper(Ray)}, with {@link Intersection} records. The default
     * asks {@link #calcIntersectionsHelper(Ray, double)} with no bound.
     *
     * @param ray the ray to intersect
     * @return the intersections, or null when there are none
     */
    protected List<Intersection> calcIntersectionsHelper(Ray ray) {
        return calcIntersectionsHelper(ray, Double.POSITIVE_INFINITY);
    }

    /**
     * The hits of the one-argument hook a class overrides alone, within {@code maxDistance} by
     * the course rule ({@link #within}), as plain {@link GeoPoint}s (the 2023–24 record's value
     * equality; the later years' defaults rewrap them); null when none is in range.
     */
    private List<GeoPoint> oneArgumentHits(HookCheck.Hook hook, Ray ray, double maxDistance) {
        List<? extends GeoPoint> all = switch (hook) {
            case FIND_GEO -> findGeoIntersectionsHelper(ray);
            case CALCULATE -> calculateIntersectionsHelper(ray);
            case CALC -> calcIntersectionsHelper(ray);
        };
        if (all == null) return null;
        Point head = ray.getHead();
        List<GeoPoint> result = new ArrayList<>(all.size());
        for (GeoPoint gp : all)
            if (within(gp.point.distance(head), maxDistance))
                result.add(gp.getClass() == GeoPoint.class ? gp : new GeoPoint(gp.geometry, gp.point));
        return nullWhenEmpty(result);
    }

    /**
     * The hits of the hook this class declares lowest: a 2025–26 student's subclass of a library
     * shape that overrides {@code calcIntersectionsHelper} is rendered through it, as its
     * {@code calcIntersections} answers (the library's own hook, {@code findGeo…}, would not be).
     */
    private List<? extends GeoPoint> hookHits(Ray ray, double maxDistance) {
        return switch (lowestHook) {
            case FIND_GEO -> findGeoIntersectionsHelper(ray, maxDistance);
            case CALCULATE -> calculateIntersectionsHelper(ray, maxDistance);
            case CALC -> calcIntersectionsHelper(ray, maxDistance);
        };
    }

    /** @return whether the doubles forms answer for this object's course hooks (see the field) */
    final boolean answersInDoubles() {
        return answersInDoubles;
    }

    /**
     * The lean closest-hit query. {@code hit.t} is the current upper bound: a hit nearer than it
     * (and with {@code alignZero(t) > 0}) replaces the record. The library's shapes answer it with
     * {@link #closestHit(Hit)} (the ray loaded into the record); a user's own shape, by default,
     * with the nearest of {@link #findGeoIntersectionsHelper}'s list.
     *
     * @param ray the ray to intersect
     * @param hit the record to update; its {@code t} is the upper bound
     * @return true when {@code hit} was updated
     */
    boolean closestHit(Ray ray, Hit hit) {
        if (answersInDoubles) return closestHit(hit.setRay(ray));
        List<? extends GeoPoint> list = hookHits(ray, hit.t);
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
     * The closest-hit query of the ray {@code hit} carries (see
     * {@link Hit#setRay(double, double, double, double, double, double)}), without any ray
     * object: the renderer's form. Same contract as {@link #closestHit(Ray, Hit)}; the library's
     * shapes implement this one, and their {@link #closestHit(Ray, Hit)} loads the ray and calls
     * it. The default, for users' own shapes, builds the {@link Ray} and calls
     * {@link #closestHit(Ray, Hit)}.
     *
     * @param hit the record holding the query ray; its {@code t} is the upper bound
     * @return true when {@code hit} was updated
     */
    @Override
    boolean closestHit(Hit hit) {
        Ray ray = hit.ray();
        boolean found = closestHit(ray, hit);
        // An override of closestHit(Ray, Hit) (a class of this package: one elsewhere cannot
        // override it) may have asked other shapes with this record and another ray (a
        // transformed one, say), which loads that ray into it: the caller's ray is put back.
        hit.setRay(ray);
        return found;
    }

    /**
     * The any-hit walk: calls {@code visitor} for every intersection with {@code alignZero(t) > 0}
     * and {@code alignZero(t - maxDistance) <= 0}, in no particular order, until it returns false.
     * The library's shapes answer it with {@link #visitHits(Hit, double, HitVisitor)}; a user's own
     * shape, by default, with {@link #findGeoIntersectionsHelper}'s list.
     *
     * @param ray         the ray to intersect
     * @param maxDistance the largest distance from the ray head that counts
     * @param visitor     called with each hit's geometry and distance
     * @return false when the visitor stopped the walk
     */
    boolean visitHits(Ray ray, double maxDistance, HitVisitor visitor) {
        if (answersInDoubles) return visitHits(Hit.of(ray), maxDistance, visitor);
        List<? extends GeoPoint> list = hookHits(ray, maxDistance);
        if (list == null) return true;
        Point head = ray.getHead();
        for (GeoPoint gp : list)
            if (!visitor.visit(gp.geometry, gp.point.distance(head))) return false;
        return true;
    }

    /**
     * The any-hit walk of the ray {@code query} carries, without any ray object: the renderer's
     * form of {@link #visitHits(Ray, double, HitVisitor)}, with the same contract. Only the ray
     * of {@code query} is read; its hit fields are left alone. The default, for users' own
     * shapes, builds the {@link Ray} and calls {@link #visitHits(Ray, double, HitVisitor)}.
     *
     * @param query       the record holding the query ray
     * @param maxDistance the largest distance from the ray head that counts
     * @param visitor     called with each hit's geometry and distance
     * @return false when the visitor stopped the walk
     */
    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        return visitHits(query.ray(), maxDistance, visitor);
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
