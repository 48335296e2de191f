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

/** An infinite circular tube of a positive radius around an axis line. Unbounded. */
public class Tube extends Geometry {
    /** {@link Hit#primitive} of a hit on the shell (the curved surface). */
    static final int SHELL = 0;
    /** {@link Hit#primitive} of a hit on a cylinder's bottom cap (at the axis head). */
    static final int BOTTOM = 1;
    /** {@link Hit#primitive} of a hit on a cylinder's top cap. */
    static final int TOP = 2;

    /** The axis: its head is a point on the axis, its direction is unit length. */
    protected final Ray axis;
    /** The radius, in scene units, positive and finite. */
    protected final double radius;
    // The axis as doubles, read by every intersection.
    final double px, py, pz, vx, vy, vz;

    /**
     * @param radius the radius, in scene units, positive and finite
     * @param axis   the axis line (both directions: the tube is infinite)
     * @throws NullPointerException     naming the axis when it is null
     * @throws IllegalArgumentException when the radius is not a positive finite number
     */
    public Tube(double radius, Ray axis) {
        this.radius = Checks.requirePositive(radius, "tube radius");
        this.axis = Objects.requireNonNull(axis, "tube axis");
        px = axis.getHead().getX();
        py = axis.getHead().getY();
        pz = axis.getHead().getZ();
        vx = axis.getDirection().getX();
        vy = axis.getDirection().getY();
        vz = axis.getDirection().getZ();
    }

    /**
     * {@link #Tube(double, Ray)} with the arguments in the order several cohorts use.
     *
     * @param axis   the axis line
     * @param radius the radius, in scene units, positive and finite
     * @throws NullPointerException     naming the axis when it is null
     * @throws IllegalArgumentException when the radius is not a positive finite number, naming it
     */
    public Tube(Ray axis, double radius) {
        this(radius, axis);
    }

    /** @return the axis: a point on it and its unit direction */
    public Ray getAxis() {
        return axis;
    }

    /** @return the radius, in scene units */
    public double getRadius() {
        return radius;
    }

    /** @return the signed distance of {@code p}'s projection along the axis from the axis head */
    double axial(Point p) {
        return axial(p.getX(), p.getY(), p.getZ());
    }

    private double axial(double x, double y, double z) {
        return (x - px) * vx + (y - py) * vy + (z - pz) * vz;
    }

    @Override
    public Vector getNormal(Point point) {
        return radialNormal(point);
    }

    /**
     * The shell's normal: from the point's foot on the axis to the point, unit length.
     *
     * @throws IllegalArgumentException for a point on the axis (within the zero tolerance of a
     *                                  vector), where no direction is radial
     */
    final Vector radialNormal(Point point) {
        double[] n = new double[3];
        if (!radialNormal(point.getX(), point.getY(), point.getZ(), n))
            throw new IllegalArgumentException("point " + point + " is on the axis " + axis + ": it has no normal there");
        return new Vector(n[0], n[1], n[2]);
    }

    /**
     * The shell's normal at (x, y, z) into {@code out[0..2]}: the one computation of both forms.
     *
     * @return false when the point is on the axis, where {@code out} means nothing (a hit on the
     *         shell never is: it lies at the radius)
     */
    private boolean radialNormal(double x, double y, double z, double[] out) {
        double s = axial(x, y, z);
        double rx = x - (px + vx * s), ry = y - (py + vy * s), rz = z - (pz + vz * s);
        Kernels.normalize(rx, ry, rz, out);
        return !(Util.isZero(rx) && Util.isZero(ry) && Util.isZero(rz));
    }

    /** The normal of the surface recorded by the closest-hit query: no guessing from the point. */
    @Override
    void normalAt(Hit hit) {
        double[] n = hit.normal;
        switch (hit.primitive) {
        case BOTTOM -> { // the axis direction, negated
            n[0] = -vx;
            n[1] = -vy;
            n[2] = -vz;
        }
        case TOP -> {
            n[0] = vx;
            n[1] = vy;
            n[2] = vz;
        }
        default -> radialNormal(hit.px, hit.py, hit.pz, n);
        }
    }

    /**
     * The axial extent of the shape: the shell is kept for 0 &lt; s &lt; height, and caps close it
     * at s = 0 and s = height. +∞ for the infinite tube (no caps, the whole shell).
     */
    double height() {
        return Double.POSITIVE_INFINITY;
    }

