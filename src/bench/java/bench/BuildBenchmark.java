package bench;

import java.io.PrintStream;
import java.util.Locale;

import geometries.Bvh;
import geometries.Geometries;
import geometries.TriangleMesh;
import scene.samples.ScalingScene;

/**
 * The {@code build} group: the BVH build alone, on 1 and on 2 threads (the tree is the same),
 * for the scaling scene's 2×10⁶ primitives and for a mesh of about 10⁶ triangles. Each scene is
 * built once to warm the JIT up, then {@code --runs} times on 1 and 2 threads in turn; the table
 * gives the medians, their ratio, and the bytes the build allocates per primitive (measured on
 * the calling thread during a 1-thread build: every array of the build and the tree, an upper
 * bound of the memory the build needs on top of the scene) and what the finished tree keeps.
 */
final class BuildBenchmark {
    private BuildBenchmark() {
    }

    /** @return the group's Markdown section */
    static String markdown(Options o, PrintStream log) {
        int n = o.quick() ? 10_000 : 1_000_000;
        int side = o.quick() ? 70 : 708; // 2·side² triangles: 1,002,528 for 708
        int runs = o.quick() ? 1 : o.runs();
        StringBuilder s = new StringBuilder("### build\n\n");
        s.append("| scene | primitives | runs | 1 thread s (median) | 2 threads s (median) | 1 thread / 2 threads "
                + "| build alloc B/primitive | tree B/primitive | nodes | depth |\n");
        s.append("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
        row(s, log, "scaling (" + Configurations.power(n) + " spheres + " + Configurations.power(n) + " triangles)",
                ScalingScene.create(n).geometries, runs);
        row(s, log, "grid mesh " + side + "×" + side + " quads", new Geometries(gridMesh(side)), runs);
        return s.append('\n').toString();
    }

    private static void row(StringBuilder s, PrintStream log, String label, Geometries g, int runs) {
        System.gc();
        long a0 = HeapMeter.threadAllocatedBytes();
        Bvh tree = Bvh.build(g, 1); // the warm-up, measured for its allocation
        long allocated = HeapMeter.threadAllocatedBytes() - a0;
        double[] one = new double[runs], two = new double[runs];
        for (int r = 0; r < runs; ++r) {
            one[r] = time(g, 1);
            two[r] = time(g, 2);
            log.printf(Locale.ROOT, "  build %s run %d: 1 thread %.3f s, 2 threads %.3f s%n", label, r + 1, one[r], two[r]);
        }
        int prims = tree.primitiveTotal();
        double m1 = RenderBenchmark.median(one), m2 = RenderBenchmark.median(two);
        double kept = tree.indexBytes() / (double) prims;
        s.append(String.format(Locale.ROOT, "| %s | %,d | %d | %.3f | %.3f | %.2f | %.0f | %.0f | %,d | %d |%n", label, prims, runs,
                m1, m2, m1 / m2, allocated / (double) prims, kept, tree.nodeCount(), tree.depth()));
    }

    private static double time(Geometries g, int threads) {
        // From a collected heap, as the render timings (RenderBenchmark): the previous build's
        // garbage would otherwise start a concurrent G1 cycle that competes with this build.
        System.gc();
        long t0 = System.nanoTime();
        Bvh.build(g, threads);
        return (System.nanoTime() - t0) / 1e9;
    }

    /** A wavy height field of side × side quads, two triangles each, as one mesh. */
    static TriangleMesh gridMesh(int side) {
        double[] pos = new double[(side + 1) * (side + 1) * 3];
        int k = 0;
        for (int i = 0; i <= side; ++i)
            for (int j = 0; j <= side; ++j) {
                pos[k++] = j;
                pos[k++] = Math.sin(i * 0.05) * Math.cos(j * 0.07) * 20;
                pos[k++] = i;
            }
        int[] idx = new int[side * side * 6];
        k = 0;
        for (int i = 0; i < side; ++i)
            for (int j = 0; j < side; ++j) {
                int a = i * (side + 1) + j, b = a + 1, c = a + side + 1, d = c + 1;
                idx[k++] = a;
                idx[k++] = b;
                idx[k++] = c;
                idx[k++] = b;
                idx[k++] = d;
                idx[k++] = c;
            }
        return new TriangleMesh(pos, idx);
    }
}
