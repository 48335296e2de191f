package geometries;

import java.util.Objects;

import primitives.Point;
import primitives.Util;
import primitives.Vector;

/** An infinite plane: a point on it and a unit normal. Unbounded, so it has no bounding box. */
public class Plane extends SingleHitGeometry {
    private final Point q;
    private final Vector normal;

    /**
     * The plane through three points; its normal is (p2 − p1) × (p3 − p1), normalized.
     *
     * @param p1 a point of the plane, also its reference point
     * @param p2 a second point
     * @param p3 a third point, not on the line through the first two
     * @throws IllegalArgumentException when two points coincide or all three are collinear
     */
    public Plane(Point p1, Point p2, Point p3) {
        this.q = p1;
        this.normal = normalOf(p1, p2, p3, "plane");
    }

    /**
     * @param q      a point of the plane
     * @param normal any non-zero vector; it is normalized
     */
    public Plane(Point q, Vector normal) {
        this.q = Objects.requireNonNull(q, "plane point q");
        this.normal = Objects.requireNonNull(normal, "plane normal").normalize();
    }

    /**
     * The unit normal (p2 − p1) × (p3 − p1) of three points, with the precise complaint when they
     * do not span a plane.
     */
    static Vector normalOf(Point p1, Point p2, Point p3, String what) {
        Objects.requireNonNull(p1, what + " point p1");
        Objects.requireNonNull(p2, what + " point p2");
        Objects.requireNonNull(p3, what + " point p3");
        if (p1.equals(p2) || p1.equals(p3) || p2.equals(p3))
            throw new IllegalArgumentException(what + " points must be distinct, got " + p1 + ", " + p2 + ", " + p3);
        Vector v1 = p2.subtract(p1);
        Vector v2 = p3.subtract(p1);
        double cx = v1.getY() * v2.getZ() - v1.getZ() * v2.getY();
        double cy = v1.getZ() * v2.getX() - v1.getX() * v2.getZ();
        double cz = v1.getX() * v2.getY() - v1.getY() * v2.getX();
        // Collinearity relative to the edge lengths, so that the test does not depend on scale.
        double rel = Math.sqrt(cx * cx + cy * cy + cz * cz) / (v1.length() * v2.length());
        if (rel < 1e-10)
            throw new IllegalArgumentException(what + " points must not be collinear, got " + p1 + ", " + p2 + ", " + p3);
        // Not new Vector(cx, cy, cz): for a tiny triangle (edges of 1e-7) the product is below the
        // absolute zero tolerance although the points clearly span a plane.
        return v1.crossProduct(v2).normalize();
    }

    /** @return a point on the plane */
    public Point getQ() {
        return q;
    }

    /** @return the unit normal */
    public Vector getNormal() {
        return normal;
    }

    @Override
    public Vector getNormal(Point point) {
        return normal;
    }

    @Override
    void normalAt(Hit hit) {
        hit.normal[0] = normal.getX();
        hit.normal[1] = normal.getY();
        hit.normal[2] = normal.getZ();
    }

    /** NaN when the ray is parallel to the plane or starts on it. */
    @Override
    double distanceTo(Hit query) {
        double nd = Util.alignZero(normal.getX() * query.dx + normal.getY() * query.dy + normal.getZ() * query.dz);
        if (nd == 0) return Double.NaN;
        double nqh = Util.alignZero(normal.getX() * (q.getX() - query.ox) + normal.getY() * (q.getY() - query.oy)
                + normal.getZ() * (q.getZ() - query.oz));
        if (nqh == 0) return Double.NaN;
        return nqh / nd;
    }
}
