package geometries;

import java.lang.reflect.InvocationTargetException;

/**
 * Which walk the trees of this JVM use, chosen once when the class initialises (Apache Lucene's
 * {@code VectorizationProvider} pattern): the {@code VectorWalk} of wide nodes when the
 * incubating Vector API is readable ({@code --add-modules jdk.incubator.vector}) and the CPU's
 * vectors hold four doubles (AVX2 and later); the scalar walk of binary nodes otherwise. (A JVM
 * that stops at the quick-start compiler, {@code -XX:TieredStopAtLevel=1}, runs the vector
 * classes as plain objects, slower than the scalar walk: the launcher passes the module only
 * with the optimizing compiler.) Nothing is required of anyone;
 * {@code -Draytracer.simd=false} forces the scalar walk. Both walks return the same hits, so the
 * choice changes speed only, never an image.
 */
final class Vectorization {
    /** The system property that, set to {@code false}, forces the scalar walk. */
    static final String PROPERTY = "raytracer.simd";
    private static final String MODULE = "jdk.incubator.vector";

    /** The wide walk of this JVM, or null for the scalar walk. */
    static final WideWalk WALK;
    /** One line: which walk runs and, for the scalar one, why. */
    static final String DESCRIPTION;

    static {
        WideWalk walk = null;
        String why;
        if ("false".equalsIgnoreCase(System.getProperty(PROPERTY))) {
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
        DESCRIPTION = walk != null ? walk.description() : "scalar walk (" + why + ")";
    }

    private Vectorization() {
    }

}
