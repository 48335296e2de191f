package geometries;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.SplittableRandom;

import com.sun.management.HotSpotDiagnosticMXBean;

import primitives.Point;

/**
 * Finds out when this JVM's vector walk runs compiled, and then sets
 * {@link Vectorization#COMPILED}: a daemon thread, started by the first long render
 * ({@link Bvh#expectLongWalk}), loads the vector walk and walks a small tree of its own with both
 * walks, the same rays in turn, until the vector walk's rounds take at most
 * {@link #COMPILED_RATIO} times the scalar walk's, {@link #STREAK} rounds running. A long render's
 * tree then gets its wide part at its next tile, and the render's threads the vector walk.
 *
 * <p>Why a thread and a tree of its own: the vector code becomes fast only when the optimizing
 * compiler has compiled it, after some 10<sup>5</sup> rays run interpreted or in the quick tier,
 * where its vectors are objects (tens of microseconds a ray). On a small tree those rays cost a
 * few hundred milliseconds of one core; on a render's tree, in the render's threads, they cost
 * about a second of a short render (BENCHMARKS.md, "The vector walk in a fresh JVM"). Meanwhile
 * the render walks its tree in scalar code, at its usual speed; the code compiled on the small
 * tree runs the large one as fast as a warm JVM does. A walk still many times slower than the
 * scalar one is still interpreted; a compiled one is within a small factor of it, faster on large
 * trees (the ratio only tells the two states apart, {@link Vectorization#MIN_PRIMITIVES} decides
 * which trees take the wide walk). A JVM that never compiles it (the quick tier only,
 * {@code -XX:TieredStopAtLevel=1}, or {@code -Xint}) is not warmed and keeps the scalar walk; nor
 * is a JVM so busy that the vector walk is not compiled within {@link #GIVE_UP_CPU_NANOS} of the
 * thread's processor time. The images do not depend on any of this, only the time: both walks
 * return the same hits.
 */
final class VectorWarmUp implements Runnable {
    /** A compiled vector walk takes at most this many times the scalar walk's time on the warm-up tree. */
    static final double COMPILED_RATIO = 1.5;
    /** Rounds in a row that must be that fast: one round is a few milliseconds, a scheduler's hiccup can flatter one. */
    static final int STREAK = 3;
    /**
     * The warm-up stops, the vector walk never taken, when it is not compiled after this much of
     * its thread's processor time (ns): about six times what it takes on a quiet machine.
     */
    static final long GIVE_UP_CPU_NANOS = 3_000_000_000L;
    /** Closest-hit rays, and as many any-hit queries, per walk and round. */
    private static final int RAYS_PER_ROUND = 64;

    private VectorWarmUp() {
    }

    /** Starts the warm-up of this JVM's vector walk, once per JVM (later calls return at once). */
    static void start() {
        Once.touch();
    }

    /** The lazy holder: the JVM initialises it once, on the first {@link #start}, whichever thread asks. */
    private static final class Once {
        static {
            Thread thread = new Thread(new VectorWarmUp(), "raytracer vector walk warm-up");
            thread.setDaemon(true);
            thread.start();
        }

        static void touch() {
            // initialising the class is the work
        }
    }

    @Override
    public void run() {
        if (!optimizingCompiler()) return;
        WideWalk walk = Vectorization.walk(); // the vector classes load here, on this thread
        if (walk == null) return;
        Geometries shapes = shapes(walk.minPrimitives());
        Bvh wide = Bvh.build(shapes, 1, Integer.MAX_VALUE, true, walk);
        Bvh scalar = Bvh.build(shapes, 1, Integer.MAX_VALUE, true, null);
        if (wide.wideNodes() == null) return; // cannot happen: the tree is made large enough
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        long start = threads.getCurrentThreadCpuTime();
        Hit hit = new Hit();
        int streak = 0;
        for (long round = 0; threads.getCurrentThreadCpuTime() - start < GIVE_UP_CPU_NANOS; ++round) {
            long t0 = System.nanoTime();
            round(wide, hit, round);
            long t1 = System.nanoTime();
            round(scalar, hit, round);
            long t2 = System.nanoTime();
            streak = t1 - t0 <= COMPILED_RATIO * (t2 - t1) ? streak + 1 : 0;
            if (streak == STREAK) {
                Vectorization.COMPILED.set(true);
                return;
            }
        }
    }

