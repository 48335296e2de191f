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

    /** What a run printed and returned. */
    record Run(int exitCode, String out, String err) {
        List<String> errLines() {
            return err.lines().toList();
        }
    }

    static Run run(boolean terminal, String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int code = RenderCommand.commandLine(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), terminal).execute(args);
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
        String classPath = location(RenderCommand.class) + File.pathSeparator + location(CommandLine.class);
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                heap, "-cp", classPath, MAIN_CLASS));
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
