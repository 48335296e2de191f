package app.spark;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.jar.JarOutputStream;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * A Spark installation on this machine, as a user has one (PyPI's {@code pyspark} gives one:
 * its package folder holds {@code bin/spark-submit}, {@code bin/spark-class} and the jars), run
 * as a user runs it: its scripts in processes of their own, on this JDK, every daemon on
 * 127.0.0.1 only (its ports and web UIs: {@code SPARK_LOCAL_IP}), with an empty configuration
 * folder so that no {@code spark-defaults.conf} or {@code log4j2.properties} of the machine
 * changes what a test sees.
 */
final class SparkInstallation {
    /** The environment variable that names the installation (a folder with bin/spark-submit); else SPARK_HOME. */
    static final String HOME_VARIABLE = "RAYTRACER_SPARK_HOME";
    /** How long a daemon may take to start, or spark-submit to end. */
    private static final long MINUTES = 3;

    private final Path home;
    private final Path dir;

    private SparkInstallation(Path home, Path dir) {
        this.home = home;
        this.dir = dir;
    }

    /**
     * @return the installation {@value #HOME_VARIABLE} names, else SPARK_HOME, when it has an
     *         executable bin/spark-submit; empty otherwise
     */
    static Optional<Path> find() {
        for (String variable : List.of(HOME_VARIABLE, "SPARK_HOME")) {
            String value = System.getenv(variable);
            if (value == null || value.isBlank()) continue;
            Path home = Path.of(value);
            if (Files.isExecutable(home.resolve("bin/spark-submit"))) return Optional.of(home);
        }
        return Optional.empty();
    }

    /**
     * @param home the installation ({@link #find()})
     * @param dir  a folder of the test's own, for logs, the empty configuration and the workers' files
     */
    static SparkInstallation at(Path home, Path dir) throws IOException {
        Files.createDirectories(dir.resolve("conf"));
        return new SparkInstallation(home, dir);
    }

    /** What a process printed and returned. */
    record Run(int exitCode, List<String> out, List<String> err) {
    }

    /**
     * Where a daemon or spark-submit runs: a network namespace of this machine (null: this one),
     * the address it binds and announces, and a folder it must not see (null: none), covered by
     * an empty file system in its own mount namespace, as a driver's files are on another machine.
     */
    record Host(String namespace, String address, Path hidden) {
        /** This machine's loopback, nothing hidden: every test cluster but the namespaces'. */
        static final Host LOOPBACK = new Host(null, "127.0.0.1", null);
    }

    /** A daemon of the installation (master or worker), stopped with its process tree on close. */
    static final class Daemon implements AutoCloseable {
        private final Process process;
        /** The master's URL (spark://127.0.0.1:PORT), or the worker's master. */
        final String url;

        private Daemon(Process process, String url) {
            this.process = process;
            this.url = url;
        }

        @Override
        public void close() throws InterruptedException {
            process.descendants().forEach(ProcessHandle::destroy);
            process.destroy();
            if (!process.waitFor(30, TimeUnit.SECONDS)) {
                process.descendants().forEach(ProcessHandle::destroyForcibly);
                process.destroyForcibly().waitFor();
            }
        }
    }

    /** A standalone master on 127.0.0.1, its port and web UI's chosen by the system. */
    Daemon master(String name) throws IOException, InterruptedException {
        return master(name, Host.LOOPBACK);
    }

    /** A standalone master on {@code host}, its port and web UI's chosen by the system. */
    Daemon master(String name, Host host, String... options) throws IOException, InterruptedException {
        Path log = dir.resolve(name + ".log");
        List<String> args = new ArrayList<>(List.of("org.apache.spark.deploy.master.Master", "--host", host.address(),
                "--port", "0", "--webui-port", "0"));
        args.addAll(List.of(options));
        Process p = start(log, host, "bin/spark-class", args);
        Matcher m = awaitLine(p, log, Pattern.compile("Starting Spark master at (spark://" + Pattern.quote(host.address()) + ":\\d+)"));
        awaitLine(p, log, Pattern.compile("I have been elected leader"));
        return new Daemon(p, m.group(1));
    }

    /** A worker of {@code master} on 127.0.0.1: 2 cores, 1 GB for executors; their files in {@code <dir>/<name>}. */
    Daemon worker(String name, Daemon master) throws IOException, InterruptedException {
        return worker(name, master, Host.LOOPBACK, 2);
    }

    /**
     * A worker of {@code master} on {@code host}: {@code cores} cores, 1 GB for executors; their files in
     * {@code <dir>/<name>}; {@code options} after the others.
     */
    Daemon worker(String name, Daemon master, Host host, int cores, String... options) throws IOException, InterruptedException {
        Path log = dir.resolve(name + ".log");
        List<String> args = new ArrayList<>(List.of("org.apache.spark.deploy.worker.Worker", master.url, "--host",
                host.address(), "--port", "0", "--webui-port", "0", "--cores", String.valueOf(cores), "--memory", "1g",
                "--work-dir", Files.createDirectories(dir.resolve(name)).toString()));
        args.addAll(List.of(options));
        Process p = start(log, host, "bin/spark-class", args);
        awaitLine(p, log, Pattern.compile("Successfully registered with master"));
        return new Daemon(p, master.url);
    }

    /** spark-submit with {@code args}, in {@code workDir}; waits for it to end (a few minutes at most). */
    Run submit(Path workDir, List<String> args) throws IOException, InterruptedException {
        return submit(workDir, args, Host.LOOPBACK).await();
    }