    /**
     * The one intersection routine behind {@link #closestHit(Hit)} and
     * {@link #visitHits(Hit, double, HitVisitor)}: the shell's quadratic is solved once, and the
     * caps are tested with the same per-ray quantities (the axial coordinate along the ray is
     * {@code wv + t·dv}, the radial vector is {@code b + t·a}). The ray is {@code query}'s. With
     * {@code visitor} null it is a closest-hit query updating {@code query}, bounded by its
     * {@code t}; otherwise an any-hit walk bounded by {@code maxDistance}.
     *
     * @return closest-hit: whether {@code hit} was updated; any-hit: false when the visitor stopped
     */
    private boolean intersect(Hit query, double maxDistance, HitVisitor visitor) {
        double dx = query.dx, dy = query.dy, dz = query.dz;
        double wx = query.ox - px, wy = query.oy - py, wz = query.oz - pz;
        double dv = dx * vx + dy * vy + dz * vz;
        double wv = wx * vx + wy * vy + wz * vz;
        // The ray's direction and head relative to the axis head, without their axial parts.
        double ax = dx - dv * vx, ay = dy - dv * vy, az = dz - dv * vz;
        double bx = wx - wv * vx, by = wy - wv * vy, bz = wz - wv * vz;
        double a = ax * ax + ay * ay + az * az;
        double b = ax * bx + ay * by + az * bz; // half of the usual b
        double c = bx * bx + by * by + bz * bz - radius * radius;
        double height = height();

        // Shell: the roots of |b + t·a|² = r², kept (for a cylinder) strictly between the caps.
        double near = Double.NaN, far = Double.NaN;
        if (!Util.isZero(a)) { // not parallel to the axis
            double disc = Util.alignZero(b * b - a * c);
            if (disc > 0) { // a tangent is no hit
                double sq = Math.sqrt(disc);
                near = keepShell((-b - sq) / a, wv, dv, height);
                far = keepShell((-b + sq) / a, wv, dv, height);
            }
        }
        // Caps: the planes s = 0 and s = height, inside the rim (the rim belongs to the cap). A ray
        // parallel to the axis at the radius lies on the shell: it only touches the cylinder, and
        // a tangent is no hit (the course's rule), though it passes through both rims.
        double bottom = Double.NaN, top = Double.NaN;
        double dvz = Util.alignZero(dv);
        boolean alongTheShell = Util.isZero(a) && Util.alignZero(c) == 0;
        if (height != Double.POSITIVE_INFINITY && dvz != 0 && !alongTheShell) {
            bottom = insideRim(-wv / dv, ax, ay, az, bx, by, bz);
            top = insideRim((height - wv) / dv, ax, ay, az, bx, by, bz);
        }

        if (visitor != null)
            return offer(visitor, maxDistance, near) && offer(visitor, maxDistance, far)
                    && offer(visitor, maxDistance, bottom) && offer(visitor, maxDistance, top);
        Hit hit = query;
        double best = hit.t;
        int surface = -1;
        if (inRange(near, best)) {
            best = near;
            surface = SHELL;
        }
        if (inRange(far, best)) {
            best = far;
            surface = SHELL;
        }
        if (inRange(bottom, best)) {
            best = bottom;
            surface = BOTTOM;
        }
        if (inRange(top, best)) {
            best = top;
            surface = TOP;
        }
        if (surface < 0) return false;
        hit.set(best, this, surface);
        return true;
    }

    /** @return {@code t} when its axial coordinate {@code wv + t·dv} is strictly inside (0, height), else NaN */
    private static double keepShell(double t, double wv, double dv, double height) {
        if (height == Double.POSITIVE_INFINITY) return t;
        double s = wv + t * dv;
        return Util.alignZero(s) > 0 && Util.alignZero(s - height) < 0 ? t : Double.NaN;
    }

    /** @return {@code t} when the ray point there is within the radius of the axis (rim included), else NaN */
    private double insideRim(double t, double ax, double ay, double az, double bx, double by, double bz) {
        double qx = bx + t * ax, qy = by + t * ay, qz = bz + t * az;
        return Util.alignZero(qx * qx + qy * qy + qz * qz - radius * radius) <= 0 ? t : Double.NaN;
    }

    /** @return false when {@code t} is in range and the visitor stops the walk there */
    private boolean offer(HitVisitor visitor, double maxDistance, double t) {
        return !within(t, maxDistance) || visitor.visit(this, t);
    }

    @Override
    boolean closestHit(Hit hit) {
        if (!answersInDoubles()) return super.closestHit(hit); // a subclass's own hook answers
        return intersect(hit, 0, null);
    }

    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        if (!answersInDoubles()) return super.visitHits(query, maxDistance, visitor);
        return intersect(query, maxDistance, Objects.requireNonNull(visitor, "visitor"));
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        double[] ts = new double[4];
        int[] n = { 0 };
        intersect(Hit.of(ray), maxDistance, (g, t) -> {
            ts[n[0]++] = t;
            return true;
        });
        if (n[0] == 0) return null;
        java.util.Arrays.sort(ts, 0, n[0]);
        List<GeoPoint> result = new ArrayList<>(n[0]);
        for (int i = 0; i < n[0]; ++i) result.add(new GeoPoint(this, ray.getPoint(ts[i])));
        return result;
    }
}
