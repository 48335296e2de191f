package app.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

import picocli.CommandLine;

/**
 * Runs the {@code render} command for the command-line tests: in-process through picocli with
 * captured streams, or in a new JVM (for heap limits and signals).
 */
final class Cli {
    /** The jar's Main-Class (pom.xml's main.class). */
    static final String MAIN_CLASS = "app.cli.Main";

    private Cli() {
    }

    /**
     * A small lit scene, 40×20 pixels, with a sphere edge against the background and a glossy
     * floor, so that anti-aliasing, seeds and beams all change pixels.
     */
    static final String SMALL = """
            <scene name="small" background-color="20 30 40">
                <ambient-light color="255 255 255" ka="0.1"/>
                <geometries>
                    <sphere center="0 0 -50" radius="12" emission="200 60 30">
                        <material kd="0.5" ks="0.5" shininess="30"/>
                    </sphere>
                    <plane point="0 -12 0" normal="0 1 0" emission="30 30 30">
                        <material kd="0.3" kr="0.5" reflection-spread="0.2"/>
                    </plane>
                </geometries>
                <lights>
                    <point-light color="300 300 300" position="20 30 0" radius="3"/>
                </lights>
                <camera location="0 0 0" direction="0 0 -1" up="0 1 0" vp-size="40 20" vp-distance="25"/>
                <image name="small" width="40" height="20"/>
                <render threads="1" beam-size="3" shadow-samples="3"/>
            </scene>
            """;

    /** What a run printed and returned. */
    record Run(int exitCode, String out, String err) {
        List<String> errLines() {
            return err.lines().toList();
        }
    }

    static Run run(boolean terminal, String... args) {
        return run(terminal, EncoderWarmUp::start, args);
    }

    /** As {@link #run(boolean, String...)}, with the PNG encoder's set-up that {@code encoderSetUp} starts. */
    static Run run(boolean terminal, Supplier<EncoderWarmUp> encoderSetUp, String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int code = RenderCommand.commandLine(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), terminal, encoderSetUp).execute(args);
        return new Run(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    static Run run(String... args) {
        return run(false, args);
    }

    /**
     * Starts the jar's entry point in a new JVM with this JVM's Java, the classes and picocli, in
     * {@code dir}, its output to dir/stdout.txt and dir/stderr.txt.
     */
    static Process startJava(Path dir, String heap, String... args) throws IOException {
        return startJava(dir, List.of(heap), args);
    }

    /** {@link #startJava(Path, String, String...)} with any options of the JVM's. */
    static Process startJava(Path dir, List<String> jvmOptions, String... args) throws IOException {
        String classPath = location(RenderCommand.class) + File.pathSeparator + location(CommandLine.class);
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        command.addAll(jvmOptions);
        command.addAll(List.of("-cp", classPath, MAIN_CLASS));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).directory(dir.toFile())
                .redirectOutput(dir.resolve("stdout.txt").toFile()).redirectError(dir.resolve("stderr.txt").toFile()).start();
    }

    /** {@link #startJava} and waits (at most a minute) for the end. */
    static Run runJava(Path dir, String heap, String... args) throws IOException, InterruptedException {
        return finished(dir, startJava(dir, heap, args));
    }

    /** What a process started by {@link #startJava} printed and returned, once it has ended. */
    static Run finished(Path dir, Process process) throws IOException, InterruptedException {
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).as("the command ends").isTrue();
        return new Run(process.exitValue(), Files.readString(dir.resolve("stdout.txt")),
                Files.readString(dir.resolve("stderr.txt")));
    }

    private static String location(Class<?> type) {
        try {
            return Path.of(type.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
