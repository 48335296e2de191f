package geometries;

import primitives.Point;
import primitives.Util;

/**
 * A triangle: a polygon of three vertices, intersected with the Möller–Trumbore kernel that
 * {@link TriangleMesh} shares, so a mesh and the same triangles as objects render identically.
 */
public class Triangle extends Polygon {
    private final double ax, ay, az, e1x, e1y, e1z, e2x, e2y, e2z;

    /**
     * @param p1 the first vertex
     * @param p2 the second vertex
     * @param p3 the third vertex; the order sets the normal (p2 − p1) × (p3 − p1)
     * @throws IllegalArgumentException when points repeat or are collinear
     */
    public Triangle(Point p1, Point p2, Point p3) {
        super(p1, p2, p3);
        ax = p1.getX();
        ay = p1.getY();
        az = p1.getZ();
        e1x = p2.getX() - ax;
        e1y = p2.getY() - ay;
        e1z = p2.getZ() - az;
        e2x = p3.getX() - ax;
        e2y = p3.getY() - ay;
        e2z = p3.getZ() - az;
    }

    /**
     * Möller–Trumbore. A ray through an edge or a vertex (a barycentric coordinate within the
     * zero tolerance) or parallel to the plane misses; so does a ray starting on the triangle.
     *
     * @return the hit distance (possibly ≤ 0: the caller checks the range), or NaN on a miss
     */
    static double intersect(Hit query, double ax, double ay, double az,
                            double e1x, double e1y, double e1z, double e2x, double e2y, double e2z) {
        double dx = query.dx, dy = query.dy, dz = query.dz;
        double px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        if (Util.isZero(det)) return Double.NaN;
        double inv = 1.0 / det;
        double tx = query.ox - ax, ty = query.oy - ay, tz = query.oz - az;
        double u = (tx * px + ty * py + tz * pz) * inv;
        if (Util.alignZero(u) <= 0 || Util.alignZero(u - 1) >= 0) return Double.NaN;
        double qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
        double v = (dx * qx + dy * qy + dz * qz) * inv;
        if (Util.alignZero(v) <= 0 || Util.alignZero(u + v - 1) >= 0) return Double.NaN;
        return (e2x * qx + e2y * qy + e2z * qz) * inv;
    }

    @Override
    byte packedKind() {
        return isLibraryShape() ? TRIANGLE : OWN; // a subclass may override the queries the packed copy stands for
    }

    /** The kernel's arguments: the first vertex and the two edges from it. */
    @Override
    void pack(int prim, double[] out, int at) {
        out[at] = ax;
        out[at + 1] = ay;
        out[at + 2] = az;
        out[at + 3] = e1x;
        out[at + 4] = e1y;
        out[at + 5] = e1z;
        out[at + 6] = e2x;
        out[at + 7] = e2y;
        out[at + 8] = e2z;
    }

    /** {@link #intersect} of a triangle packed at {@code s[at..at + 9)} by {@link #pack}. */
    static double intersect(Hit query, double[] s, int at) {
        return intersect(query, s[at], s[at + 1], s[at + 2], s[at + 3], s[at + 4], s[at + 5], s[at + 6], s[at + 7], s[at + 8]);
    }

    /** Möller–Trumbore instead of the polygon's plane-then-edges test. */
    @Override
    double distanceTo(Hit query) {
        return intersect(query, ax, ay, az, e1x, e1y, e1z, e2x, e2y, e2z);
    }
}