    /** A spark-submit under way: its process and the files its output goes to. */
    final class Submitted {
        private final Process p;
        private final List<String> command;
        final Path out, err;

        private Submitted(Process p, List<String> command, Path out, Path err) {
            this.p = p;
            this.command = command;
            this.out = out;
            this.err = err;
        }

        boolean alive() {
            return p.isAlive();
        }

        /** Waits for it to end (a few minutes at most). */
        Run await() throws IOException, InterruptedException {
            if (!p.waitFor(MINUTES, TimeUnit.MINUTES)) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly().waitFor();
                throw new AssertionError("spark-submit did not end within " + MINUTES + " minutes: " + command
                        + "\nstderr:\n" + String.join("\n", lines(err)));
            }
            return new Run(p.exitValue(), lines(out), lines(err));
        }
    }

    /** Starts spark-submit with {@code args} on {@code host} (the driver's), in {@code workDir}. */
    Submitted submit(Path workDir, List<String> args, Host host) throws IOException {
        List<String> command = new ArrayList<>(List.of(home.resolve("bin/spark-submit").toString()));
        command.addAll(args);
        Path out = Files.createTempFile(dir, "submit", ".out"), err = Files.createTempFile(dir, "submit", ".err");
        ProcessBuilder pb = new ProcessBuilder(command).directory(workDir.toFile())
                .redirectOutput(out.toFile()).redirectError(err.toFile());
        environment(pb.environment(), host.address());
        return new Submitted(pb.start(), command, out, err);
    }

    /**
     * Starts a script of the installation on {@code host}: in its network namespace (through
     * {@code ip netns exec}, whose mount namespace is the process's own), with its hidden folder
     * covered by an empty tmpfs first.
     */
    private Process start(Path log, Host host, String script, List<String> args) throws IOException {
        List<String> command = new ArrayList<>();
        if (host.namespace() != null) command.addAll(List.of("ip", "netns", "exec", host.namespace()));
        if (host.hidden() != null)
            command.addAll(List.of("sh", "-c", "mount -t tmpfs hidden \"$0\" && exec \"$@\"", host.hidden().toString()));
        command.add(home.resolve(script).toString());
        command.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        environment(pb.environment(), host.address());
        return pb.start();
    }

    /** This JDK, the installation, the host's address only, the empty configuration folder. */
    private void environment(Map<String, String> env, String address) {
        env.put("JAVA_HOME", System.getProperty("java.home"));
        env.put("SPARK_HOME", home.toString());
        env.put("SPARK_LOCAL_IP", address);
        env.put("SPARK_CONF_DIR", dir.resolve("conf").toString());
        env.remove("SPARK_DIST_CLASSPATH");
        env.remove("SPARK_TESTING");
    }

    /**
     * The program's jar as {@code mvn -Pspark package} makes it, the classes this build compiled
     * and picocli's (the runnable jar does not exist yet when the tests run, or is the last
     * package's). Not picocli's jar beside it with {@code --jars}: spark-submit then reads that
     * jar through Hadoop before the command starts, and Hadoop's warning about its native library
     * comes out on stderr in Spark's default log, out of the command's reach.
     */
    static Path applicationJar(Path target) throws IOException, URISyntaxException {
        Path classes = codeSource(SparkEntry.class);
        if (Files.isRegularFile(classes)) return classes;
        try (OutputStream file = Files.newOutputStream(target); JarOutputStream out = new JarOutputStream(file)) {
            try (Stream<Path> all = Files.walk(classes)) {
                for (Path f : all.filter(Files::isRegularFile).sorted().toList()) {
                    out.putNextEntry(new JarEntry(classes.relativize(f).toString().replace('\\', '/')));
                    Files.copy(f, out);
                    out.closeEntry();
                }
            }
            try (JarFile cli = new JarFile(codeSource(picocli.CommandLine.class).toFile())) {
                for (JarEntry e : Collections.list(cli.entries())) {
                    if (e.isDirectory() || e.getName().startsWith("META-INF/")) continue;
                    out.putNextEntry(new JarEntry(e.getName()));
                    try (InputStream in = cli.getInputStream(e)) {
                        in.transferTo(out);
                    }
                    out.closeEntry();
                }
            }
        }
        return target;
    }

    private static Path codeSource(Class<?> c) throws URISyntaxException {
        return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    /** The lines of a file a process wrote, bytes that are not UTF-8 replaced. */
    static List<String> lines(Path file) throws IOException {
        return new String(Files.readAllBytes(file), StandardCharsets.UTF_8).lines().toList();
    }

    /** Waits until the daemon's log has a line matching {@code pattern}; fails with the log when it dies or takes too long. */
    private static Matcher awaitLine(Process p, Path log, Pattern pattern) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(MINUTES);
        while (System.nanoTime() < deadline) {
            for (String line : lines(log)) {
                Matcher m = pattern.matcher(line);
                if (m.find()) return m;
            }
            if (!p.isAlive()) throw new AssertionError("the daemon ended (exit " + p.exitValue() + ") before '"
                    + pattern + "':\n" + String.join("\n", lines(log)));
            Thread.sleep(200);
        }
        throw new AssertionError("no '" + pattern + "' within " + MINUTES + " minutes:\n" + String.join("\n", lines(log)));
    }
}
