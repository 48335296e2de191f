package geometries;

import java.util.ArrayList;
import java.util.List;

import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/** An infinite circular tube of a positive radius around an axis line. Unbounded. */
public class Tube extends Geometry {
    /** The axis: its head is a point on the axis, its direction is unit length. */
    protected final Ray axis;
    protected final double radius;
    // The axis as doubles, read by every intersection.
    final double px, py, pz, vx, vy, vz;

    /** @throws IllegalArgumentException when the radius is not a positive finite number */
    public Tube(double radius, Ray axis) {
        this.radius = Util.requirePositive(radius, "tube radius");
        this.axis = axis;
        px = axis.getHead().getX();
        py = axis.getHead().getY();
        pz = axis.getHead().getZ();
        vx = axis.getDirection().getX();
        vy = axis.getDirection().getY();
        vz = axis.getDirection().getZ();
    }

    public Ray getAxis() {
        return axis;
    }

    public double getRadius() {
        return radius;
    }

    /** @return the signed distance of {@code p}'s projection along the axis from the axis head */
    double axial(Point p) {
        return (p.getX() - px) * vx + (p.getY() - py) * vy + (p.getZ() - pz) * vz;
    }

    @Override
    public Vector getNormal(Point point) {
        double s = axial(point);
        return new Vector(point.getX() - (px + vx * s), point.getY() - (py + vy * s), point.getZ() - (pz + vz * s))
                .normalize();
    }

    /**
     * One root of |(h + t·d − p)⊥|² = r², where ⊥ removes the axis component.
     *
     * @param far false for the nearer root, true for the farther one
     * @return the root, or NaN when the ray is parallel to the axis, misses or is tangent
     */
    double shellRoot(Ray ray, boolean far) {
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        double dx = d.getX(), dy = d.getY(), dz = d.getZ();
        double wx = h.getX() - px, wy = h.getY() - py, wz = h.getZ() - pz;
        double dv = dx * vx + dy * vy + dz * vz;
        double wv = wx * vx + wy * vy + wz * vz;
        double ax = dx - dv * vx, ay = dy - dv * vy, az = dz - dv * vz;
        double bx = wx - wv * vx, by = wy - wv * vy, bz = wz - wv * vz;
        double a = ax * ax + ay * ay + az * az;
        if (Util.isZero(a)) return Double.NaN;
        double b = ax * bx + ay * by + az * bz; // half of the usual b
        double c = bx * bx + by * by + bz * bz - radius * radius;
        double disc = Util.alignZero(b * b - a * c);
        if (disc <= 0) return Double.NaN;
        double sq = Math.sqrt(disc);
        return far ? (-b + sq) / a : (-b - sq) / a;
    }

    /** @return the root if it lies on the part of the shell this shape keeps (all of it, for a tube) */
    double keepShell(Ray ray, double t) {
        return t;
    }

    private double near(Ray ray) {
        return keepShell(ray, shellRoot(ray, false));
    }

    private double far(Ray ray) {
        return keepShell(ray, shellRoot(ray, true));
    }

    /** Cap roots (none for an infinite tube); see {@link Cylinder}. */
    double cap(Ray ray, boolean top) {
        return Double.NaN;
    }

    @Override
    public boolean closestHit(Ray ray, Hit hit) {
        double best = hit.t;
        double t = near(ray);
        if (inRange(t, best)) best = t;
        t = far(ray);
        if (inRange(t, best)) best = t;
        t = cap(ray, false);
        if (inRange(t, best)) best = t;
        t = cap(ray, true);
        if (inRange(t, best)) best = t;
        if (best == hit.t) return false;
        hit.set(best, this, 0);
        return true;
    }

    @Override
    public boolean visitHits(Ray ray, double maxDistance, HitVisitor visitor) {
        double t = near(ray);
        if (within(t, maxDistance) && !visitor.visit(this, t)) return false;
        t = far(ray);
        if (within(t, maxDistance) && !visitor.visit(this, t)) return false;
        t = cap(ray, false);
        if (within(t, maxDistance) && !visitor.visit(this, t)) return false;
        t = cap(ray, true);
        return !within(t, maxDistance) || visitor.visit(this, t);
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        double[] ts = { near(ray), far(ray), cap(ray, false), cap(ray, true) };
        java.util.Arrays.sort(ts); // NaN sorts last
        List<GeoPoint> result = new ArrayList<>(2);
        for (double t : ts)
            if (within(t, maxDistance)) result.add(new GeoPoint(this, ray.getPoint(t)));
        return result;
    }
}
