package app.migrate;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * The JDK's own compiler, run in this process on a set of a project's files: which of them do not
 * compile, and why. Where one file's errors hide another's (javac stops after parse errors), the
 * failing files are left out and the rest compiled again, until what remains compiles.
 */
final class Javac {
    /** One compile error. {@code code} is javac's key ({@code compiler.err.cant.resolve.location.args}). */
    record Problem(Path file, long line, String code, String message, Charset encoding) {
        Problem(Path file, long line, String code, String message) {
            this(file, line, code, message, StandardCharsets.UTF_8);
        }

        /** The text of the line the error is on ({@code ""} when it cannot be read). */
        String sourceLine() {
            return sourceText(0);
        }

        /** The error's line and the {@code more} lines after it, joined by line breaks. */
        String sourceText(int more) {
            try {
                return line < 1 ? "" : String.join("\n", new String(Files.readAllBytes(file), encoding).lines().skip(line - 1)
                        .limit(more + 1L).toList());
            } catch (IOException e) {
                return ""; // the file was just compiled; unreadable now, its line is simply not shown
            }
        }
    }

    /** What a compile left: the files that compile, and per file left out its errors. */
    record Outcome(List<Path> compiled, Map<Path, List<Problem>> failed) {
    }

    private final JavaCompiler compiler;
    /** The project's source encoding: every file compiled is read in it. */
    private final Charset encoding;

    /**
     * @throws MigrationException when the running Java has no compiler (a JRE, not a JDK)
     */
    Javac(Charset encoding) throws MigrationException {
        this(encoding, ToolProvider.getSystemJavaCompiler());
    }

    /** With a given compiler: a test's, which fails the way the real one does when it runs out of memory. */
    Javac(Charset encoding, JavaCompiler compiler) throws MigrationException {
        this.encoding = encoding;
        this.compiler = compiler;
        if (compiler == null)
            throw new MigrationException("this Java (" + System.getProperty("java.home")
                    + ") has no compiler: run migrate with a JDK (17 or newer), as your IDE does");
    }

    /** javac's message in one line: {@code cannot find symbol (symbol: method f(), location: class A)}. */
    static String oneLine(String message) {
        List<String> lines = message.lines().map(String::strip).filter(l -> !l.isEmpty()).toList();
        return lines.isEmpty() ? "" : lines.get(0) + (lines.size() > 1 ? " (" + String.join(", ", lines.subList(1, lines.size())).replaceAll("\\s+", " ") + ")" : "");
    }

    /** The newest release this JDK compiles for. */
    static int newestRelease() {
        return Runtime.version().feature();
    }

    /**
     * Compiles {@code files} for {@code release}, leaving out the failing ones round by round.
     *
     * @param out where the classes go (a scratch folder)
     */
    Outcome compile(Collection<Path> files, List<Path> classPath, int release, Path out) throws IOException, MigrationException {
        Set<Path> remaining = new LinkedHashSet<>(files);
        Map<Path, List<Problem>> failed = new LinkedHashMap<>();
        while (!remaining.isEmpty()) {
            // A fresh folder each round: a failed round may have written some classes.
            deleteTree(out);
            Files.createDirectories(out);
            Map<Path, List<Problem>> errors = once(remaining, classPath, release, out);
            if (errors.isEmpty()) break;
            errors.forEach((file, problems) -> {
                remaining.remove(file);
                failed.put(file, problems);
            });
        }
        return new Outcome(List.copyOf(remaining), failed);
    }

    /** The refusal when javac runs out of memory: a fact about this process, not about the project's code. */
    private static MigrationException outOfMemory(Collection<Path> files, OutOfMemoryError cause) {
        Path largest = files.stream().max(Comparator.comparingLong(Javac::size)).orElse(null);
        String message = "javac ran out of memory (this Java's heap is " + Runtime.getRuntime().maxMemory() / (1024 * 1024)
                + " MB) compiling " + files.size() + " files" + (largest == null ? ""
                        : ", the largest " + largest.getFileName() + " (" + size(largest) / 1024 + " kB)")
                + ": run migrate with a larger heap, e.g. RAYTRACER_JAVA_OPTS=-Xmx2g (nothing was changed)";
        return cause == null ? new MigrationException(message) : new MigrationException(message, cause);
    }

    private static long size(Path file) {
        try {
            return Files.size(file);
        } catch (IOException e) {
            return 0; // only for naming the largest file; an unreadable one is not it
        }
    }

    static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) return;
        try (Stream<Path> walk = Files.walk(dir)) {
            for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) Files.delete(p);
        }
    }

    /** One javac run: the errors per file (none: everything compiled into {@code out}). */
    private Map<Path, List<Problem>> once(Collection<Path> files, List<Path> classPath, int release, Path out)
            throws IOException, MigrationException {
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager fm = compiler.getStandardFileManager(diagnostics, Locale.ROOT, encoding)) {
            List<String> options = new ArrayList<>(List.of("--release", Integer.toString(release), "-proc:none",
                    "-nowarn", "-Xlint:none", "-Xmaxerrs", "100000", "-encoding", encoding.name(), "-implicit:none",
                    "-sourcepath", "", "-d", out.toString()));
            // Always stated: left out, an in-process javac takes this JVM's own class path, where
            // the library's classes would stand in for the project's.
            options.add("-classpath");
            options.add(classPath.isEmpty() ? out.toString()
                    : String.join(File.pathSeparator, classPath.stream().map(Path::toString).toList()));
            Iterable<? extends JavaFileObject> units = fm.getJavaFileObjectsFromPaths(files);
            StringWriter chatter = new StringWriter();
            boolean compiled;
            try {
                compiled = compiler.getTask(chatter, fm, diagnostics, options, null, units).call();
            } catch (OutOfMemoryError e) {
                throw outOfMemory(files, e);
            }
            Map<Path, List<Problem>> errors = new LinkedHashMap<>();
            for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                if (d.getKind() != Diagnostic.Kind.ERROR) continue;
                if (d.getSource() == null)
                    throw new IOException("javac: " + d.getMessage(Locale.ROOT));
                Path file = Path.of(d.getSource().toUri()).toAbsolutePath().normalize();
                errors.computeIfAbsent(file, f -> new ArrayList<>())
                        .add(new Problem(file, d.getLineNumber(), d.getCode(), d.getMessage(Locale.ROOT), encoding));
            }
            // javac catches its own crash (out of memory among them), prints it to the chatter and
            // reports no error: taken as "compiled", every class would be missing for what follows.
            if (!compiled && errors.isEmpty()) {
                if (chatter.toString().contains("OutOfMemoryError")) throw outOfMemory(files, null);
                throw new MigrationException("javac stopped without naming an error while compiling " + files.size()
                        + " files: " + Javac.oneLine(chatter.toString()) + " (nothing was changed)");
            }
            return errors;
        }
    }
}
