package app.migrate;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.Charset;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Decides, in a scratch folder, what a migration does: the project compiled as it is, then its
 * extras and tests against the library, each set aside or left out with its reason where it does
 * not compile, and the lowest Java release at which all that stays compiles.
 */
final class Planner {
    /** Jars of a project's lib/ that are JUnit's (the pom's JUnit replaces them), by name prefix. */
    private static final List<String> TEST_FRAMEWORK_JARS = List.of("junit", "opentest4j", "apiguardian", "hamcrest");

    private final Toolchain tools;
    /** Where each step says what it is doing (the compiles take seconds to a minute on a real project). */
    private final PrintStream progress;

    Planner(Toolchain tools, PrintStream progress) {
        this.tools = tools;
        this.progress = progress;
    }

    private void step(String what) {
        progress.println("raytracer migrate: " + what + "...");
    }

    Plan plan(Project project, List<SourceFile> course, List<SourceFile> extras, List<SourceFile> tests, List<Path> junit,
            Path scratch) throws IOException, MigrationException {
        Layout layout = project.layout();
        Path d = layout.dir();
        Charset charset = project.encoding().charset();
        Javac javac = new Javac(charset);
        int jdk = tools.jdk();
        // JUnit 5 as the project's build had it (its lib/), and the project's other libraries.
        List<Path> projectJars = new ArrayList<>(layout.jars().stream()
                .filter(j -> isTestFramework(j) && Files.isRegularFile(j)).toList());
        projectJars.addAll(project.resolved().values());

        // 1. The project as it is must compile (else its errors would be blamed on the library).
        step("compiling " + d.getFileName() + " as it is (" + (course.size() + extras.size()) + " classes, " + tests.size()
                + " test files)");
        List<String> missing = project.libraries().stream().filter(l -> !project.resolved().containsKey(l))
                .map(Libraries.Library::describe).toList();
        AsIsCheck.require(javac, tools.jdk(), d, course, extras, tests, junit, projectJars, missing, scratch);

        List<CourseChoices.Choice> choices = new ArrayList<>(CourseChoices.find(course, tests, d));
        choices.addAll(CourseProbes.find(scratch.resolve(AsIsCheck.MAIN_CLASSES), course, tests, d));

        // 2. The extras against the library, folded and staged; those that fail are set aside.
        Map<String, String> own = new LinkedHashMap<>();
        course.forEach(f -> own.putIfAbsent(f.simpleName(), f.text()));
        List<Kept> keptExtras = new ArrayList<>();
        for (SourceFile f : extras) keptExtras.add(SourceRewrite.kept(f, project.relocated()));
        Map<Path, Kept> staged = stage(keptExtras, d, scratch.resolve("stage-main"), charset);
        step("compiling your " + extras.size() + " own classes against the library");
        List<Path> libraryPath = new ArrayList<>(List.of(tools.library()));
        libraryPath.addAll(projectJars.stream().filter(j -> !isTestFramework(j)).toList());
        Javac.Outcome main = javac.compile(staged.keySet(), libraryPath, jdk, scratch.resolve("main"));
        Map<String, String> setAsideNames = new LinkedHashMap<>();
        main.failed().keySet().forEach(p -> setAsideNames.put(staged.get(p).file().simpleName(),
                "it does not compile against the library (" + Plan.SET_ASIDE + ")"));
        Reasons reasons = new Reasons(own, setAsideNames, jdk);
        Map<SourceFile, String> setAside = explain(main.failed(), staged, reasons, d);

        // 3. The tests against the library and the kept extras; those that fail are left out.
        // A test of a class of the student's that is named as one inside the library (their BVH's
        // BoundingBox) would compile against the library's and test it instead: such methods go,
        // or the whole file where they cannot be told apart.
        Set<String> namesakes = new LinkedHashSet<>();
        course.stream().filter(f -> !Catalog.isCourseClass(f.className())).forEach(f -> namesakes.add(f.simpleName()));
        Map<SourceFile, String> trimmed = new LinkedHashMap<>();
        Map<SourceFile, String> leftOutFirst = new LinkedHashMap<>();
        List<Kept> keptTests = new ArrayList<>();
        for (SourceFile f : tests) {
            Kept k = SourceRewrite.kept(f, project.relocated());
            List<Long> lines = namesakes.isEmpty() ? List.of() : JavaNames.lines(k.text(), f.relative(d), namesakes);
            if (lines.isEmpty()) {
                keptTests.add(k);
                continue;
            }
            // The first namesake the file names, by the list's order: the one the summary names.
            String name = null;
            long first = 0;
            for (String n : namesakes) {
                first = JavaNames.firstLine(k.text(), f.relative(d), n);
                if (first > 0) {
                    name = n;
                    break;
                }
            }
            String why = "it uses your own " + name + ", moved to " + Layout.BACKUP + "/: the library has a class of that name inside"
                    + " it, which this test would run against instead";
            TestMethods.Trimmed t = TestMethods.without(k.text(), f.relative(d), lines, why);
            if (t == null) {
                leftOutFirst.put(f, f.relative(d) + ":" + first + ": " + why);
                continue;
            }
            keptTests.add(new Kept(f, t.text(), k.target()));
            trimmed.put(f, trimmedLine(f, d, t, why));
        }
        Map<Path, Kept> stagedTests = stage(keptTests, d, scratch.resolve("stage-test"), charset);
        step("compiling your " + tests.size() + " test files against the library");
        List<Path> testPath = new ArrayList<>(libraryPath);
        testPath.add(scratch.resolve("main"));
        testPath.addAll(junit);
        testPath.addAll(projectJars);
        Javac.Outcome test = javac.compile(stagedTests.keySet(), testPath, jdk, scratch.resolve("test"));
        // A test file whose errors all lie in some of its test methods keeps the others: those
        // methods give way to a comment line (the original kept in originals/), and the file is
        // compiled again with the rest; one that still fails is left out whole, as before.
        Map<Path, List<Javac.Problem>> failedTests = new LinkedHashMap<>(test.failed());
        Map<Path, Kept> retried = new LinkedHashMap<>();
        Map<Path, String> trimmedLines = new LinkedHashMap<>();
        for (Map.Entry<Path, List<Javac.Problem>> e : test.failed().entrySet()) {
            Kept k = stagedTests.get(e.getKey());
            Javac.Problem first = e.getValue().get(0);
            TestMethods.Trimmed t = TestMethods.without(k.text(), k.file().relative(d), e.getValue().stream().map(Javac.Problem::line).toList(),
                    reasons.explain(first, true));
            if (t == null) continue;
            Files.write(e.getKey(), t.text().getBytes(charset));
            retried.put(e.getKey(), new Kept(k.file(), t.text(), k.target()));
            trimmedLines.put(e.getKey(), trimmedLine(k.file(), d, t, first.line() + ": " + reasons.explain(first, true)));
        }
        if (!retried.isEmpty()) {
            step("compiling " + retried.size() + " of your test files again without the test methods that do not compile");
            List<Path> again = new ArrayList<>(test.compiled());
            again.addAll(retried.keySet());
            Javac.Outcome second = javac.compile(again, testPath, jdk, scratch.resolve("test"));
            for (Path p : second.compiled())
                if (retried.containsKey(p)) {
                    failedTests.remove(p);
                    stagedTests.put(p, retried.get(p));
                    trimmed.put(retried.get(p).file(), trimmedLines.get(p));
                }
            // A trimmed file that still fails is left out whole, for the first reason it had.
            second.failed().forEach(failedTests::putIfAbsent);
            test = second;
        }
        Map<SourceFile, String> leftOut = new LinkedHashMap<>(leftOutFirst);
        leftOut.putAll(explain(failedTests, stagedTests, reasons, d));

        // 4. The lowest release of 17, 21 and this JDK's at which all that stays compiles.
        List<Kept> extrasKept = main.compiled().stream().map(staged::get).toList();
        List<Kept> testsKept = test.compiled().stream().map(stagedTests::get).toList();
        int release = jdk;
        step("finding the Java release your code needs");
        for (int candidate : new int[] { 17, 21 }) {
            if (candidate >= jdk) break;
            Javac.Outcome m = javac.compile(main.compiled(), libraryPath, candidate, scratch.resolve("r-main"));
            if (!m.failed().isEmpty()) continue;
            List<Path> path = new ArrayList<>(testPath);
            path.set(path.indexOf(scratch.resolve("main")), scratch.resolve("r-main"));
            if (javac.compile(test.compiled(), path, candidate, scratch.resolve("r-test")).failed().isEmpty()) {
                release = candidate;
                break;
            }
        }
        return new Plan(course, extrasKept, setAside, testsKept, leftOut, trimmed, choices,
                PomPatterns.buildPlan(tools, project, extras, tests, leftOut.keySet(), release));
    }

