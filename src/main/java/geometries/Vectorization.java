package geometries;

import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Which walk the trees of this JVM take (Apache Lucene's {@code VectorizationProvider} pattern):
 * the {@code VectorWalk} of wide nodes where the incubating Vector API is readable
 * ({@code --add-modules jdk.incubator.vector}) and the CPU's vectors hold four doubles (AVX2 and
 * later); the scalar walk of binary nodes otherwise. A render's tree takes the vector walk by
 * itself only in a long render: from the first ray of a render of {@link #FIRST_RAY_CAMERA_RAYS}
 * camera rays or more ({@link Bvh#expectCameraRays}), or once a render has seconds of work left
 * and the walk runs compiled ({@link #COMPILED}, {@link Bvh#expectLongWalk}). A short render never
 * loads a vector class. (Until the fourth session of 2026-11-29 JDK 17-24 took it only with
 * {@code -Draytracer.simd=true}: about one long render in four to eight came out 1.2-1.7x slower
 * on it. The cause was two render workers' records put on one cache line by a garbage
 * collection, which {@code RenderLoop} now rules out; BENCHMARKS.md, issue 50.) Nothing is required
 * of anyone: {@code -Draytracer.simd=false} forces the scalar walk, {@code -Draytracer.simd=true}
 * gives every tree of {@link #ASKED_MIN_PRIMITIVES} primitives or more the vector walk from its first ray
 * (a JVM that renders for long: a benchmark, a Spark executor). Both walks return the same hits,
 * so the choice changes speed only, never an image.
 */
final class Vectorization {
    /** The system property: {@code false} forces the scalar walk, {@code true} the vector walk from the first ray. */
    static final String PROPERTY = "raytracer.simd";
    private static final String MODULE = "jdk.incubator.vector";
    /** Whether this JVM may take the vector walk: the module is readable and not refused by the property. */
    static final boolean AVAILABLE;
    /** Whether {@code -Draytracer.simd=true} asks for the vector walk from the first ray. */
    private static final boolean EAGER;
    /** Why the scalar walk when not {@link #AVAILABLE}; null when it is. */
    private static final String WHY_NOT;
    /**
     * The smallest tree worth the wide walk, on every JDK. A vector step costs more than the few
     * scalar box tests of a shallow tree. On JDK 17 the meshes of 10^4 triangles and more ran
     * 1.5-1.9x faster, the teapot scene of 1,392 shapes on par. On JDK 25 this was 128 until
     * whole renders with the module said otherwise (BENCHMARKS.md, issue 50, night session; vector
     * walk from the first ray against scalar, 2 threads): the showcase (133 shapes) at 64 samples
     * a pixel 11.9 s against 8.9-9.3 s, the teapot (992 triangles) at 25 samples 3.4-4.0 s against
     * 2.2-2.4 s, the 137-primitive scene at 64 samples 9.9-14.2 s against 9.2 s; where most rays
     * miss or hit a few large shapes, the scalar walk's early exits win. (Those figures included
     * the slow runs of two workers' records on one cache line, see {@code RenderLoop}; measured
     * again without them, fourth session of 2026-11-29: the showcase 1.045x, the 137-primitive
     * scene 1.009x, the teapot at 25 samples a pixel 1.13x on JDK 25, at 64 samples 0.94x, which
     * {@link #ASKED_MIN_PRIMITIVES} takes.)
     */
    static final int MIN_PRIMITIVES = 4096;
    /**
     * The smallest tree that takes the vector walk when {@code -Draytracer.simd=true} asks for it
     * (a JVM that renders for long: a benchmark, a Spark executor). Such a JVM pays the walk's
     * compilation once, and then a tree of about a thousand triangles gains too: the teapot scene
     * (992 triangles, 2 threads, 64 samples a pixel, vector walk from the first ray against
     * scalar, 5 pairs) 0.94 on JDK 25 and 0.88 on JDK 17; the walk alone, one thread, 1.11x
     * Embree's time against 2.03x (BENCHMARKS.md, issue 50, fourth session of 2026-11-29). Not
     * below: the showcase (133 shapes) at 64 samples a pixel took 1.045x on it. A render that was
     * not asked keeps {@link #MIN_PRIMITIVES}: the teapot at 25 samples a pixel, in a fresh JVM,
     * took 1.13x on JDK 25 (the compilation is not won back).
     */
    static final int ASKED_MIN_PRIMITIVES = 512;
    /**
     * The camera rays from which a render takes the vector walk from its first ray, on a tree of
     * {@link #MIN_PRIMITIVES} or more ({@link Bvh#expectCameraRays}), decided before any
     * ray of it is traced. Measured on the 99,224-triangle mesh
     * at 600×600, 2 threads, whole renders against the scalar walk: on JDK 25, in pairs, 0.97 (64 a
     * pixel) and 0.94 (144), where switching at the render's pace gave 1.03 (64 a pixel, too short to
     * switch) and 0.92–0.94; one a pixel took 1.5× on JDK 17 (the vector code runs interpreted until
     * compiled, about 0.6 s). With workers' records renewed after each collection ({@code
     * RenderLoop}), 5-6 pairs: JDK 17 0.81 (64 a pixel) and 0.75 (144), JDK 25 0.85 and 0.82.
     */
    static final long FIRST_RAY_CAMERA_RAYS = 20_000_000L;
    /**
     * Whether the vector walk runs compiled in this JVM: set by {@link VectorWarmUp} (from the
     * start with {@code -Draytracer.simd=true}), never unset. The one piece of state a JVM's
     * renders share, and it decides speed only: both walks give the same hits.
     */
    static final AtomicBoolean COMPILED;

    static {
        String asked = System.getProperty(PROPERTY);
        if ("false".equalsIgnoreCase(asked)) WHY_NOT = "-D" + PROPERTY + "=false";
        else if (ModuleLayer.boot().findModule(MODULE).isEmpty()) WHY_NOT = "no " + MODULE;
        else WHY_NOT = null;
        AVAILABLE = WHY_NOT == null;
        EAGER = AVAILABLE && "true".equalsIgnoreCase(asked);
        COMPILED = new AtomicBoolean(EAGER);
    }

    private Vectorization() {
    }

    /** The walk, loaded the first time it is asked for (by the warm-up's thread, or at once when {@link #EAGER}). */
    private static final class Loaded {
        static final WideWalk WALK;
        static final String WHY_NOT;

        static {
            WideWalk walk = null;
            String why = null;
            try {
                walk = (WideWalk) Class.forName("geometries.VectorWalk").getConstructor().newInstance();
            } catch (InvocationTargetException e) {
                why = e.getCause().getMessage(); // the walk's own reason: a CPU without 256-bit vectors
            } catch (ReflectiveOperationException | LinkageError e) {
                why = "the vector walk did not load: " + e;
            }
            WALK = walk;
            WHY_NOT = why;
        }
    }

    /** @return this JVM's vector walk, or null where there is none (not {@link #AVAILABLE}, or the CPU refused it) */
    static WideWalk walk() {
        return AVAILABLE ? Loaded.WALK : null;
    }

    /** @return the smallest tree this JVM's vector walk takes: {@link #ASKED_MIN_PRIMITIVES} with {@code -Draytracer.simd=true}, else {@link #MIN_PRIMITIVES} */
    static int minPrimitives() {
        return EAGER ? ASKED_MIN_PRIMITIVES : MIN_PRIMITIVES;
    }

    /** @return the walk a render's tree gets when it is built: this JVM's vector walk with {@code -Draytracer.simd=true}, else none */
    static WideWalk eagerWalk() {
        return EAGER ? walk() : null;
    }

    /**
     * @return one line: the walk a render's tree takes now (the vector one once {@link #COMPILED},
     *         for trees of {@link #MIN_PRIMITIVES} or more) and, for the scalar one, why
     */
    static String describe() {
        if (!AVAILABLE) return "scalar walk (" + WHY_NOT + ")";
        // Both causes in one line: telling them apart would load java.management (35-45 ms) for a
        // summary line; a long render with the optimizing compiler has the walk compiled. No
        // comma: the summary line's last comma ends the words before the walk's.
        if (!COMPILED.get()) return "scalar walk (the vector walk is not compiled: a short render or a JVM without the optimizing compiler)";
        WideWalk walk = walk();
        return walk != null ? walk.description() : "scalar walk (" + Loaded.WHY_NOT + ")";
    }
}
