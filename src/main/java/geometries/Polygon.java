package geometries;

import java.util.List;
import java.util.Objects;

import primitives.Point;
import primitives.Util;
import primitives.Vector;

/**
 * A convex planar polygon given by its vertices in order (either winding). A ray through an edge
 * or a vertex does not hit it (the course's rule), nor does a ray in its plane.
 */
public class Polygon extends SingleHitGeometry {
    /** The vertices, in order. */
    protected final List<Point> vertices;
    /** The supporting plane. */
    protected final Plane plane;
    /** The number of vertices. */
    protected final int size;

    // Flat copies for the inside test: vertex i and edge i = vertex (i+1) − vertex i.
    private final double[] vx, vy, vz, ex, ey, ez;
    private final double nx, ny, nz;

    /**
     * @param vertices the corners in order around the polygon (either direction), at least 3, all in
     *                 one plane, forming a convex polygon
     * @throws IllegalArgumentException for fewer than 3 vertices, repeated or collinear vertices,
     *                                  vertices off the plane of the first three, or a concave or
     *                                  out-of-order (self-crossing) vertex list
     */
    public Polygon(Point... vertices) {
        if (vertices == null || vertices.length < 3)
            throw new IllegalArgumentException("a polygon needs at least 3 vertices, got "
                    + (vertices == null ? 0 : vertices.length));
        for (int i = 0; i < vertices.length; ++i) Objects.requireNonNull(vertices[i], "polygon vertex " + i);
        this.vertices = List.of(vertices);
        this.size = vertices.length;
        for (int i = 0; i < size; ++i)
            if (vertices[i].equals(vertices[(i + 1) % size]))
                throw new IllegalArgumentException("polygon vertices " + i + " and " + (i + 1) % size
                        + " repeat the point " + vertices[i]);
        this.plane = new Plane(vertices[0], Plane.normalOf(vertices[0], vertices[1], vertices[2], "polygon"));
        requireHittableSize(vertices[0], vertices[1], vertices[2]);
        Vector n = plane.getNormal();
        nx = n.getX();
        ny = n.getY();
        nz = n.getZ();
        vx = new double[size];
        vy = new double[size];
        vz = new double[size];
        ex = new double[size];
        ey = new double[size];
        ez = new double[size];
        for (int i = 0; i < size; ++i) {
            Point a = vertices[i], b = vertices[(i + 1) % size];
            vx[i] = a.getX();
            vy[i] = a.getY();
            vz[i] = a.getZ();
            ex[i] = b.getX() - a.getX();
            ey[i] = b.getY() - a.getY();
            ez[i] = b.getZ() - a.getZ();
        }
        double scale = 0;
        for (int i = 0; i < size; ++i) scale = Math.max(scale, Math.sqrt(ex[i] * ex[i] + ey[i] * ey[i] + ez[i] * ez[i]));
        for (int i = 3; i < size; ++i) {
            double off = nx * (vx[i] - vx[0]) + ny * (vy[i] - vy[0]) + nz * (vz[i] - vz[0]);
            if (Math.abs(off) > 1e-10 * scale)
                throw new IllegalArgumentException("polygon vertex " + i + " " + vertices[i]
                        + " is not in the plane of the first three (off by " + off + ")");
        }
        // Convex and ordered: every turn (edge i × edge i+1) points the same way as the normal,
        // and the edges wind around exactly once.
        double winding = 0;
        for (int i = 0; i < size; ++i) {
            int j = (i + 1) % size;
            double turn = nx * (ey[i] * ez[j] - ez[i] * ey[j]) + ny * (ez[i] * ex[j] - ex[i] * ez[j])
                    + nz * (ex[i] * ey[j] - ey[i] * ex[j]);
            if (turn <= 1e-10 * scale * scale)
                throw new IllegalArgumentException("polygon must be convex with vertices in order: the turn at vertex "
                        + j + " " + vertices[j] + (Math.abs(turn) <= 1e-10 * scale * scale ? " is straight (collinear)" : " goes the wrong way"));
            double li = Math.sqrt(ex[i] * ex[i] + ey[i] * ey[i] + ez[i] * ez[i]);
            double lj = Math.sqrt(ex[j] * ex[j] + ey[j] * ey[j] + ez[j] * ez[j]);
            double dot = (ex[i] * ex[j] + ey[i] * ey[j] + ez[i] * ez[j]) / (li * lj);
            winding += Math.acos(Math.max(-1, Math.min(1, dot)));
        }
        if (winding > 2 * Math.PI + 1e-6)
            throw new IllegalArgumentException("polygon vertices must be in order: the edges wind around "
                    + winding / (2 * Math.PI) + " times (self-crossing)");
    }

    /**
     * Rejects a polygon too small to be hit: the intersection tests (the edge test below,
     * Möller–Trumbore in {@link Triangle}) compare quantities of the order of twice the area with
     * the absolute zero tolerance, so when (v1 − v0) × (v2 − v0) is below it no ray would ever hit
     * the shape. The same rule as {@link MeshChecks#isDegenerate}'s "too small". (A plane through
     * such points is fine: its test uses the unit normal.)
     */
    private static void requireHittableSize(Point p0, Point p1, Point p2) {
        double e1x = p1.getX() - p0.getX(), e1y = p1.getY() - p0.getY(), e1z = p1.getZ() - p0.getZ();
        double e2x = p2.getX() - p0.getX(), e2y = p2.getY() - p0.getY(), e2z = p2.getZ() - p0.getZ();
        double cx = e1y * e2z - e1z * e2y, cy = e1z * e2x - e1x * e2z, cz = e1x * e2y - e1y * e2x;
        if (Util.isZero(cx) && Util.isZero(cy) && Util.isZero(cz))
            throw new IllegalArgumentException("polygon is too small to be hit: twice the area of its first three vertices "
                    + p0 + ", " + p1 + ", " + p2 + " is " + Math.sqrt(cx * cx + cy * cy + cz * cz)
                    + ", below the zero tolerance 2^-40");
    }

    @Override
    public Vector getNormal(Point point) {
        return plane.getNormal();
    }

    @Override
    void normalAt(Hit hit) {
        plane.normalAt(hit);
    }

    /** NaN when the ray misses the polygon or grazes its boundary. */
    @Override
    double distanceTo(Hit query) {
        double t = plane.distanceTo(query);
        if (!(t > 0)) return Double.NaN;
        double px = query.ox + query.dx * t, py = query.oy + query.dy * t, pz = query.oz + query.dz * t;
        // Inside when P is strictly on the inner side of every edge: (edge × (P − vertex)) · n > 0.
        for (int i = 0; i < size; ++i) {
            double wx = px - vx[i], wy = py - vy[i], wz = pz - vz[i];
            double s = nx * (ey[i] * wz - ez[i] * wy) + ny * (ez[i] * wx - ex[i] * wz) + nz * (ex[i] * wy - ey[i] * wx);
            if (Util.alignZero(s) <= 0) return Double.NaN;
        }
        return t;
    }

    @Override
    BoundingBox getBoundingBox() {
        double minX = vx[0], minY = vy[0], minZ = vz[0], maxX = minX, maxY = minY, maxZ = minZ;
        for (int i = 1; i < size; ++i) {
            minX = Math.min(minX, vx[i]);
            minY = Math.min(minY, vy[i]);
            minZ = Math.min(minZ, vz[i]);
            maxX = Math.max(maxX, vx[i]);
            maxY = Math.max(maxY, vy[i]);
            maxZ = Math.max(maxZ, vz[i]);
        }
        return new BoundingBox(minX, minY, minZ, maxX, maxY, maxZ);
    }
}
