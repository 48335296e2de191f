package app.spark;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import app.Project;

/**
 * The command line through the real {@code spark-submit} script of a Spark installation (PyPI's
 * pyspark 4.0.1: {@value SparkInstallation#HOME_VARIABLE} names its package folder; .ci/run makes
 * one), on a standalone master and worker of that installation started here on 127.0.0.1 only.
 * What a user sees is counted: the lines on spark-submit's stderr (the driver's), and the lines in
 * each executor's stderr file the worker keeps. Spark's own log appears in neither unless
 * {@code spark.log.level} asks for it; the one line allowed besides ours is the JVM's own warning
 * that Spark's launcher enables an incubator module. Skipped, with the reason, where no
 * installation is named.
 */
@EnabledWhereSparkRuns
class SparkSubmitTest {
    /** The JVM's own line on a JDK where Spark's launcher adds the vector incubator module. */
    private static final String JVM_WARNING = "WARNING: Using incubator modules: jdk.incubator.vector";

    @TempDir
    static Path dir;
    private static SparkInstallation spark;
    private static SparkInstallation.Daemon master;
    private static SparkInstallation.Daemon worker;
    private static Path jar;

    @BeforeAll
    static void cluster() throws Exception {
        assumeTrue("127.0.0.1".equals(System.getenv("SPARK_LOCAL_IP")), "SPARK_LOCAL_IP=127.0.0.1 (pom.xml, spark-tests)");
        Path home = SparkInstallation.find().orElse(null);
        assumeTrue(home != null, "no spark-submit: set " + SparkInstallation.HOME_VARIABLE + " to a Spark 4.0 installation,"
                + " such as PyPI's pyspark 4.0.1 (python3 -m venv V && V/bin/pip install pyspark==4.0.1; then its package"
                + " folder, V/lib/python3.X/site-packages/pyspark; docs/spark.md)");
        spark = SparkInstallation.at(home, dir);
        jar = SparkInstallation.applicationJar(dir.resolve("raytracer.jar"));
        master = spark.master("master");
        worker = spark.worker("worker", master);
    }

    @AfterAll
    static void stop() throws InterruptedException {
        if (worker != null) worker.close();
        if (master != null) master.close();
    }