    /**
     * @return whether this JVM compiles with C2, the compiler that makes vector code fast: not
     *         when it stops at the quick tier ({@code TieredStopAtLevel} below 4) or has no compiler
     *         ({@code -Xint}). Asked of the JVM's own options, read only by a long render.
     */
    static boolean optimizingCompiler() {
        HotSpotDiagnosticMXBean hotspot = ManagementFactory.getPlatformMXBean(HotSpotDiagnosticMXBean.class);
        if (hotspot == null) return true; // not HotSpot: let the warm-up's measure decide
        return Integer.parseInt(hotspot.getVMOption("TieredStopAtLevel").getValue()) >= 4
                && !"false".equals(hotspot.getVMOption("UseCompiler").getValue());
    }

    /** Round {@code round}'s rays through {@code tree}: the same for both trees, from the round's own seed. */
    private static void round(Bvh tree, Hit hit, long round) {
        SplittableRandom random = new SplittableRandom(round);
        int[] visits = new int[1];
        // As a shadow ray's walk: stops at its third hit (most rays have fewer, so most walks go on).
        HitVisitor count = (geometry, t) -> ++visits[0] < 3;
        for (int i = 0; i < RAYS_PER_ROUND; ++i) {
            ray(hit, random);
            tree.closestHit(hit.reset(Double.POSITIVE_INFINITY));
            ray(hit, random);
            visits[0] = 0;
            tree.visitHits(hit, 2 + random.nextDouble(), count);
        }
    }

    /** A ray from a point around the shapes towards a point near their centre: most hit, some miss. */
    private static void ray(Hit hit, SplittableRandom random) {
        double a = random.nextDouble(2 * Math.PI), b = random.nextDouble(-1, 1), c = Math.sqrt(1 - b * b);
        double ox = 3 * c * Math.cos(a), oy = 3 * b, oz = 3 * c * Math.sin(a);
        double tx = random.nextDouble(-1.2, 1.2), ty = random.nextDouble(-1.2, 1.2), tz = random.nextDouble(-1.2, 1.2);
        hit.setRay(ox, oy, oz, tx - ox, ty - oy, tz - oz);
    }

    /**
     * A bumpy unit sphere of at least {@code triangles} triangles (leaves of one to four, as a
     * mesh's are) and a few small spheres on it (leaves of spheres, and of both): every path of
     * the walks, so that the compiled code has seen each one before a render's tree runs it.
     */
    static Geometries shapes(int triangles) {
        int n = 8;
        while (4 * n * (n - 1) < triangles) n += 4;
        double[] positions = new double[(n + 1) * 2 * n * 3];
        int v = 0;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j < 2 * n; ++j) {
                double theta = Math.PI * i / n, phi = Math.PI * j / n;
                double r = 1 + 0.1 * Math.sin(5 * theta) * Math.cos(7 * phi);
                positions[v++] = r * Math.sin(theta) * Math.cos(phi);
                positions[v++] = r * Math.cos(theta);
                positions[v++] = r * Math.sin(theta) * Math.sin(phi);
            }
        // Two triangles per grid cell, one at each pole (the other would have two equal vertices).
        int[] indices = new int[4 * n * (n - 1) * 3];
        int k = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < 2 * n; ++j) {
                int a = i * 2 * n + j, b = i * 2 * n + (j + 1) % (2 * n), c = a + 2 * n, d = b + 2 * n;
                if (i > 0) k = triangle(indices, k, a, c, b);
                if (i < n - 1) k = triangle(indices, k, b, c, d);
            }
        Geometries shapes = new Geometries(new TriangleMesh(positions, indices));
        for (int s = 0; s < 24; ++s) {
            double a = s * 2.399963, y = 1 - (s + 0.5) / 12; // a golden-angle spiral
            double c = Math.sqrt(1 - y * y);
            shapes.add(new Sphere(new Point(1.05 * c * Math.cos(a), 1.05 * y, 1.05 * c * Math.sin(a)), 0.08));
        }
        return shapes;
    }

    private static int triangle(int[] indices, int k, int a, int b, int c) {
        indices[k] = a;
        indices[k + 1] = b;
        indices[k + 2] = c;
        return k + 3;
    }
}
