package geometries;

import java.lang.reflect.InvocationTargetException;

/**
 * Which walk the trees of this JVM use, chosen once when the class initialises (Apache Lucene's
 * {@code VectorizationProvider} pattern): the {@code VectorWalk} of wide nodes when the
 * incubating Vector API is readable ({@code --add-modules jdk.incubator.vector}) and the CPU's
 * vectors hold four doubles (AVX2 and later); the scalar walk of binary nodes otherwise. A tree
 * a render builds takes the vector walk only once it runs compiled ({@link #COMPILED}); until
 * then, and in a JVM that never compiles it, the scalar walk. Nothing is required of anyone:
 * {@code -Draytracer.simd=false} forces the scalar walk, {@code -Draytracer.simd=true} takes the
 * vector walk from the first ray (a JVM that renders for long: a benchmark, a Spark executor).
 * Both walks return the same hits, so the choice changes speed only, never an image.
 */
final class Vectorization {
    /** The system property: {@code false} forces the scalar walk, {@code true} the vector walk from the first ray. */
    static final String PROPERTY = "raytracer.simd";
    private static final String MODULE = "jdk.incubator.vector";

    /** The wide walk of this JVM, or null for the scalar walk. */
    static final WideWalk WALK;
    /**
     * The gate of the trees a render builds: opened by {@link VectorWarmUp} once {@link #WALK}
     * runs compiled in this JVM (open from the start with {@code -Draytracer.simd=true}), never
     * when there is no {@link #WALK}. The one piece of state a JVM shares between its renders,
     * and it decides speed only: both walks give the same hits.
     */
    static final WideGate COMPILED;
    /** Why there is no {@link #WALK}, in words; null when there is one. */
    private static final String WHY_SCALAR;

    static {
        WideWalk walk = null;
        String why;
        String asked = System.getProperty(PROPERTY);
        if ("false".equalsIgnoreCase(asked)) {
            why = "-D" + PROPERTY + "=false";
        } else if (ModuleLayer.boot().findModule(MODULE).isEmpty()) {
            why = "no " + MODULE;
        } else {
            try {
                walk = (WideWalk) Class.forName("geometries.VectorWalk").getConstructor().newInstance();
                why = null;
            } catch (InvocationTargetException e) {
                why = e.getCause().getMessage(); // the walk's own reason: a CPU without 256-bit vectors
            } catch (ReflectiveOperationException | LinkageError e) {
                why = "the vector walk did not load: " + e;
            }
        }
        WALK = walk;
        WHY_SCALAR = why;
        COMPILED = new WideGate(walk != null && "true".equalsIgnoreCase(asked));
    }

    /**
     * @return one line: the walk a render's tree takes now (the vector one once {@link #COMPILED}
     *         is open) and, for the scalar one, why
     */
    static String describe() {
        if (WALK == null) return "scalar walk (" + WHY_SCALAR + ")";
        return COMPILED.isOpen() ? WALK.description()
                : "scalar walk (the " + WALK.width() + "-wide vector walk is not compiled yet)";
    }

    private Vectorization() {
    }

}
