package geometries;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

import bench.MeshRays;

/**
 * The work behind {@code bench.MeshRays}'s times: per ray, the node boxes and triangles that
 * {@link Bvh#closestHit(Hit)} tests, counted by the walk itself ({@link Bvh#COUNTING}, a constant
 * the compilers drop in every other JVM), and the tree's shape (leaves, primitives per leaf,
 * depth, the surface-area cost). The scalar walk of the binary tree, the one every JVM has.
 *
 * <pre>java -Draytracer.walkCounts=true -cp target/bench/classes:target/classes geometries.WalkCounts MESH RAYS</pre>
 * with the files {@code scripts/embree_benchmark.py} writes (see {@code bench.MeshRays}).
 */
public final class WalkCounts {
    private WalkCounts() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2) throw new IllegalArgumentException("usage: WalkCounts MESH RAYS");
        if (!Bvh.COUNTING)
            throw new IllegalStateException("the walk counts its tests only in a JVM run with -Draytracer.walkCounts=true");
        TriangleMesh mesh = MeshRays.readMesh(Path.of(args[0]));
        double[] rays = MeshRays.readRays(Path.of(args[1]));
        int count = rays.length / 6, triangles = mesh.triangleCount();

        Bvh bvh = Bvh.build(new Geometries(mesh), 1, 4096, true, null);
        float[] node = bvh.nodes();
        int nodeCount = bvh.nodeCount();
        long hits = 0;
        Hit hit = new Hit();
        for (int i = 0; i < count; ++i) {
            int r = 6 * i;
            hit.setRay(rays[r], rays[r + 1], rays[r + 2], rays[r + 3], rays[r + 4], rays[r + 5]);
            if (bvh.closestHit(hit.reset(Double.POSITIVE_INFINITY))) hits++;
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
                triangles, count, hits, nodeCount, leaves, leafPrims / (double) leaves, bvh.depth(), sah,
                hit.boxTests / (double) count, hit.primitiveTests / (double) count));
    }

    private static double area(float[] nd, int n) {
        int at = BvhNodes.at(n);
        double dx = BvhNodes.max(nd, at, BvhNodes.X) - BvhNodes.min(nd, at, BvhNodes.X);
        double dy = BvhNodes.max(nd, at, BvhNodes.Y) - BvhNodes.min(nd, at, BvhNodes.Y);
        double dz = BvhNodes.max(nd, at, BvhNodes.Z) - BvhNodes.min(nd, at, BvhNodes.Z);
        return dx * dy + dy * dz + dz * dx;
    }
}
