package app.spark;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

import app.Project;

/**
 * One render across hosts: a Spark standalone cluster of this machine's network namespaces
 * ({@code scripts/spark_netns_cluster.sh}): the master on host 1 (10.231.77.1), a worker of one
 * core on hosts 2 and 3, the driver (spark-submit) in this namespace at 10.231.77.254 on the
 * bridge. Each worker's mount namespace covers the driver's folder with an empty file system, as a
 * driver's files are on another machine: the executors get the scenes and the program over the
 * network only. Every image is compared byte for byte with the same render on this machine alone.
 * Then the faults of a network: a link slowed by 200 ms, a worker's link cut mid-job, and that
 * worker back. Needs root, iproute2 and a Spark installation; skipped with one line otherwise.
 * The namespaces and the bridge are removed after the tests whatever happened.
 */
@EnabledWhereSparkRuns
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class NetnsClusterTest {
    private static final String PREFIX = "rtc";
    private static final String DRIVER = "10.231.77.254";
    private static final Path SCRIPT = Project.file("scripts/spark_netns_cluster.sh");

    @TempDir
    static Path dir;
    /** The driver's folder: the program, the scene files, the images; hidden from the workers. */
    @TempDir
    static Path driver;
    private static SparkInstallation spark;
    private static SparkInstallation.Daemon master;
    private static final List<SparkInstallation.Daemon> workers = new ArrayList<>();
    private static boolean up;

    /** Runs the namespace script; the output of a failure, or null when it succeeded. */
    private static String script(String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of("bash", SCRIPT.toString()));
        command.addAll(List.of(args));
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        return p.waitFor() == 0 ? null : said.isEmpty() ? "exit " + p.exitValue() : said;
    }

    @BeforeAll
    static void cluster() throws Exception {
        Path home = SparkInstallation.find().orElse(null);
        assumeTrue(home != null, "no Spark installation: set " + SparkInstallation.HOME_VARIABLE + " (docs/spark.md)");
        script("down", PREFIX); // what a killed run may have left
        String refused = script("up", PREFIX, "3");
        if (refused != null) script("down", PREFIX);
        assumeTrue(refused == null, "network namespaces cannot be made here (root and iproute2 needed): " + refused);
        up = true;
        spark = SparkInstallation.at(home, dir);
        Files.copy(SparkInstallation.applicationJar(dir.resolve("raytracer.jar")), driver.resolve("raytracer.jar"));
        Path scenes = Files.createDirectories(driver.resolve("scenes"));
        try (Stream<Path> files = Files.list(Project.file("scenes"))) {
            for (Path f : files.toList()) Files.copy(f, scenes.resolve(f.getFileName()));
        }
        // The master declares a worker lost after 10 s without a heartbeat (default 60 s), so that
        // the worker whose link comes back registers again within the test. The workers read the
        // same setting: a worker beats every quarter of *its* timeout, and with the default (every
        // 15 s) a healthy worker was dropped every 10 s and its executor replaced mid-job.
        Path conf = Files.writeString(dir.resolve("cluster.conf"), "spark.worker.timeout 10\n");
        master = spark.master("master", new SparkInstallation.Host(PREFIX + "-1", "10.231.77.1", null), "--properties-file",
                conf.toString());
        for (int n = 2; n <= 3; n++)
            workers.add(spark.worker("worker" + n, master, new SparkInstallation.Host(PREFIX + "-" + n, "10.231.77." + n, driver), 1,
                    "--properties-file", conf.toString()));
    }

    @AfterAll
    static void tearDown() throws Exception {
        try {
            for (SparkInstallation.Daemon w : workers) w.close();
            if (master != null) master.close();
        } finally {
            if (up) script("down", PREFIX);
        }
    }

    /** spark-submit of the command line from the driver's folder, on the cluster, with {@code conf} and then {@code args}. */
    private static SparkInstallation.Submitted submit(List<String> conf, String... args) throws IOException {
        List<String> command = new ArrayList<>(List.of("--master", master.url, "--conf", "spark.driver.host=" + DRIVER,
                "--conf", "spark.driver.bindAddress=" + DRIVER, "--driver-memory", "512m", "--executor-memory", "512m"));
        conf.forEach(c -> command.addAll(List.of("--conf", c)));
        command.addAll(List.of("--class", "app.cli.Main", "raytracer.jar", "--spark", "submit"));
        command.addAll(List.of(args));
        return spark.submit(driver, command, new SparkInstallation.Host(null, DRIVER, null));
    }

    /** The same render on this machine alone (the command line, no Spark), as the reference. */
    private static byte[] local(String scene, String... options) throws Exception {
        Path png = dir.resolve("local-" + Path.of(scene).getFileName() + String.join("", options).replaceAll("\\W", "") + ".png");
        List<String> args = new ArrayList<>(List.of(scene, "--quiet", "-o", png.toString()));
        args.addAll(List.of(options));
        run(driver, "app.cli.Main", args.toArray(String[]::new));
        return Files.readAllBytes(png);
    }

    /** Runs {@code main} of this build with {@code args} in a JVM of its own, in {@code folder}. */
    private static void run(Path folder, String main, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), main));
        command.addAll(List.of(args));
        Process p = new ProcessBuilder(command).directory(folder.toFile()).redirectErrorStream(true).start();
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor()).as(said).isZero();
    }

    /** The summary line of a Spark render. */
    private static String summary(SparkInstallation.Run r) {
        return r.out().stream().filter(l -> l.matches("spark render [^:]+: \\d+\\.\\d+ s, .*")).findFirst()
                .orElseThrow(() -> new AssertionError("no summary line; stderr:\n" + String.join("\n", r.err())));
    }

    @Test
    @Order(1)
    @DisplayName("the scenes of scenes/ across three hosts in one job: each PNG byte-identical to this machine's render, both workers used")
    void scenesAcrossHosts() throws Exception {
        List<String> names = List.of("showcase", "glossy", "two-colors", "teapot");
        SparkInstallation.Run r = submit(List.of(), names.stream().map(n -> "scenes/" + n + ".xml").toArray(String[]::new)).await();
        assertThat(r.exitCode()).as(String.join("\n", r.err())).isZero();
        assertThat(summary(r)).contains("2 executors");
        // this machine alone, each scene into images/<image name>.png of a folder of its own
        Path alone = Files.createDirectories(dir.resolve("alone"));
        for (String n : names) run(alone, "app.cli.Main", driver.resolve("scenes/" + n + ".xml").toString(), "--quiet");
        assertThat(images(driver.resolve("images"))).hasSize(names.size()).isEqualTo(images(alone.resolve("images")));
        report("across hosts", r, images(driver.resolve("images")).toString());
    }

    /** Each PNG of a folder, by name, as the bytes' SHA-256 (the comparison shows names, not arrays). */
    private static java.util.Map<String, String> images(Path folder) throws Exception {
        java.util.Map<String, String> all = new java.util.TreeMap<>();
        try (Stream<Path> files = Files.list(folder)) {
            for (Path f : files.toList()) all.put(f.getFileName().toString(), sha(f));
        }
        return all;
    }

    @Test
    @Order(2)
    @DisplayName("a worker's link delayed by 200 ms (tc netem), or where the kernel has no netem held to 2 Mbit/s (tc tbf): the same bytes")
    void slowLink() throws Exception {
        String noDelay = script("delay", PREFIX, "2", "200");
        if (noDelay != null) {
            assertThat(noDelay).contains("no delay on this machine: tc netem");
            assertThat(script("rate", PREFIX, "2", "2000")).isNull();
        }
        try {
            Path png = driver.resolve("slow.png");
            SparkInstallation.Run r = submit(List.of(), "scenes/teapot.xml", "--width", "400", "--height", "400", "-o",
                    png.toString()).await();
            assertThat(r.exitCode()).as(String.join("\n", r.err())).isZero();
            assertThat(Files.readAllBytes(png)).isEqualTo(local("scenes/teapot.xml", "--width", "400", "--height", "400"));
            report(noDelay == null ? "delayed 200 ms" : "held to 2 Mbit/s (no netem: " + noDelay + ")", r, sha(png));
        } finally {
            assertThat(script("delay", PREFIX, "2", "0")).isNull();
            assertThat(script("rate", PREFIX, "2", "0")).isNull();
        }
    }

    @Test
    @Order(3)
    @DisplayName("a worker's link cut mid-job: the job ends on the other worker, byte-identical (or in one line within the bound)")
    void cutLink() throws Exception {
        Path png = driver.resolve("cut.png");
        // Lost executors are noticed after 15 s without a heartbeat (the default is 120 s).
        SparkInstallation.Submitted job = submit(List.of("spark.network.timeout=15s", "spark.network.timeoutInterval=5s", "spark.executor.heartbeatInterval=3s"),
                "scenes/showcase.xml", "--width", "600", "--height", "600", "-o", png.toString());
        awaitProgress(job, 10);
        assertThat(script("cut", PREFIX, "3")).isNull();
        SparkInstallation.Run r = job.await();
        report("link cut at 10 %", r, Files.exists(png) ? sha(png) : "no image");
        if (r.exitCode() == 0) {
            assertThat(Files.readAllBytes(png)).isEqualTo(local("scenes/showcase.xml", "--width", "600", "--height", "600"));
        } else {
            assertThat(r.exitCode()).isEqualTo(1);
            assertThat(r.err().stream().filter(l -> l.startsWith("raytracer: ")).toList()).hasSize(1);
            assertThat(png).doesNotExist();
        }
    }

    @Test
    @Order(4)
    @DisplayName("that worker back: it registers again and the next job uses both workers, byte-identical")
    void workerBack() throws Exception {
        assertThat(script("mend", PREFIX, "3")).isNull();
        // the master forgot it (10 s without a heartbeat); back on the network, it registers again
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(2);
        Path log = dir.resolve("worker3.log");
        while (System.nanoTime() < deadline && SparkInstallation.lines(log).stream()
                .filter(l -> l.contains("Successfully registered with master")).count() < 2
                && SparkInstallation.lines(log).stream().noneMatch(l -> l.contains("Master has changed") || l.contains("reconnect")))
            Thread.sleep(500);
        Path png = driver.resolve("back.png");
        SparkInstallation.Run r = submit(List.of(), "scenes/glossy.xml", "-o", png.toString()).await();
        assertThat(r.exitCode()).as(String.join("\n", r.err())).isZero();
        assertThat(summary(r)).contains("2 executors");
        assertThat(Files.readAllBytes(png)).isEqualTo(local("scenes/glossy.xml"));
        report("worker back", r, sha(png));
    }

    /** What a run did, for the test's output file (target/surefire-reports/app.spark.NetnsClusterTest-output.txt). */
    private static void report(String what, SparkInstallation.Run r, String images) {
        System.out.println("netns cluster, " + what + ": exit " + r.exitCode() + "; " + r.out().stream()
                .filter(l -> l.matches("spark render [^:]+: \\d+\\.\\d+ s, .*")).findFirst().orElse("(no summary)")
                + "; " + r.err().stream().filter(l -> l.startsWith("raytracer")).toList() + "; images " + images);
    }

    /** One PNG's SHA-256. */
    private static String sha(Path png) throws Exception {
        return java.util.HexFormat.of().formatHex(java.security.MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(png)));
    }

    /** Waits until the job's progress line reaches {@code percent} (on its standard output, as the command prints it). */
    private static void awaitProgress(SparkInstallation.Submitted job, double percent) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(2);
        var progress = java.util.regex.Pattern.compile("spark render \\S+:\\s+(\\d+\\.\\d)%");
        while (System.nanoTime() < deadline && job.alive()) {
            for (String line : SparkInstallation.lines(job.out))
                for (String part : line.split("\r")) {
                    var m = progress.matcher(part);
                    if (m.find() && Double.parseDouble(m.group(1)) >= percent) return;
                }
            Thread.sleep(200);
        }
        throw new AssertionError("no progress to " + percent + "% within 2 minutes, or the job ended:\n" + String.join("\n", SparkInstallation.lines(job.out))
                + "\n" + String.join("\n", SparkInstallation.lines(job.err)));
    }
}
