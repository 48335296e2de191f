package app.spark;

import org.apache.spark.SparkConf;

/**
 * The executors' BVH walk: the vector walk from the first ray ({@code -Draytracer.simd=true}),
 * where their JDK has {@code jdk.incubator.vector} (Spark 4 adds the module to its JVMs). An
 * executor renders tile after tile for the whole job, each tile too short for the library to
 * warm the vector walk by itself (it does so in a render with seconds left,
 * docs/student-guide.md, "The vector walk"), while the job as a whole runs long enough to pay
 * for compiling it. A user's own {@code raytracer.simd} option is left as it is.
 */
final class ExecutorWalk {
    /** The library's system property of the walk ({@code geometries.Vectorization}). */
    static final String PROPERTY = "raytracer.simd";

    private ExecutorWalk() {
    }

    /** Adds {@code -Draytracer.simd=true} to the executors' JVM options of {@code conf}, unless they set the property. */
    static void fromTheFirstRay(SparkConf conf) {
        String options = conf.get(QuietLog.EXECUTOR_JVM_OPTIONS, "").trim();
        if (options.contains("-D" + PROPERTY + "=")) return;
        String option = "-D" + PROPERTY + "=true";
        conf.set(QuietLog.EXECUTOR_JVM_OPTIONS, options.isEmpty() ? option : options + " " + option);
    }
}
