package app.cli;

import java.io.PrintStream;

/**
 * The Spark render behind {@code --spark}, found with {@link java.util.ServiceLoader}: the
 * package {@code app.spark} provides it when the build includes Spark (the Maven profile
 * {@code spark}, asked for with {@code -Pspark}). The command line names no Spark type,
 * so a build without Spark (the README's first command) compiles, runs and downloads nothing of
 * Spark's; {@code --spark} then says in one line how to get it. Internal to the command line.
 */
public interface SparkRunner {
    /**
     * How to render on Spark, for the one-line errors of a jar or class path without it: the one
     * wording of the command line and of the Spark entry point.
     */
    String HOW_TO_RUN = "build it with 'mvn -q -Pspark package -DskipTests' and run it with"
            + " 'spark-submit --class app.cli.Main target/raytracer.jar --spark submit SCENE', or on this machine with"
            + " 'mvn -q -Pspark compile exec:exec -Dspark.args=\"--spark local[2] SCENE\"' (see docs/spark.md)";

    /**
     * Renders on Spark as {@code request} says.
     *
     * @param request  what to render
     * @param progress where progress lines go
     * @param out      where the summary and the "wrote" lines go
     * @param err      where errors go, one line each
     * @return the exit code: 0 written, 1 the job or a write failed, 2 bad input (including no
     *         Spark on the class path, or a JDK Spark does not run on)
     */
    int run(SparkRequest request, PrintStream progress, PrintStream out, PrintStream err);
}
