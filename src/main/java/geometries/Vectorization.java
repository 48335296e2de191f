package geometries;

import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Which walk the trees of this JVM take (Apache Lucene's {@code VectorizationProvider} pattern):
 * the {@code VectorWalk} of wide nodes where the incubating Vector API is readable
 * ({@code --add-modules jdk.incubator.vector}) and the CPU's vectors hold four doubles (AVX2 and
 * later); the scalar walk of binary nodes otherwise. A render's tree takes the vector walk only
 * in a render with seconds of work left, once the walk runs compiled ({@link #COMPILED},
 * {@link Bvh#expectLongWalk}), and only from JDK 25 on ({@link #SWITCHES}): a short render never
 * loads a vector class. Nothing is required
 * of anyone: {@code -Draytracer.simd=false} forces the scalar walk, {@code -Draytracer.simd=true}
 * gives every tree the vector walk from its first ray (a JVM that renders for long: a benchmark,
 * a Spark executor). Both walks return the same hits, so the choice changes speed only, never an
 * image.
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
     * The smallest tree worth the wide walk on this JDK. A vector step costs more than the few
     * scalar box tests of a shallow tree: the renders of the benchmark (interleaved A/B, one
     * thread) ran slower with the vector walk on a scene of 72 shapes (glossy: 1.08x on JDK 17,
     * 1.11x on JDK 25) and faster from 133 shapes on JDK 25 (showcase: 0.75-0.92x); on JDK 17,
     * whose vector code is slower, from about 10^4 triangles (meshes: 1.5-1.9x faster; the teapot
     * scene of 1,392 shapes on par, the showcase of 133 mixed).
     */
    static final int MIN_PRIMITIVES = Runtime.version().feature() >= 25 ? 128 : 4096;
    /**
     * Whether a render's tree takes the vector walk by itself, once it is compiled and the render
     * has seconds left ({@link Bvh#expectLongWalk}): from JDK 25 on. On JDK 17 a tree switched in
     * the middle of a render walked about 30 % slower than the scalar walk (a mesh of 10<sup>5</sup>
     * triangles, 144 samples a pixel: 15-17 s against 12.3 s), although the same walk from the
     * first ray is about 18 % faster (10.1 s): the code the compiler makes for a walk that changes
     * under a running render is worse there (BENCHMARKS.md, issue 50, item 2, second pass). JDK 18
     * to 24 are not measured, so they keep the scalar walk too; {@code -Draytracer.simd=true} gives
     * any of them the vector walk from the first ray.
     */
    static final boolean SWITCHES = Runtime.version().feature() >= 25;
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
        if (!COMPILED.get())
            return SWITCHES ? "scalar walk (the vector walk is not compiled yet: a short render)"
                    : "scalar walk (JDK " + Runtime.version().feature() + " takes the vector walk only with -D" + PROPERTY + "=true)";
        WideWalk walk = walk();
        return walk != null ? walk.description() : "scalar walk (" + Loaded.WHY_NOT + ")";
    }
}
