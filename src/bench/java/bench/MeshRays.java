package bench;

import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;

import geometries.Bvh;
import geometries.Geometries;
import geometries.Hit;
import geometries.LeanQueries;
import geometries.TriangleMesh;

/**
 * The library's half of {@code scripts/embree_benchmark.py}: the same triangles and the same rays
 * as Embree gets, each ray one closest-hit query through the library's BVH on a reused
 * {@link Hit} (no shading, no ray objects), timed over whole passes. The script writes the mesh
 * and the rays, runs this once per mesh and thread count, and compares the distances with
 * Embree's.
 *
 * <p>Files are little-endian: a mesh is {@code int32 vertices, int32 triangles, float64 xyz per
 * vertex, int32 three indices per triangle}; rays are {@code int32 count, float64 origin and
 * direction per ray}. The output is one {@code float64} distance per ray (NaN for a miss) and one
 * JSON line on standard output.
 *
 * <pre>java -cp CLASSES bench.MeshRays MESH RAYS THREADS PASSES OUT</pre>
 */
public final class MeshRays {
    /** Rays a worker claims at a time: whole image rows of a 512-wide view, in order. */
    private static final int CHUNK = 2048;
    /** Untimed passes first, so that the timed ones run compiled code. */
    private static final int WARM_UP = 5;

    private MeshRays() {
    }

    /**
     * @param args the mesh file, the rays file, the thread count, the timed passes and the output file
     * @throws IOException when a file cannot be read or written
     * @throws InterruptedException when interrupted while the workers run
     */
    public static void main(String[] args) throws IOException, InterruptedException {
        if (args.length != 5)
            throw new IllegalArgumentException("usage: MeshRays MESH RAYS THREADS PASSES OUT, got " + Arrays.toString(args));
        TriangleMesh triangleMesh = readMesh(Path.of(args[0]));
        int triangles = triangleMesh.triangleCount();
        double[] rays = readRays(Path.of(args[1]));
        int count = rays.length / 6;
        int threads = Integer.parseInt(args[2]), passes = Integer.parseInt(args[3]);

        Geometries scene = new Geometries(triangleMesh);
        double[] builds = new double[3];
        Bvh bvh = null;
        for (int i = 0; i < builds.length; ++i) {
            long start = System.nanoTime();
            bvh = Bvh.build(scene, threads);
            builds[i] = (System.nanoTime() - start) / 1e9;
        }
        double[] t = new double[count];
        List<Double> times = new ArrayList<>();
        // On one thread the trace runs on this one: its CPU time too, which a busy machine's
        // other processes disturb less than the wall time (they take the core, not the time).
        java.lang.management.ThreadMXBean cpu = java.lang.management.ManagementFactory.getThreadMXBean();
        List<Double> cpuTimes = new ArrayList<>();
        for (int pass = 0; pass < WARM_UP + passes; ++pass) {
            long start = System.nanoTime(), cpuStart = cpu.getCurrentThreadCpuTime();
            trace(bvh, rays, t, threads);
            if (pass >= WARM_UP) {
                times.add((System.nanoTime() - start) / 1e9);
                cpuTimes.add((cpu.getCurrentThreadCpuTime() - cpuStart) / 1e9);
            }
        }
        try (OutputStream file = Files.newOutputStream(Path.of(args[4]));
             DataOutputStream out = new DataOutputStream(new java.io.BufferedOutputStream(file))) {
            for (double d : t) out.writeLong(Long.reverseBytes(Double.doubleToRawLongBits(d)));
        }
        long hits = Arrays.stream(t).filter(d -> !Double.isNaN(d)).count();
        times.sort(null);
        cpuTimes.sort(null);
        Arrays.sort(builds);
        // median_trace_cpu_s: the tracing thread's CPU time, meaningful on one thread only.
        System.out.println(String.format(Locale.ROOT,
                "{\"triangles\": %d, \"rays\": %d, \"hits\": %d, \"threads\": %d, \"build_s\": %.4f, \"trace_s\": %s, \"median_trace_s\": %.5f, \"median_trace_cpu_s\": %.5f}",
                triangles, count, hits, threads, builds[builds.length / 2], times, times.get(times.size() / 2),
                cpuTimes.get(cpuTimes.size() / 2)));
    }

    /**
     * @param file a mesh file as the script writes it (see the class comment)
     * @return the mesh
     * @throws IOException when it cannot be read
     */
    public static TriangleMesh readMesh(Path file) throws IOException {
        ByteBuffer mesh = read(file);
        int vertices = mesh.getInt(), triangles = mesh.getInt();
        double[] positions = new double[3 * vertices];
        mesh.asDoubleBuffer().get(positions);
        mesh.position(8 + 8 * positions.length);
        int[] indices = new int[3 * triangles];
        mesh.asIntBuffer().get(indices);
        return new TriangleMesh(positions, indices);
    }

    /**
     * @param file a rays file as the script writes it (see the class comment)
     * @return origin and direction of each ray, six doubles a ray
     * @throws IOException when it cannot be read
     */
    public static double[] readRays(Path file) throws IOException {
        ByteBuffer rayFile = read(file);
        double[] rays = new double[6 * rayFile.getInt()];
        rayFile.asDoubleBuffer().get(rays);
        return rays;
    }

    private static ByteBuffer read(Path file) throws IOException {
        return ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
    }

    /** A query record whose ray this benchmark sets (the setters are Hit's protected ones, as the renderer's). */
    private static final class RayRecord extends Hit {
        /** Sets the ray to the six doubles of {@code rays} at {@code r}: origin, then direction. */
        void set(double[] rays, int r) {
            setRay(rays[r], rays[r + 1], rays[r + 2], rays[r + 3], rays[r + 4], rays[r + 5]);
        }
    }

    /** One pass over every ray on {@code threads} workers, chunks claimed in order. */
    private static void trace(Bvh bvh, double[] rays, double[] t, int threads) throws InterruptedException {
        AtomicInteger next = new AtomicInteger();
        Runnable worker = () -> {
            RayRecord hit = new RayRecord();
            for (int from; (from = next.getAndAdd(CHUNK)) < t.length;) {
                int to = Math.min(t.length, from + CHUNK);
                for (int i = from; i < to; ++i) {
                    int r = 6 * i;
                    hit.set(rays, r);
                    t[i] = LeanQueries.closestHit(bvh, hit.reset(Double.POSITIVE_INFINITY)) ? hit.getT() : Double.NaN;
                }
            }
        };
        if (threads == 1) {
            worker.run();
            return;
        }
        Thread[] workers = new Thread[threads];
        for (int i = 0; i < threads; ++i) (workers[i] = new Thread(worker)).start();
        for (Thread w : workers) w.join();
    }
}
