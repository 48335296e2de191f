package geometries;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import primitives.Kernels;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A triangle mesh with one emission and one material: vertex positions and triangle indices in
 * flat arrays, no object per triangle. Each triangle is intersected with the same kernel as
 * {@link Triangle} ({@code Triangle.intersect}, fed the same differences of the same doubles), and
 * its flat normal is computed with the same arithmetic as {@link Triangle}'s, so a mesh renders
 * bit for bit like the same triangles given as {@link Triangle} objects.
 *
 * <p>In a {@link Bvh} the mesh is one leaf of {@link #triangleCount()} primitives, each bounded on
 * its own. Outside a BVH (the flat list) every query loops over all triangles after a test of the
 * mesh's box.
 *
 * <p>Shading: with per-vertex normals, the normal at a hit is the normalized barycentric blend of
 * the three vertex normals (smooth shading); without, it is the triangle's face normal
 * {@code (v1 − v0) × (v2 − v0)}, normalized. Barycentric coordinates are recomputed from the hit
 * point when the normal is asked for (once per shaded ray), so the hit records only the triangle.
 *
 * <p>Memory: 12 bytes per triangle (three {@code int} indices) plus 24 bytes per vertex (48 with
 * normals). A closed mesh has about half as many vertices as triangles, so that is about 24 bytes
 * per triangle (36 with normals). The mesh stores no edge vectors: its own queries recompute
 * them (six subtractions next to a test of about thirty flops). A {@link Bvh} over a library mesh
 * keeps a packed copy of the kernel's nine doubles per triangle in leaf order (72 bytes and a
 * kind byte), which its walks read instead of the mesh's arrays. Measured on a 1,000,000-triangle
 * sphere before that copy: 25 bytes per triangle for the mesh, about 130 more for the tree.
 *
 * <p>Immutable: the constructor copies its arrays.
 */
public class TriangleMesh extends Geometry {
    /** Twice a triangle's area must exceed this fraction of its longest edge squared (as in {@link Polygon}). */
    private static final double MIN_AREA_RATIO = 1e-10;

    /** x, y, z of vertex i at 3i, 3i+1, 3i+2. */
    private final double[] positions;
    /** Vertex indices of triangle k at 3k, 3k+1, 3k+2, in winding order. */
    private final int[] indices;
    /** Unit normal of vertex i at 3i..3i+2, or null for flat shading. */
    private final double[] normals;
    private final BoundingBox bounds;
    // The bounds widened like the BVH's primitive boxes, for the early-out of the whole-mesh queries.
    private final BoundingBox paddedBounds;

    /**
     * A flat-shaded mesh: every triangle has its face normal.
     *
     * @param positions x, y, z of each vertex, interleaved; finite
     * @param indices   three vertex indices (0-based) per triangle
     * @throws IllegalArgumentException as {@link #TriangleMesh(double[], int[], double[])} does
     * @see #TriangleMesh(double[], int[], double[])
     */
    public TriangleMesh(double[] positions, int[] indices) {
        this(positions, indices, null);
    }