    /** The summary's line for a test file kept without some of its methods. */
    private static String trimmedLine(SourceFile f, Path d, TestMethods.Trimmed t, String why) {
        int n = t.removed().size();
        return f.relative(d) + ": " + n + " test method" + (n == 1 ? "" : "s") + " left out (" + String.join("(), ", t.removed())
                + "()), the rest kept: " + why;
    }

    /** Writes the files, as they will be, under {@code stage} at their paths in the project. */
    private static Map<Path, Kept> stage(List<Kept> files, Path d, Path stage, Charset charset) throws IOException {
        Map<Path, Kept> staged = new LinkedHashMap<>();
        for (Kept k : files) {
            Path p = stage.resolve(d.relativize(k.target()).toString()).toAbsolutePath().normalize();
            Files.createDirectories(p.getParent());
            Files.write(p, k.text().getBytes(charset));
            staged.put(p, k);
        }
        return staged;
    }

    private static Map<SourceFile, String> explain(Map<Path, List<Javac.Problem>> failed, Map<Path, Kept> staged,
            Reasons reasons, Path d) {
        Map<SourceFile, String> lines = new LinkedHashMap<>();
        failed.forEach((p, problems) -> {
            SourceFile f = staged.get(p).file();
            Javac.Problem first = problems.get(0);
            lines.put(f, f.relative(d) + ":" + first.line() + ": " + reasons.explain(first, f.test())
                    + (problems.size() > 1 ? " (and " + (problems.size() - 1) + " more)" : ""));
        });
        return lines;
    }

    private static boolean isTestFramework(Path jar) {
        String name = jar.getFileName().toString();
        return TEST_FRAMEWORK_JARS.stream().anyMatch(name::startsWith);
    }
}
