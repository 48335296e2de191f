package app.spark;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import app.Project;

/**
 * A Spark render on the command line, in a JVM of its own as a user starts it: nothing on stderr
 * from Spark or the JVM on success or bad input; Spark's log when {@code spark.log.level} asks.
 */
@EnabledWhereSparkRuns
class QuietSparkTest {
    @TempDir
    Path dir;

    /** What the command printed and returned. */
    private record Run(int exitCode, String out, String err) {
    }

    /** app.cli.Main in a new JVM with this JVM's class path and module openings (Spark's), in {@code dir}. */
    private Run main(List<String> jvm, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        for (String a : ManagementFactory.getRuntimeMXBean().getInputArguments())
            if (a.startsWith("--add-opens") || a.startsWith("-Djdk.") || a.startsWith("-Dio.netty")) command.add(a);
        command.addAll(jvm);
        if (jvm.stream().noneMatch(a -> a.startsWith("-Xmx"))) command.add("-Xmx512m");
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), "app.cli.Main"));
        command.addAll(List.of(args));
        Process p = new ProcessBuilder(command).directory(dir.toFile())
                .redirectOutput(dir.resolve("out.txt").toFile()).redirectError(dir.resolve("err.txt").toFile()).start();
        assertThat(p.waitFor(3, TimeUnit.MINUTES)).as("the command ends").isTrue();
        return new Run(p.exitValue(), Files.readString(dir.resolve("out.txt")), Files.readString(dir.resolve("err.txt")));
    }

    private Path scene() throws IOException {
        return Files.copy(Project.file("scenes/glossy.xml").toAbsolutePath(), dir.resolve("glossy.xml"));
    }

    @Test
    @DisplayName("a render: stdout has the progress, summary and 'wrote' lines; stderr is empty")
    void success() throws Exception {
        Run r = main(List.of(), "--spark", "local[2]", scene().toString(), "--width", "32", "--height", "16", "-o",
                dir.resolve("out.png").toString());
        assertThat(r.exitCode()).as(r.err()).isZero();
        assertThat(r.err()).isEmpty();
        assertThat(r.out()).contains("wrote ");
    }

    @Test
    @DisplayName("bad input: exit 2 and the one line, nothing after it")
    void badInput() throws Exception {
        Path bad = Files.writeString(dir.resolve("bad.xml"), "<scene>");
        Run r = main(List.of(), "--spark", "local[2]", bad.toString());
        assertThat(r.exitCode()).isEqualTo(2);
        assertThat(r.err()).hasLineCount(1).startsWith(bad + ":");
    }

    @Test
    @DisplayName("-Dspark.log.level=INFO asks for Spark's log")
    void verbose() throws Exception {
        Run r = main(List.of("-Dspark.log.level=INFO"), "--spark", "local[2]", scene().toString(), "--width", "16",
                "--height", "16", "-o", dir.resolve("out.png").toString());
        assertThat(r.exitCode()).as(r.err()).isZero();
        assertThat(r.err()).contains("INFO SparkContext: Running Spark version");
    }

    @Test
    @DisplayName("a driver Spark refuses (a 300 MB heap): exit 1 and one line")
    void driverRefused() throws Exception {
        Run r = main(List.of("-Xmx300m"), "--spark", "local[2]", scene().toString(), "-o", dir.resolve("out.png").toString());
        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.err()).hasLineCount(1).startsWith("raytracer: cannot start Spark: [INVALID_DRIVER_MEMORY] System memory");
    }
}