    /**
     * @param positions x, y, z of each vertex, interleaved; finite
     * @param indices   three vertex indices (0-based) per triangle; the order sets the face normal
     *                  {@code (v1 − v0) × (v2 − v0)}
     * @param normals   null for flat shading, or one normal per vertex (x, y, z interleaved, as
     *                  long as {@code positions}); any non-zero length, they are normalized
     * @throws NullPointerException     when {@code positions} or {@code indices} is null
     * @throws IllegalArgumentException for a length not a multiple of 3, no triangle, a non-finite
     *                                  coordinate, a zero or non-finite normal, an index out of
     *                                  range, or a degenerate triangle (two vertices that coincide,
     *                                  or one too thin to have a normal, as {@link Triangle} rejects),
     *                                  naming the vertex or triangle
     */
    public TriangleMesh(double[] positions, int[] indices, double[] normals) {
        Objects.requireNonNull(positions, "positions");
        Objects.requireNonNull(indices, "indices");
        if (positions.length % 3 != 0)
            throw new IllegalArgumentException("positions length " + positions.length
                    + " is not a multiple of 3 (x, y, z per vertex)");
        if (indices.length % 3 != 0)
            throw new IllegalArgumentException("indices length " + indices.length
                    + " is not a multiple of 3 (three vertices per triangle)");
        if (indices.length == 0) throw new IllegalArgumentException("a mesh needs at least one triangle, got none");
        int vertexCount = positions.length / 3;
        for (int i = 0; i < vertexCount; ++i)
            if (!Double.isFinite(positions[3 * i]) || !Double.isFinite(positions[3 * i + 1])
                    || !Double.isFinite(positions[3 * i + 2]))
                throw new IllegalArgumentException("vertex " + i + " " + vertexString(positions, i)
                        + " has a non-finite coordinate");
        if (normals != null) {
            if (normals.length != positions.length)
                throw new IllegalArgumentException("normals length " + normals.length + " must equal positions length "
                        + positions.length + " (one normal per vertex)");
            normals = normals.clone();
            for (int i = 0; i < vertexCount; ++i) {
                double x = normals[3 * i], y = normals[3 * i + 1], z = normals[3 * i + 2];
                if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)
                        || Util.isZero(x) && Util.isZero(y) && Util.isZero(z))
                    throw new IllegalArgumentException("normal of vertex " + i + " " + vertexString(normals, i)
                            + " must be finite and non-zero");
                double inv = 1 / Math.sqrt(x * x + y * y + z * z);
                normals[3 * i] = x * inv;
                normals[3 * i + 1] = y * inv;
                normals[3 * i + 2] = z * inv;
            }
        }
        for (int k = 0, n = indices.length / 3; k < n; ++k) {
            for (int c = 0; c < 3; ++c) {
                int v = indices[3 * k + c];
                if (v < 0 || v >= vertexCount)
                    throw new IllegalArgumentException("triangle " + k + " has vertex index " + v + " outside 0.."
                            + (vertexCount - 1));
            }
            int a = indices[3 * k], b = indices[3 * k + 1], c = indices[3 * k + 2];
            String why = degeneracy(positions, a, b, c);
            if (why != null)
                throw new IllegalArgumentException("triangle " + k + " (vertices " + a + " " + vertexString(positions, a)
                        + ", " + b + " " + vertexString(positions, b) + ", " + c + " " + vertexString(positions, c)
                        + ") is degenerate: " + why);
        }
        this.positions = positions.clone();
        this.indices = indices.clone();
        this.normals = normals;
        this.bounds = computeBounds();
        this.paddedBounds = bounds.padded();
    }

    /**
     * Whether the triangle of vertices {@code a}, {@code b}, {@code c} of {@code positions} is one
     * the constructor (and {@link Triangle}) would reject: two vertices coincide (within the zero
     * tolerance per coordinate), or it is so thin that twice its area is at most 1e-10 of its
     * longest edge squared, or its normal is below the zero tolerance. Lets a loader or a
     * generator drop or report such triangles first.
     *
     * @param positions x, y, z per vertex, interleaved
     * @param a         the first vertex's index (a vertex, not an array offset)
     * @param b         the second vertex's index
     * @param c         the third vertex's index
     * @return true when the triangle would be rejected
     * @throws ArrayIndexOutOfBoundsException when an index is outside {@code positions}
     */
    static boolean isDegenerate(double[] positions, int a, int b, int c) {
        return degeneracy(positions, a, b, c) != null;
    }

    /** @return why the triangle is degenerate, or null when it is not */
    private static String degeneracy(double[] p, int a, int b, int c) {
        int ia = 3 * a, ib = 3 * b, ic = 3 * c;
        if (coincide(p, ia, ib) || coincide(p, ia, ic) || coincide(p, ib, ic)) return "two vertices coincide";
        double e1x = p[ib] - p[ia], e1y = p[ib + 1] - p[ia + 1], e1z = p[ib + 2] - p[ia + 2];
        double e2x = p[ic] - p[ia], e2y = p[ic + 1] - p[ia + 1], e2z = p[ic + 2] - p[ia + 2];
        double e3x = p[ic] - p[ib], e3y = p[ic + 1] - p[ib + 1], e3z = p[ic + 2] - p[ib + 2];
        double cx = e1y * e2z - e1z * e2y, cy = e1z * e2x - e1x * e2z, cz = e1x * e2y - e1y * e2x;
        double longest2 = Math.max(e1x * e1x + e1y * e1y + e1z * e1z,
                Math.max(e2x * e2x + e2y * e2y + e2z * e2z, e3x * e3x + e3y * e3y + e3z * e3z));
        if (Math.sqrt(cx * cx + cy * cy + cz * cz) <= MIN_AREA_RATIO * longest2) return "its vertices are collinear";
        // A well-shaped but tiny triangle: its normal (twice its area) would be a zero vector.
        if (Util.isZero(cx) && Util.isZero(cy) && Util.isZero(cz))
            return "it is too small: twice its area, " + Math.sqrt(cx * cx + cy * cy + cz * cz)
                    + ", is below the zero tolerance";
        return null;
    }

    /** The tolerant equality of {@link Point#equals}. */
    private static boolean coincide(double[] p, int i, int j) {
        return Util.isZero(p[i] - p[j]) && Util.isZero(p[i + 1] - p[j + 1]) && Util.isZero(p[i + 2] - p[j + 2]);
    }

    private static String vertexString(double[] xyz, int i) {
        return "(" + xyz[3 * i] + "," + xyz[3 * i + 1] + "," + xyz[3 * i + 2] + ")";
    }

    private BoundingBox computeBounds() {
        double minX = Double.POSITIVE_INFINITY, minY = minX, minZ = minX;
        double maxX = Double.NEGATIVE_INFINITY, maxY = maxX, maxZ = maxX;
        // Over the vertices triangles use: an unused vertex must not widen the box.
        for (int v : indices) {
            int o = 3 * v;
            minX = Math.min(minX, positions[o]);
            minY = Math.min(minY, positions[o + 1]);
            minZ = Math.min(minZ, positions[o + 2]);
            maxX = Math.max(maxX, positions[o]);
            maxY = Math.max(maxY, positions[o + 1]);
            maxZ = Math.max(maxZ, positions[o + 2]);
        }
        return new BoundingBox(minX, minY, minZ, maxX, maxY, maxZ);
    }

    /** @return the number of triangles */
    public int triangleCount() {
        return indices.length / 3;
    }

    /** @return the number of vertices (including any that no triangle uses) */
    public int vertexCount() {
        return positions.length / 3;
    }

    /** @return true when the mesh has per-vertex normals (smooth shading) */
    public boolean hasVertexNormals() {
        return normals != null;
    }

    /**
     * @param index the vertex, 0-based
     * @return vertex {@code index}
     * @throws IndexOutOfBoundsException naming the index
     */
    public Point getVertex(int index) {
        int o = 3 * Objects.checkIndex(index, vertexCount());
        return new Point(positions[o], positions[o + 1], positions[o + 2]);
    }

    /**
     * @param index the vertex, 0-based
     * @return the unit normal of vertex {@code index}
     * @throws IllegalStateException     when the mesh has no vertex normals
     * @throws IndexOutOfBoundsException naming the index
     */
    public Vector getVertexNormal(int index) {
        if (normals == null) throw new IllegalStateException("this mesh has no vertex normals (flat shading)");
        int o = 3 * Objects.checkIndex(index, vertexCount());
        return new Vector(normals[o], normals[o + 1], normals[o + 2]);
    }

    /**
     * @param triangle the triangle, 0-based, in the order of the constructor's indices
     * @return a new array with the three vertex indices of triangle {@code triangle}, in winding order
     * @throws IndexOutOfBoundsException naming the index
     */
    public int[] getTriangleIndices(int triangle) {
        int o = 3 * Objects.checkIndex(triangle, triangleCount());
        return new int[] { indices[o], indices[o + 1], indices[o + 2] };
    }

    /** @return the distance to triangle {@code k} along the ray (see {@code Triangle.intersect}), or NaN */
    private double intersect(int k, Hit query) {
        double[] p = positions;
        int a = 3 * indices[3 * k], b = 3 * indices[3 * k + 1], c = 3 * indices[3 * k + 2];
        double ax = p[a], ay = p[a + 1], az = p[a + 2];
        // The same subtractions Triangle makes in its constructor, so the kernel sees the same bits.
        return Triangle.intersect(query, ax, ay, az, p[b] - ax, p[b + 1] - ay, p[b + 2] - az,
                p[c] - ax, p[c + 1] - ay, p[c + 2] - az);
    }

    /**
     * Its triangles; one, the whole mesh, for a subclass that overrides a course hook: the tree
     * then asks it as one leaf, and its queries ask the hook once per ray (a triangle at a time,
     * each of its hits would be visited again for every triangle a shadow ray reaches).
     */
    @Override
    int primitiveCount() {
        return answersInDoubles() ? triangleCount() : 1;
    }

    /**
     * A tree keeps the library's mesh triangles packed in leaf order, as it keeps the library's
     * {@link Triangle}s: a leaf's triangles are then tested from one run of memory, not through
     * this mesh's index array into vertices scattered over its position array (a cache miss per
     * vertex on a big mesh). The packed numbers are the ones {@link #intersect(int, Hit)} feeds
     * the kernel, so a packed triangle gives the same distances, bit for bit
     * ({@code TriangleMeshTest}, the golden meshes). A subclass keeps its own queries.
     */
    @Override
    byte packedKind() {
        return isLibraryShape() ? TRIANGLE : OWN;
    }

    /** The kernel's arguments for triangle {@code prim}: its first vertex and the two edges from it. */
    @Override
    void pack(int prim, double[] out, int at) {
        double[] p = positions;
        int a = 3 * indices[3 * prim], b = 3 * indices[3 * prim + 1], c = 3 * indices[3 * prim + 2];
        double ax = p[a], ay = p[a + 1], az = p[a + 2];
        out[at] = ax;
        out[at + 1] = ay;
        out[at + 2] = az;
        out[at + 3] = p[b] - ax;
        out[at + 4] = p[b + 1] - ay;
        out[at + 5] = p[b + 2] - az;
        out[at + 6] = p[c] - ax;
        out[at + 7] = p[c + 1] - ay;
        out[at + 8] = p[c + 2] - az;
    }

    @Override
    BoundingBox primitiveBounds(int prim) {
        double[] p = positions;
        int a = 3 * indices[3 * prim], b = 3 * indices[3 * prim + 1], c = 3 * indices[3 * prim + 2];
        return new BoundingBox(Math.min(p[a], Math.min(p[b], p[c])), Math.min(p[a + 1], Math.min(p[b + 1], p[c + 1])),
                Math.min(p[a + 2], Math.min(p[b + 2], p[c + 2])), Math.max(p[a], Math.max(p[b], p[c])),
                Math.max(p[a + 1], Math.max(p[b + 1], p[c + 1])), Math.max(p[a + 2], Math.max(p[b + 2], p[c + 2])));
    }

    @Override
    boolean closestHit(int prim, Hit hit) {
        if (!answersInDoubles()) return closestHit(hit); // the whole mesh, one leaf (see primitiveCount)
        double t = intersect(prim, hit);
        if (!inRange(t, hit.t)) return false;
        hit.set(t, this, prim);
        return true;
    }

    @Override
    boolean visitHits(int prim, Hit query, double maxDistance, HitVisitor visitor) {
        if (!answersInDoubles()) return visitHits(query, maxDistance, visitor);
        double t = intersect(prim, query);
        return !within(t, maxDistance) || visitor.visit(this, t);
    }

    /** The early-out of the whole-mesh queries: false when the ray cannot reach the mesh before {@code tMax}. */
    private boolean mayHit(Hit query, double tMax) {
        return paddedBounds.intersects(query.ox, query.oy, query.oz, 1 / query.dx, 1 / query.dy, 1 / query.dz, tMax);
    }

    /**
     * Tests the triangles in index order, as a list of the same {@link Triangle}s would be.
     */
    @Override
    boolean closestHit(Hit hit) {
        if (!answersInDoubles()) return super.closestHit(hit); // a subclass's own hook answers
        if (!mayHit(hit, hit.t)) return false;
        boolean found = false;
        for (int k = 0, n = triangleCount(); k < n; ++k) found |= closestHit(k, hit);
        return found;
    }

    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        if (!answersInDoubles()) return super.visitHits(query, maxDistance, visitor);
        if (!mayHit(query, Double.POSITIVE_INFINITY)) return true;
        for (int k = 0, n = triangleCount(); k < n; ++k)
            if (!visitHits(k, query, maxDistance, visitor)) return false;
        return true;
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        Hit query = Hit.of(ray);
        if (!mayHit(query, Double.POSITIVE_INFINITY)) return null;
        List<GeoPoint> result = null;
        for (int k = 0, n = triangleCount(); k < n; ++k) {
            double t = intersect(k, query);
            if (within(t, maxDistance)) {
                if (result == null) result = new ArrayList<>(2);
                result.add(new GeoPoint(this, ray.getPoint(t)));
            }
        }
        return result;
    }

    @Override
    BoundingBox getBoundingBox() {
        return bounds;
    }

    /** The normal of the recorded triangle at the hit point: interpolated, or the face normal. */
    @Override
    void normalAt(Hit hit) {
        normalOf(hit.primitive, hit.px, hit.py, hit.pz, hit.normal);
    }

    /**
     * The course API without a hit record: the normal of the triangle nearest to {@code point}
     * (the one containing it, for a point on the surface). A linear search over the triangles, so
     * slow on a large mesh; the renderer uses the hit's triangle instead. Where triangles meet, the
     * lowest-numbered one is taken.
     */
    @Override
    public Vector getNormal(Point point) {
        double px = point.getX(), py = point.getY(), pz = point.getZ();
        int best = 0;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (int k = 0, n = triangleCount(); k < n; ++k) {
            double d = distanceSquared(k, px, py, pz);
            if (d < bestDistance) {
                bestDistance = d;
                best = k;
            }
        }
        return normalOf(best, point);
    }

    private Vector normalOf(int k, Point point) {
        double[] n = new double[3];
        normalOf(k, point.getX(), point.getY(), point.getZ(), n);
        return new Vector(n[0], n[1], n[2]);
    }

    /** The normal of triangle k at (x, y, z) into {@code out[0..2]}: the one computation of both forms. */
    private void normalOf(int k, double x, double y, double z, double[] out) {
        if (normals == null) faceNormal(k, out);
        else smoothNormal(k, x, y, z, out);
    }

    /** (v1 − v0) × (v2 − v0), normalized: the arithmetic of {@code Plane.normalOf}, the normal of a {@link Triangle}. */
    private void faceNormal(int k, double[] out) {
        double[] p = positions;
        int a = 3 * indices[3 * k], b = 3 * indices[3 * k + 1], c = 3 * indices[3 * k + 2];
        double v1x = p[b] - p[a], v1y = p[b + 1] - p[a + 1], v1z = p[b + 2] - p[a + 2];
        double v2x = p[c] - p[a], v2y = p[c + 1] - p[a + 1], v2z = p[c + 2] - p[a + 2];
        Kernels.normalize(v1y * v2z - v1z * v2y, v1z * v2x - v1x * v2z, v1x * v2y - v1y * v2x, out);
    }

    /**
     * The vertex normals of triangle k blended with the barycentric coordinates of {@code point}
     * (projected onto the triangle's plane and clamped into the triangle), normalized; the face
     * normal where the blend cancels out.
     */
    private void smoothNormal(int k, double x, double y, double z, double[] out) {
        double[] p = positions;
        int ia = indices[3 * k], ib = indices[3 * k + 1], ic = indices[3 * k + 2];
        int a = 3 * ia, b = 3 * ib, c = 3 * ic;
        double e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
        double e2x = p[c] - p[a], e2y = p[c + 1] - p[a + 1], e2z = p[c + 2] - p[a + 2];
        double wx = x - p[a], wy = y - p[a + 1], wz = z - p[a + 2];
        double d11 = e1x * e1x + e1y * e1y + e1z * e1z, d12 = e1x * e2x + e1y * e2y + e1z * e2z;
        double d22 = e2x * e2x + e2y * e2y + e2z * e2z;
        double dw1 = wx * e1x + wy * e1y + wz * e1z, dw2 = wx * e2x + wy * e2y + wz * e2z;
        double den = d11 * d22 - d12 * d12; // > 0: the triangle is not degenerate
        double u = Math.max(0, (d22 * dw1 - d12 * dw2) / den); // weight of vertex b
        double v = Math.max(0, (d11 * dw2 - d12 * dw1) / den); // weight of vertex c
        if (u + v > 1) {
            double s = u + v;
            u /= s;
            v /= s;
        }
        double w = 1 - u - v;
        double[] n = normals;
        double nx = w * n[a] + u * n[b] + v * n[c];
        double ny = w * n[a + 1] + u * n[b + 1] + v * n[c + 1];
        double nz = w * n[a + 2] + u * n[b + 2] + v * n[c + 2];
        if (Util.isZero(nx) && Util.isZero(ny) && Util.isZero(nz)) faceNormal(k, out);
        else Kernels.normalize(nx, ny, nz, out);
    }

    /** The squared distance from (px, py, pz) to triangle k (Ericson, Real-Time Collision Detection, 5.1.5). */
    private double distanceSquared(int k, double px, double py, double pz) {
        double[] p = positions;
        int a = 3 * indices[3 * k], b = 3 * indices[3 * k + 1], c = 3 * indices[3 * k + 2];
        double ax = p[a], ay = p[a + 1], az = p[a + 2];
        double abx = p[b] - ax, aby = p[b + 1] - ay, abz = p[b + 2] - az;
        double acx = p[c] - ax, acy = p[c + 1] - ay, acz = p[c + 2] - az;
        double apx = px - ax, apy = py - ay, apz = pz - az;
        double d1 = abx * apx + aby * apy + abz * apz, d2 = acx * apx + acy * apy + acz * apz;
        // The closest point is a + s·ab + r·ac; find (s, r) by the Voronoi region of the point.
        double s, r;
        double d3 = abx * (px - p[b]) + aby * (py - p[b + 1]) + abz * (pz - p[b + 2]);
        double d4 = acx * (px - p[b]) + acy * (py - p[b + 1]) + acz * (pz - p[b + 2]);
        double d5 = abx * (px - p[c]) + aby * (py - p[c + 1]) + abz * (pz - p[c + 2]);
        double d6 = acx * (px - p[c]) + acy * (py - p[c + 1]) + acz * (pz - p[c + 2]);
        double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
        if (d1 <= 0 && d2 <= 0) { // vertex a
            s = 0;
            r = 0;
        } else if (d3 >= 0 && d4 <= d3) { // vertex b
            s = 1;
            r = 0;
        } else if (vc <= 0 && d1 >= 0 && d3 <= 0) { // edge ab
            s = d1 / (d1 - d3);
            r = 0;
        } else if (d6 >= 0 && d5 <= d6) { // vertex c
            s = 0;
            r = 1;
        } else if (vb <= 0 && d2 >= 0 && d6 <= 0) { // edge ac
            s = 0;
            r = d2 / (d2 - d6);
        } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) { // edge bc
            r = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            s = 1 - r;
        } else { // inside
            double inv = 1 / (va + vb + vc);
            s = vb * inv;
            r = vc * inv;
        }
        double dx = apx - s * abx - r * acx, dy = apy - s * aby - r * acy, dz = apz - s * abz - r * acz;
        return dx * dx + dy * dy + dz * dz;
    }

    @Override
    public String toString() {
        return "TriangleMesh{" + triangleCount() + " triangles, " + vertexCount() + " vertices"
                + (normals == null ? "" : ", smooth") + "}";
    }
}
