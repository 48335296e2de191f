package app.migrate;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The check before anything changes that the project compiles as it is, with this JDK: else its
 * errors would be blamed on the library. A file that needs a newer Java than this JDK (a record
 * pattern in 2025–26's {@code Double3}, {@code List.getFirst}, the unnamed {@code _}) does not fail
 * it, nor does a file that fails only because of such a file: the migration names those later,
 * with the release they need, and replaces the course classes among them anyway. A refusal names
 * the first true cause.
 */
final class AsIsCheck {
    /** Where, under the scratch folder, the student's classes compiled as they are stay for the course probes. */
    static final String MAIN_CLASSES = "as-is-main";
    private static final Pattern MISSING_PACKAGE = Pattern.compile("package ([\\w.]+) does not exist");

    private AsIsCheck() {
    }

    /**
     * @param jdk              the release this JDK compiles for
     * @param jars             the project's libraries (and its own JUnit), as its build had them
     * @param missingLibraries the project's libraries this machine lacks, as the summary names them
     * @throws MigrationException naming the first file that does not compile and why (nothing changed)
     */
    static void require(Javac javac, int jdk, Path d, List<SourceFile> course, List<SourceFile> extras, List<SourceFile> tests,
            List<Path> junit, List<Path> jars, List<String> missingLibraries, Path scratch) throws IOException, MigrationException {
        List<Path> main = Stream.concat(course.stream(), extras.stream()).map(SourceFile::path).toList();
        Javac.Outcome m = javac.compile(main, jars, jdk, scratch.resolve(MAIN_CLASSES));
        List<Path> path = new ArrayList<>(List.of(scratch.resolve(MAIN_CLASSES)));
        path.addAll(junit);
        path.addAll(jars);
        Javac.Outcome t = javac.compile(tests.stream().map(SourceFile::path).toList(), path, jdk,
                scratch.resolve("as-is-test"));
        Map<Path, List<Javac.Problem>> failed = new LinkedHashMap<>(m.failed());
        failed.putAll(t.failed());
        // A file that needs a newer Java than this JDK's is named later, with its reason (a course
        // class among them is replaced by the library's anyway); so is a file that failed only
        // because such a file was left out, directly or through others: javac reports those as a
        // missing class or a missing package (every file of 2025-26's geometries.api left out).
        Map<Path, String> packages = new LinkedHashMap<>();
        Stream.of(course, extras, tests).flatMap(List::stream)
                .forEach(f -> packages.put(f.path().toAbsolutePath().normalize(), f.packageName()));
        Set<String> excused = new LinkedHashSet<>();
        Set<String> excusedPackages = new LinkedHashSet<>();
        failed.forEach((f, problems) -> {
            if (Reasons.releaseNeeded(problems.get(0)) > jdk) excuse(f, packages, excused, excusedPackages);
        });
        for (boolean grew = !excused.isEmpty(); grew;) {
            grew = false;
            for (Map.Entry<Path, List<Javac.Problem>> e : failed.entrySet())
                if (!excused.contains(className(e.getKey())) && knockOn(e.getValue().get(0), excused, excusedPackages)) {
                    excuse(e.getKey(), packages, excused, excusedPackages);
                    grew = true;
                }
        }
        for (Map.Entry<Path, List<Javac.Problem>> e : failed.entrySet()) {
            if (excused.contains(className(e.getKey()))) continue;
            Javac.Problem p = e.getValue().get(0);
            boolean syntax = p.code().startsWith("compiler.err.expected") || p.code().startsWith("compiler.err.illegal.start")
                    || p.code().startsWith("compiler.err.premature.eof") || p.code().startsWith("compiler.err.not.stmt");
            throw new MigrationException(d + " does not compile as it is (" + d.relativize(p.file()).toString().replace('\\', '/')
                    + ":" + p.line() + ": " + Javac.oneLine(p.message()) + "): fix it first"
                    + (syntax ? " (if that file is written for a Java newer than " + jdk + ", run migrate with that JDK)" : "")
                    // A library of the project this machine lacks is the likelier cause of a missing name.
                    + (!missingLibraries.isEmpty() && (p.code().startsWith("compiler.err.cant.resolve")
                            || p.code().startsWith("compiler.err.doesnt.exist"))
                            ? "; your libraries this machine does not have: " + String.join(", ", missingLibraries) : "")
                    + " (nothing was changed)");
        }
    }

    /** Records a file left out of the as-is check: its class, and its package as far as javac would miss it. */
    private static void excuse(Path file, Map<Path, String> packages, Set<String> excused, Set<String> excusedPackages) {
        excused.add(className(file));
        excusedPackages.add(packages.getOrDefault(file, ""));
    }

    /**
     * Whether a file's first error is the knock-on of files left out: it names one of their
     * classes, or a package of theirs ("package geometries.api does not exist").
     */
    private static boolean knockOn(Javac.Problem p, Set<String> excused, Set<String> excusedPackages) {
        Matcher missing = MISSING_PACKAGE.matcher(p.message());
        if (missing.find() && excusedPackages.stream().anyMatch(x -> x.equals(missing.group(1)) || x.startsWith(missing.group(1) + ".")))
            return true;
        return excused.stream().anyMatch(x -> Pattern.compile("\\b" + Pattern.quote(x) + "\\b").matcher(p.message()).find());
    }

    private static String className(Path file) {
        return file.getFileName().toString().replaceFirst("\\.java$", "");
    }
}
