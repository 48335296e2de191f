package app.spark;

import java.io.PrintStream;
import java.util.Optional;

import app.cli.SparkRequest;
import app.cli.SparkRunner;

/**
 * The command line's door to Spark, found by the command line as its {@link SparkRunner}. Spark
 * is a {@code provided} dependency: a cluster's {@code spark-submit} puts it on the class path,
 * the Maven profile {@code spark} does for a run on one machine, and the plain runnable jar leaves
 * it out. This class names no Spark type, so it can be loaded and asked before any class that
 * needs Spark is loaded.
 */
public final class SparkEntry implements SparkRunner {
    /** Exit code of bad input (as the command line's). */
    static final int BAD_INPUT = 2;

    /** The service the command line loads with {@link java.util.ServiceLoader}. */
    public SparkEntry() {
    }

    /** @return whether Spark's classes are on the class path */
    public static boolean available() {
        try {
            Class.forName("org.apache.spark.api.java.JavaSparkContext", false, SparkEntry.class.getClassLoader());
            return true;
        } catch (ClassNotFoundException e) {
            return false;
        }
    }

    /**
     * Renders on Spark as {@code request} says: checks that Spark is on the class path and runs on
     * this JDK, validates every scene on the driver (bad input: the local renderer's one-line
     * message, exit 2, no task), runs one job and writes one PNG per scene.
     */
    @Override
    public int run(SparkRequest request, PrintStream progress, PrintStream out, PrintStream err) {
        if (!available()) {
            err.println("raytracer: --spark needs Apache Spark on the class path, which the runnable jar leaves out: " + HOW_TO_RUN);
            return BAD_INPUT;
        }
        Optional<String> jdk = SparkJdk.unsupported();
        if (jdk.isPresent()) {
            err.println("raytracer: --spark: " + jdk.get());
            return BAD_INPUT;
        }
        return SparkCommand.run(request, progress, out, err);
    }
}
