package geometries;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.io.ObjReader;

/**
 * The meshes and rays of {@code scripts/embree_benchmark.py}, made here the same way (to within
 * the rounding of NumPy's against Java's sines, which no test depends on): the course teapot and
 * displaced UV spheres, whose fans at the poles give long thin triangles and whose bumps give
 * triangles of every size and slant; and the benchmark's pinhole view, which the mesh fills.
 */
final class BenchmarkMeshes {
    private BenchmarkMeshes() {
    }

    /** @return the course teapot, 992 triangles (the resource scenes/teapot.obj is a copy of) */
    static TriangleMesh teapot() {
        try {
            return ObjReader.readResource("/models/teapot.obj");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * A UV sphere of radius about 1 whose radius follows a few sines: a fan at each pole, two
     * triangles per quad between; 2 · segments · (rings − 1) triangles (70 × 72: 9,936).
     */
    static TriangleMesh displacedSphere(int rings, int segments) {
        int inner = rings - 1; // rings of vertices between the poles
        double[] pos = new double[3 * (inner * segments + 2)];
        pos[2] = 1; // the north pole, vertex 0
        for (int i = 0; i < inner; ++i) {
            double th = Math.PI * (i + 1) / rings;
            for (int j = 0; j < segments; ++j) {
                double ph = 2 * Math.PI * j / segments;
                double r = 1 + 0.12 * Math.sin(5 * th) * Math.cos(7 * ph) + 0.05 * Math.sin(13 * ph + 3 * th)
                        + 0.03 * Math.cos(29 * th);
                int o = 3 * (1 + i * segments + j);
                pos[o] = r * Math.sin(th) * Math.cos(ph);
                pos[o + 1] = r * Math.sin(th) * Math.sin(ph);
                pos[o + 2] = r * Math.cos(th);
            }
        }
        int south = inner * segments + 1;
        pos[3 * south + 2] = -1;
        int[] idx = new int[3 * 2 * segments * inner];
        int q = 0;
        for (int j = 0; j < segments; ++j) {
            idx[q++] = 0;
            idx[q++] = at(0, j, segments);
            idx[q++] = at(0, j + 1, segments);
        }
        for (int i = 0; i < inner - 1; ++i)
            for (int j = 0; j < segments; ++j) {
                int a = at(i, j, segments), b = at(i, j + 1, segments), c = at(i + 1, j, segments), d = at(i + 1, j + 1, segments);
                idx[q++] = a;
                idx[q++] = c;
                idx[q++] = b;
                idx[q++] = b;
                idx[q++] = c;
                idx[q++] = d;
            }
        for (int j = 0; j < segments; ++j) {
            idx[q++] = south;
            idx[q++] = at(inner - 1, j + 1, segments);
            idx[q++] = at(inner - 1, j, segments);
        }
        return new TriangleMesh(pos, idx);
    }

    private static int at(int ring, int segment, int segments) {
        return 1 + ring * segments + segment % segments;
    }

    /**
     * The benchmark's view of {@code mesh} at {@code side} × {@code side} pixels, a ray through
     * each pixel's centre: from a corner, 2.2 bounding radii from the centre, the mesh filling
     * the image.
     */
    static List<Ray> pinholeRays(TriangleMesh mesh, int side) {
        BoundingBox box = mesh.getBoundingBox();
        double cx = (box.minX + box.maxX) / 2, cy = (box.minY + box.maxY) / 2, cz = (box.minZ + box.maxZ) / 2;
        double radius = Math.sqrt(sq(box.maxX - box.minX) + sq(box.maxY - box.minY) + sq(box.maxZ - box.minZ)) / 2;
        Vector to = new Vector(-0.45, -0.35, -0.82).normalize();
        Point eye = new Point(cx, cy, cz).add(to.scale(-radius * 2.2));
        Vector right = to.crossProduct(new Vector(0, 0, 1)).normalize();
        Vector up = right.crossProduct(to);
        double half = 0.62 * radius, depth = radius * 2.2;
        List<Ray> rays = new ArrayList<>(side * side);
        for (int row = 0; row < side; ++row)
            for (int col = 0; col < side; ++col) {
                double x = ((col + 0.5) / side * 2 - 1) * half, y = (1 - (row + 0.5) / side * 2) * half;
                Vector d = to.scale(depth);
                if (x != 0) d = d.add(right.scale(x));
                if (y != 0) d = d.add(up.scale(y));
                rays.add(new Ray(eye, d));
            }
        return rays;
    }

    /** @return the mesh's largest extent along an axis, in its units */
    static double size(TriangleMesh mesh) {
        BoundingBox box = mesh.getBoundingBox();
        return Math.max(box.maxX - box.minX, Math.max(box.maxY - box.minY, box.maxZ - box.minZ));
    }

    private static double sq(double x) {
        return x * x;
    }
}
