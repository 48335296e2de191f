package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Runs a test class's {@code main} in a JVM of its own, on this test JVM's JDK and class path.
 *
 * <p>Why: what the JIT compiler does is a property of a JVM's history. In the suite's JVM, after
 * thousands of tests, the vector walk, though compiled by C2, stayed slow and allocating for
 * minutes, and its leaf tests stayed in the profiled tier (seen in CI and here; the compile queue
 * was nearly idle meanwhile, the cause is not known), so a check of "the vector walk once compiled"
 * made there passed or failed by chance. A user's render runs in
 * a JVM whose queue is short; a fresh JVM is that case. And a JVM's walk is decided once per JVM
 * ({@link Vectorization}), so options such as {@code -Draytracer.simd} need a JVM of their own.
 */
final class FreshJvm {
    /** A fresh JVM that compiles the vector walk takes about a second; this is the bound for a loaded machine. */
    private static final long TIMEOUT_SECONDS = 180;

    private FreshJvm() {
    }

    /**
     * Runs {@code main}'s {@code main(args)} with the JVM options {@code options} and returns what it
     * printed on standard output, stripped; fails when it does not exit with 0 within the timeout,
     * with what it printed on both streams.
     */
    static String run(Class<?> main, List<String> options, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xshare:off", "-cp", System.getProperty("java.class.path")));
        command.addAll(options);
        command.add(main.getName());
        command.addAll(List.of(args));
        // Both streams to files: the wait below is then bounded, whatever the JVM prints or does.
        Path output = Files.createTempFile("fresh-jvm", ".out"), errors = Files.createTempFile("fresh-jvm", ".err");
        try {
            Process p = new ProcessBuilder(command).redirectOutput(output.toFile()).redirectError(errors.toFile()).start();
            p.getOutputStream().close();
            boolean ended = p.waitFor(TIMEOUT_SECONDS, TimeUnit.SECONDS);
            if (!ended) p.destroyForcibly().waitFor();
            String out = Files.readString(output).strip(), err = Files.readString(errors);
            assertThat(ended).as("%s ended within %d s; it printed:%n%s%n%s", command, TIMEOUT_SECONDS, out, err).isTrue();
            assertThat(p.exitValue()).as("%s's exit value; it printed:%n%s%n%s", command, out, err).isZero();
            return out;
        } finally {
            Files.deleteIfExists(output);
            Files.deleteIfExists(errors);
        }
    }

    /** The options that make the vector walk readable in a fresh JVM. */
    static List<String> withVectorModule(String... more) {
        List<String> options = new ArrayList<>(List.of("--add-modules", "jdk.incubator.vector"));
        options.addAll(List.of(more));
        return options;
    }
}