    /** spark-submit of the command line on {@code url} with spark-submit's {@code options}, then the command's {@code args}. */
    private static SparkInstallation.Run submit(String url, List<String> options, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of("--master", url, "--driver-memory", "512m", "--executor-memory",
                "512m", "--class", "app.cli.Main"));
        command.addAll(options);
        command.add(jar.toString());
        command.addAll(List.of(args));
        return spark.submit(Project.file(".").toAbsolutePath().normalize(), command);
    }

    /** The lines of the run's stderr but the JVM's warning. */
    private static List<String> driverLines(SparkInstallation.Run r) {
        return r.err().stream().filter(l -> !l.equals(JVM_WARNING)).toList();
    }

    /**
     * The lines the executors of the worker's latest application wrote in their {@code stream}
     * file (stderr, stdout), but the worker's header of stderr (the executor's command, a rule, a
     * blank line) and the JVM's warning.
     */
    private static List<String> executorLines(String stream) throws IOException {
        Path work = dir.resolve("worker");
        Path app;
        try (Stream<Path> apps = Files.list(work)) {
            app = apps.filter(Files::isDirectory).max(Path::compareTo).orElseThrow(() -> new AssertionError("no application in " + work));
        }
        List<String> lines = new ArrayList<>();
        try (Stream<Path> files = Files.walk(app)) {
            for (Path file : files.filter(f -> f.getFileName().toString().equals(stream)).toList()) {
                List<String> all = SparkInstallation.lines(file);
                int rule = stream.equals("stderr") ? all.indexOf("========================================") : -1;
                if (stream.equals("stderr")) assertThat(rule).as("the worker's header in " + file).isGreaterThanOrEqualTo(0);
                all.subList(rule + 1, all.size()).stream().filter(l -> !l.isEmpty() && !l.equals(JVM_WARNING)).forEach(lines::add);
            }
        }
        return lines;
    }

    @Test
    @DisplayName("a 25-tile teapot: exit 0, the PNG; no line of Spark's on the driver's stderr or in the executor's")
    void quiet() throws Exception {
        Path png = dir.resolve("teapot.png");
        SparkInstallation.Run r = submit(master.url, List.of(), "--spark", "submit", "scenes/teapot.xml", "--width", "320",
                "--height", "320", "-o", png.toString());
        assertThat(r.exitCode()).as(String.join("\n", r.err())).isZero();
        assertThat(driverLines(r)).isEmpty();
        assertThat(r.out()).anyMatch(l -> l.startsWith("wrote " + png + " (320x320)"));
        assertThat(png).isNotEmptyFile();
        assertThat(executorLines("stderr")).isEmpty();
        assertThat(executorLines("stdout")).isEmpty();
    }

    @Test
    @DisplayName("--conf spark.log.level=INFO: Spark's log on the driver's stderr and in the executor's stdout file")
    void verbose() throws Exception {
        SparkInstallation.Run r = submit(master.url, List.of("--conf", "spark.log.level=INFO"), "--spark", "submit",
                "scenes/two-colors.xml", "--width", "32", "--height", "32", "-o", dir.resolve("verbose.png").toString());
        assertThat(r.exitCode()).as(String.join("\n", r.err())).isZero();
        assertThat(driverLines(r)).anyMatch(l -> l.contains("INFO SparkContext: Running Spark version"));
        // log4j's default configuration at the level asked: its console is standard output
        assertThat(executorLines("stdout")).anyMatch(l -> l.contains("INFO") && l.contains("Executor"));
    }

    @Test
    @DisplayName("a bad spark.raytracer.executorTimeout: exit 2 and our one line, before Spark starts")
    void badTimeout() throws Exception {
        SparkInstallation.Run r = submit(master.url, List.of("--conf", "spark.raytracer.executorTimeout=abc"), "--spark",
                "submit", "scenes/two-colors.xml", "-o", dir.resolve("bad.png").toString());
        assertThat(r.exitCode()).isEqualTo(2);
        assertThat(driverLines(r)).containsExactly("raytracer: spark.raytracer.executorTimeout 'abc' is not a time"
                + " (expected a positive time such as 120s, 5m or 500ms)");
    }

    /**
     * The issue's case: an image that fits a 512 MB driver's heap (462 MB) but not beside its
     * 29,584 tasks; before, Spark's "Task serialization failed: java.lang.OutOfMemoryError" with
     * 64 frames, later our one line after about 11 s; now refused before the image is allocated.
     */
    @Test
    @DisplayName("--driver-memory 512m, teapot 11000²: exit 1, one line naming the image, the tasks, the limit and --driver-memory")
    void driverMemory() throws Exception {
        Path png = dir.resolve("huge.png");
        SparkInstallation.Run r = submit(master.url, List.of(), "--spark", "submit", "scenes/teapot.xml", "--width", "11000",
                "--height", "11000", "-o", png.toString());
        assertThat(r.exitCode()).as(String.join("\n", r.err())).isEqualTo(1);
        assertThat(driverLines(r)).hasSize(1);
        assertThat(driverLines(r).get(0)).matches("raytracer: failed on Spark: spark render teapot: the driver cannot hold the"
                + " job: its images \\(11000x11000, 462 MB\\) and 29584 tasks \\(about 48 MB\\) need about 511 MB; Java may use"
                + " at most \\d+ MB here, of which about \\d+ MB were free \\(give the driver more memory with spark-submit"
                + " --driver-memory, or -Xmx for a local master; or render it smaller\\)");
        assertThat(png).doesNotExist();
    }

    /**
     * Item 4 of issue 41: on 66cde8e, with 1ms (or 0s) the watch fired before the job was
     * submitted, and the job then waited for executors without end (spark-submit still running
     * after 5 minutes; the line came out only when the process was killed). Now the watch is armed
     * when the job starts, so even a timeout of a millisecond ends the job.
     */
    @Test
    @DisplayName("a master without workers: after the timeout (5 s, 1 ms), exit 1 and our one line; the driver's JVM ends")
    void noWorkers() throws Exception {
        try (SparkInstallation.Daemon alone = spark.master("master-alone")) {
            for (String timeout : List.of("5s", "1ms")) {
                Path png = dir.resolve("alone.png");
                // submit waits for the process to end (and fails the test if it does not within minutes)
                SparkInstallation.Run r = submit(alone.url, List.of("--conf", "spark.raytracer.executorTimeout=" + timeout),
                        "--spark", "submit", "scenes/two-colors.xml", "--width", "32", "--height", "32", "-o", png.toString());
                assertThat(r.exitCode()).as(timeout).isEqualTo(1);
                assertThat(driverLines(r)).as(timeout).containsExactly("raytracer: failed on Spark: spark render two-colors:"
                        + " no executor joined in the " + (timeout.equals("5s") ? "5" : "0.001") + " s since the job asked for"
                        + " them: the cluster has no worker free for this job, or its executors take longer to start (raise"
                        + " spark.raytracer.executorTimeout)");
                assertThat(png).doesNotExist();
            }
        }
    }
}
