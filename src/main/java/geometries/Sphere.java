package geometries;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import primitives.Checks;
import primitives.Kernels;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A sphere given by its centre and a positive radius. Intersections use the geometric method
 * (the ray point nearest the centre, then half the chord), so a hit lies on the surface up to
 * rounding that grows linearly with the distance from the ray head, not with its square: measured
 * at most about 6e-16 of the distance (6e-11 for a unit sphere 1e5 away). A ray tangent to the
 * sphere does not hit it.
 */
public class Sphere extends Geometry {
    private final Point center;
    private final double radius;
    private final double radiusSquared;

    /**
     * @param center the centre
     * @param radius the radius, in scene units, positive and finite
     * @throws NullPointerException     naming the centre when it is null
     * @throws IllegalArgumentException when the radius is not a positive finite number
     */
    public Sphere(Point center, double radius) {
        this.center = Objects.requireNonNull(center, "sphere center");
        this.radius = Checks.requirePositive(radius, "sphere radius");
        this.radiusSquared = radius * radius;
    }

    /**
     * The argument order of older course versions.
     *
     * @param radius the radius, in scene units, positive and finite
     * @param center the centre
     * @throws IllegalArgumentException when the radius is not a positive finite number
     */
    public Sphere(double radius, Point center) {
        this(center, radius);
    }

    /** @return the centre */
    public Point getCenter() {
        return center;
    }

    /** @return the radius, in scene units */
    public double getRadius() {
        return radius;
    }

    @Override
    public Vector getNormal(Point point) {
        // Divided by the radius first: for a point on the surface that is already unit length
        // within the zero tolerance, so normalize() returns it without a second allocation.
        double[] n = new double[3];
        normal(point.getX(), point.getY(), point.getZ(), n);
        return new Vector(n[0], n[1], n[2]);
    }

    /** The normal at (x, y, z) into {@code out[0..2]}: the one computation of both forms. */
    private void normal(double x, double y, double z, double[] out) {
        Kernels.normalize((x - center.getX()) / radius, (y - center.getY()) / radius, (z - center.getZ()) / radius, out);
    }

    @Override
    void normalAt(Hit hit) {
        normal(hit.px, hit.py, hit.pz, hit.normal);
    }

    /** Distance along the ray to the point nearest the centre: the middle of the two roots. */
    private double projection(Hit q) {
        return projection(q, center.getX(), center.getY(), center.getZ());
    }

    /** {@link #projection(Hit)} of a sphere centred at (cx, cy, cz): the one computation of both forms. */
    static double projection(Hit q, double cx, double cy, double cz) {
        return (cx - q.ox) * q.dx + (cy - q.oy) * q.dy + (cz - q.oz) * q.dz;
    }

    /**
     * Half the chord length: the roots of |head + t·dir − center|² = r² are {@code tm ± th} with
     * th² = r² − d², d being the distance from the centre to the ray's line. d² is taken as
     * |u − tm·dir|² (u = center − head), the square of a vector of length ≤ r where it matters,
     * rather than as |u|² − tm², a difference of two squares of the distance to the sphere: there
     * the rounding of |u|² (relative 1e-16 of the distance squared) swamps r² for far spheres.
     * This way the error of a hit grows linearly with the distance, not with its square.
     *
     * @return th, or NaN when the ray misses or only touches the sphere (a tangent is no hit)
     */
    private double halfChord(Hit q, double tm) {
        return halfChord(q, tm, center.getX(), center.getY(), center.getZ(), radiusSquared);
    }

    /** {@link #halfChord(Hit, double)} of a sphere centred at (cx, cy, cz) of radius squared {@code r2}. */
    static double halfChord(Hit q, double tm, double cx, double cy, double cz, double r2) {
        double px = cx - q.ox - tm * q.dx;
        double py = cy - q.oy - tm * q.dy;
        double pz = cz - q.oz - tm * q.dz;
        double th2 = r2 - (px * px + py * py + pz * pz);
        return Util.alignZero(th2) <= 0 ? Double.NaN : Math.sqrt(th2);
    }

    @Override
    boolean closestHit(Hit hit) {
        if (!answersInDoubles()) return super.closestHit(hit); // a subclass's own hook answers
        double t = distance(hit, center.getX(), center.getY(), center.getZ(), radiusSquared);
        if (!inRange(t, hit.t)) return false;
        hit.set(t, this, 0);
        return true;
    }

    /**
     * The distance to the first crossing ahead of the ray head (the far one when the head is
     * inside) of the sphere centred at (cx, cy, cz) of radius squared {@code r2}: the one
     * computation behind {@link #closestHit(Hit)} and a tree's packed spheres.
     *
     * @return the distance, possibly ≤ 0 (the caller checks the range), or NaN on a miss
     */
    static double distance(Hit q, double cx, double cy, double cz, double r2) {
        double tm = projection(q, cx, cy, cz);
        double th = halfChord(q, tm, cx, cy, cz, r2);
        double t = tm - th;
        return Util.alignZero(t) > 0 ? t : tm + th;
    }

    @Override
    byte packedKind() {
        return isLibraryShape() ? SPHERE : OWN; // a subclass may override the queries the packed copy stands for
    }

    @Override
    void pack(int prim, double[] out, int at) {
        out[at] = center.getX();
        out[at + 1] = center.getY();
        out[at + 2] = center.getZ();
        out[at + 3] = radiusSquared;
    }

    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        if (!answersInDoubles()) return super.visitHits(query, maxDistance, visitor);
        return visitHits(this, query, maxDistance, visitor, center.getX(), center.getY(), center.getZ(), radiusSquared);
    }

    /**
     * {@link #visitHits(Hit, double, HitVisitor)} of {@code sphere}, centred at (cx, cy, cz) of
     * radius squared {@code r2}: the one computation behind it and a tree's packed spheres.
     */
    static boolean visitHits(Geometry sphere, Hit query, double maxDistance, HitVisitor visitor,
                             double cx, double cy, double cz, double r2) {
        double tm = projection(query, cx, cy, cz);
        double th = halfChord(query, tm, cx, cy, cz, r2);
        if (Double.isNaN(th)) return true;
        if (within(tm - th, maxDistance) && !visitor.visit(sphere, tm - th)) return false;
        return !within(tm + th, maxDistance) || visitor.visit(sphere, tm + th);
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        Hit query = Hit.of(ray);
        double tm = projection(query);
        double th = halfChord(query, tm);
        if (Double.isNaN(th)) return null;
        List<GeoPoint> result = new ArrayList<>(2);
        if (within(tm - th, maxDistance)) result.add(new GeoPoint(this, ray.getPoint(tm - th)));
        if (within(tm + th, maxDistance)) result.add(new GeoPoint(this, ray.getPoint(tm + th)));
        return result.isEmpty() ? null : result;
    }

    @Override
    BoundingBox getBoundingBox() {
        return new BoundingBox(center.getX() - radius, center.getY() - radius, center.getZ() - radius,
                center.getX() + radius, center.getY() + radius, center.getZ() + radius);
    }
}
