package geometries;

import java.io.IOException;
import java.lang.reflect.Field;
import java.nio.file.Path;
import java.util.Locale;

import bench.MeshRays;

/**
 * The work behind {@code bench.MeshRays}'s times: per ray, the node boxes and triangles that
 * {@link Bvh#closestHit(Hit)} tests, counted by a copy of its walk (the same order, the same
 * skips; checked against the walk's own answer on every ray) over the tree's own arrays, and the
 * tree's shape (leaves, primitives per leaf, depth, the surface-area cost). Lives in the bench
 * profile, in the package whose arrays it reads: the library has no counters on its hot path, so
 * the walk is copied here rather than instrumented there.
 *
 * <pre>java -cp target/bench/classes:target/classes geometries.WalkCounts MESH RAYS</pre>
 * with the files {@code scripts/embree_benchmark.py} writes (see {@code bench.MeshRays}).
 */
public final class WalkCounts {
    private WalkCounts() {
    }

    public static void main(String[] args) throws IOException, ReflectiveOperationException {
        if (args.length != 2) throw new IllegalArgumentException("usage: WalkCounts MESH RAYS");
        TriangleMesh mesh = MeshRays.readMesh(Path.of(args[0]));
        double[] rays = MeshRays.readRays(Path.of(args[1]));
        int count = rays.length / 6, triangles = mesh.triangleCount();

        // The scalar walk's tree, whatever this JVM reads: with wide nodes, the leaves' packed
        // numbers are laid out in lanes (TriangleLanes), which the scalar copy below does not read.
        Bvh bvh = Bvh.build(new Geometries(mesh), 1, 4096, true, null);
        float[] node = field(bvh, "node");
        double[] packed = field(bvh, "packed");
        int nodeCount = bvh.nodeCount();
        long[] totals = new long[3]; // boxes, triangles, hits
        Hit hit = new Hit();
        int[] stack = new int[bvh.depth() + 1];
        double[] stackT = new double[bvh.depth() + 1];
        for (int i = 0; i < count; ++i) {
            int r = 6 * i;
            hit.setRay(rays[r], rays[r + 1], rays[r + 2], rays[r + 3], rays[r + 4], rays[r + 5]);
            hit.reset(Double.POSITIVE_INFINITY);
            boolean found = walk(node, packed, hit, stack, stackT, totals);
            if (found) totals[2]++;
            // The copy must be the walk it counts for: the same answer on every ray, to the bit.
            double t = hit.t;
            hit.reset(Double.POSITIVE_INFINITY);
            if (bvh.closestHit(hit) != found || Double.compare(hit.t, t) != 0)
                throw new IllegalStateException("the counted walk and Bvh.closestHit disagree on ray " + i + ": "
                        + t + " against " + hit.t);
        }
        // The tree's shape: leaves, their sizes, and the SAH cost (1 per box pair, 1 per triangle).
        long leaves = 0, leafPrims = 0;
        double rootArea = area(node, 0), sah = 0;
        for (int n = 0; n < nodeCount; ++n) {
            int at = BvhNodes.at(n);
            int c = BvhNodes.count(node, at);
            if (c > 0) {
                leaves++;
                leafPrims += c;
                sah += area(node, n) / rootArea * c;
            } else {
                sah += area(node, n) / rootArea;
            }
        }
        System.out.println(String.format(Locale.ROOT,
                "{\"triangles\": %d, \"rays\": %d, \"hits\": %d, \"nodes\": %d, \"leaves\": %d, \"per_leaf\": %.2f, "
                        + "\"depth\": %d, \"sah_cost\": %.2f, \"boxes_per_ray\": %.2f, \"triangles_per_ray\": %.2f}",
                triangles, count, totals[2], nodeCount, leaves, leafPrims / (double) leaves, bvh.depth(), sah,
                totals[0] / (double) count, totals[1] / (double) count));
    }

    /** {@link Bvh#closestHit(Hit)}'s walk for a tree of packed triangles only, counting its tests. */
    private static boolean walk(float[] nd, double[] packed, Hit hit, int[] stack, double[] stackT, long[] totals) {
        double ox = hit.ox, oy = hit.oy, oz = hit.oz;
        double ix = BoundingBox.inverse(hit.dx), iy = BoundingBox.inverse(hit.dy), iz = BoundingBox.inverse(hit.dz);
        totals[0]++;
        if (!(entry(nd, 0, ox, oy, oz, ix, iy, iz, hit.t) < hit.t)) return false;
        boolean found = false;
        int top = 0, n = 0;
        while (true) {
            int rec = BvhNodes.at(n);
            int count = BvhNodes.count(nd, rec);
            if (count > 0) {
                for (int k = BvhNodes.first(nd, rec), end = k + count; k < end; ++k) {
                    totals[1]++;
                    double t = Triangle.intersect(hit, packed, k * BvhLeaf.PACKED);
                    if (Intersectable.inRange(t, hit.t)) {
                        hit.t = t;
                        found = true;
                    }
                }
            } else {
                int left = n + 1, right = BvhNodes.right(nd, rec);
                double tMax = hit.t;
                totals[0] += 2;
                double tl = entry(nd, left, ox, oy, oz, ix, iy, iz, tMax);
                double tr = entry(nd, right, ox, oy, oz, ix, iy, iz, tMax);
                if (tl < tMax || tr < tMax) {
                    boolean leftFirst = tl <= tr;
                    int far = leftFirst ? right : left;
                    double tf = leftFirst ? tr : tl;
                    n = leftFirst ? left : right;
                    stack[top] = far;
                    stackT[top] = tf;
                    top += tf < tMax ? 1 : 0;
                    continue;
                }
            }
            do {
                if (top == 0) return found;
                --top;
            } while (!(stackT[top] < hit.t));
            n = stack[top];
        }
    }

    /** {@code Bvh.entry}'s slab test of node {@code n}, through the same kernel. */
    private static double entry(float[] nd, int n, double ox, double oy, double oz, double ix, double iy, double iz,
                                double tMax) {
        int at = BvhNodes.at(n);
        return BoundingBox.entry(BvhNodes.min(nd, at, BvhNodes.X), BvhNodes.min(nd, at, BvhNodes.Y),
                BvhNodes.min(nd, at, BvhNodes.Z), BvhNodes.max(nd, at, BvhNodes.X), BvhNodes.max(nd, at, BvhNodes.Y),
                BvhNodes.max(nd, at, BvhNodes.Z), ox, oy, oz, ix, iy, iz, tMax);
    }

    private static double area(float[] nd, int n) {
        int at = BvhNodes.at(n);
        double dx = BvhNodes.max(nd, at, BvhNodes.X) - BvhNodes.min(nd, at, BvhNodes.X);
        double dy = BvhNodes.max(nd, at, BvhNodes.Y) - BvhNodes.min(nd, at, BvhNodes.Y);
        double dz = BvhNodes.max(nd, at, BvhNodes.Z) - BvhNodes.min(nd, at, BvhNodes.Z);
        return dx * dy + dy * dz + dz * dx;
    }

    @SuppressWarnings("unchecked")
    private static <T> T field(Bvh bvh, String name) throws ReflectiveOperationException {
        Field f = Bvh.class.getDeclaredField(name);
        f.setAccessible(true);
        return (T) f.get(bvh);
    }
}
