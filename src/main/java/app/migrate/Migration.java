package app.migrate;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * {@code raytracer migrate DIR}: a course project onto the library, with nothing lost.
 *
 * <ol>
 * <li>Reads the layout ({@link Layout}) and refuses, in one line and before anything changes, a
 * folder that is not a course project, one that does not compile as it is, one that cannot be
 * written, an earlier run's {@code course-backup/}, uncommitted git changes (unless allowed).</li>
 * <li>Names where the student's course classes chose otherwise than the library
 * ({@link CourseChoices}).</li>
 * <li>Compiles, in a scratch folder, the student's other classes (their extras) and then their
 * tests against the library, 2025–26's {@code api}/{@code impl} packages folded: an extra that
 * does not compile is set aside into {@code course-backup/set-aside/}, a test that does not is
 * left out of the build (excluded in the pom; the file stays where it is, untouched), each with
 * its reason ({@link Reasons}).</li>
 * <li>Moves the course classes the library provides into {@code course-backup/}, writes the pom
 * (and the IntelliJ module's library entry), records every change in the {@link Manifest}, and
 * prints the summary, also kept as {@code course-backup/migration-report.txt}.</li>
 * </ol>
 * A failure while changing files takes back what was changed; {@link #undo} takes back a whole
 * migration, refusing when a file changed since.
 */
public final class Migration {
    static final String REPORT = Layout.BACKUP + "/migration-report.txt";
    static final String SET_ASIDE = Layout.BACKUP + "/set-aside/";
    static final String ORIGINALS = Layout.BACKUP + "/originals/";
    /** Jars of a project's lib/ that are JUnit's (the pom's JUnit replaces them), by name prefix. */
    private static final List<String> TEST_FRAMEWORK_JARS = List.of("junit", "opentest4j", "apiguardian", "hamcrest");

    private final Toolchain tools;
    private final Catalog catalog;
    private final PrintStream out;
    /** Where each step says what it is doing (the compiles take seconds to a minute on a real project). */
    private final PrintStream progress;
    /** Where a test stops the run ({@link Faults#NONE} in a real one). */
    private final Faults faults;

    Migration(Toolchain tools, ClassLoader library, PrintStream out, PrintStream progress) {
        this(tools, library, out, progress, Faults.NONE);
    }

    /** As the other, with the run stopped where {@code faults} says (the crash tests). */
    Migration(Toolchain tools, ClassLoader library, PrintStream out, PrintStream progress, Faults faults) {
        this.tools = tools;
        this.catalog = new Catalog(library);
        this.out = out;
        this.progress = progress;
        this.faults = faults;
    }

    /**
     * @param out      where the summary goes
     * @param progress where each step is announced as it starts
     * @return a migration with the library this command runs with, JUnit from the local Maven repository
     */
    public static Migration ofThisProcess(PrintStream out, PrintStream progress) {
        return new Migration(Toolchain.ofThisProcess(), Migration.class.getClassLoader(), out, progress);
    }

    private void step(String what) {
        progress.println("raytracer migrate: " + what + "...");
    }

    /**
     * Migrates the project in {@code dir}, printing its summary.
     *
     * @param dir        the course project's folder
     * @param allowDirty go on despite uncommitted changes in a git folder
     * @param dryRun     print what would change, change nothing
     * @return true when it changed the project; false when there was nothing to do (already migrated)
     * @throws MigrationException refused or taken back, with the one line to print; nothing changed
     */
    public boolean migrate(Path dir, boolean allowDirty, boolean dryRun) throws MigrationException {
        return migrate(dir, allowDirty, dryRun, null);
    }

    /**
     * As {@link #migrate(Path, boolean, boolean)}, the sources read in the encoding named.
     *
     * @param dir        the course project's folder
     * @param allowDirty go on despite uncommitted changes in a git folder
     * @param dryRun     print what would change, change nothing
     * @param encoding   the sources' character encoding ({@code windows-1255}), or null: as the
     *                   project states it, else detected
     * @return true when it changed the project; false when there was nothing to do (already migrated)
     * @throws MigrationException refused or taken back, with the one line to print; nothing changed
     */
    public boolean migrate(Path dir, boolean allowDirty, boolean dryRun, String encoding) throws MigrationException {
        if (dryRun) return migrateHeld(dir, allowDirty, true, encoding);
        Path d = dir.toAbsolutePath().normalize();
        if (!Files.isDirectory(d)) throw new MigrationException(d + " is not a folder");
        try (RunLock held = RunLock.take(d)) {
            return migrateHeld(dir, allowDirty, false, encoding);
        }
    }

    /** The migration, with the project's lock held unless it is a dry run. */
    private boolean migrateHeld(Path dir, boolean allowDirty, boolean dryRun, String encoding) throws MigrationException {
        Layout named = Layout.read(dir, tools.mavenRepository());
        Path d = named.dir();
        requireInside(d, named);
        List<SourceFile> files;
        List<Path> strays;
        Layout layout;
        SourceEncoding charset;
        try {
            strays = named.strayTestRoots();
            layout = named.withTests(strays);
            charset = SourceEncoding.of(d, encoding, layout.javaFiles());
            files = layout.sources(charset.charset());
        } catch (IOException e) {
            throw new MigrationException("cannot read " + d + ": " + e.getMessage(), e);
        }
        requireNames(d, files);
        requireReadablePom(layout);
        List<SourceFile> tests = files.stream().filter(SourceFile::test).toList();
        // A course class kept in another course package (lighting.Material) goes as the library's
        // (primitives.Material); what stays is pointed at the library's.
        Map<String, String> relocated = new LinkedHashMap<>();
        files.stream().filter(f -> !f.test()).forEach(f -> {
            String to = catalog.relocated(f.className());
            // Only where the project has no class of the library's name: else this one is its own.
            if (to != null && files.stream().noneMatch(g -> Catalog.libraryName(g.className()).equals(to)))
                relocated.put(f.className(), to);
        });
        List<SourceFile> course = files.stream()
                .filter(f -> !f.test() && (catalog.provides(f.className()) || relocated.containsKey(f.className()))).toList();
        List<SourceFile> extras = files.stream().filter(f -> !f.test() && !course.contains(f)).toList();

        Path backup = d.resolve(Layout.BACKUP);
        if (Files.isDirectory(backup) && !Files.exists(d.resolve(Manifest.FILE))) deleteTemporaries(d);
        if (Files.exists(backup) && !isEmptyFolder(backup)) { // empty: a run stopped before it wrote anything
            Manifest.State state = Manifest.stateOf(d);
            if (state == Manifest.State.APPLYING || state == Manifest.State.UNDOING)
                throw new MigrationException("a " + (state == Manifest.State.APPLYING ? "migration" : "--undo") + " of " + d
                        + " was stopped part-way (" + Manifest.FILE + " lists what is left to take back): run raytracer migrate --undo "
                        + d + " to put everything back, then migrate again (nothing was changed)");
            if (state == null)
                throw new MigrationException(backup + " is already there, and not from raytracer migrate: rename or remove it,"
                        + " then run migrate again (nothing was changed)");
            if (course.isEmpty()) {
                out.println("raytracer migrate: " + d + " is already migrated (" + Manifest.FILE
                        + "); nothing changed. Undo: raytracer migrate --undo " + d);
                return false;
            }
            throw new MigrationException(d + " was migrated before (" + Manifest.FILE + "), and has course classes again ("
                    + relative(d, course.get(0)) + "): undo the earlier migration first (raytracer migrate --undo " + d
                    + "), or move " + Layout.BACKUP + "/ away (nothing was changed)");
        }
        if (course.isEmpty())
            throw new MigrationException(d + " has no course class the library provides (such as primitives.Point or"
                    + " renderer.Camera, in " + Layout.names(d, layout.mainRoots()) + "): nothing to migrate");
        if (!allowDirty && !dryRun) requireCleanGit(d);
        if (!dryRun) requireWritable(d, files, layout);
        List<Path> junit = new ArrayList<>(tools.junitFetchedIfMissing());
        if (junit.isEmpty() && layout.jars().stream().noneMatch(j -> j.getFileName().toString().startsWith("junit-jupiter-api")
                && Files.isRegularFile(j)))
            throw new MigrationException("JUnit 5 is not in " + tools.mavenRepository() + " and Maven could not fetch it"
                    + " (offline?): run mvn -q install in the library's clone first (its tests fetch JUnit), then migrate again");

        List<Libraries.Library> libraries = Libraries.of(d, tools.mavenRepository(), layout.jars(), files);
        Map<Libraries.Library, Path> resolved = new LinkedHashMap<>();
        for (Libraries.Library l : libraries) {
            Path jar = Libraries.jar(l, d, tools.mavenRepository()).orElse(null);
            if (jar == null) {
                step("fetching " + l.coordinates() + " (" + l.from() + ") with mvn");
                jar = tools.fetch(l.coordinates()).orElse(null);
            }
            if (jar != null) resolved.put(l, jar);
        }
        if (libraries.stream().anyMatch(l -> l.artifact().equals("junit") && l.group().equals("junit")))
            tools.fetchIfMissing("org.hamcrest:hamcrest-core:1.3").ifPresent(junit::add);
        Project project = new Project(layout, charset, strays, libraries, resolved, relocated);

        Plan plan;
        try (Scratch scratch = new Scratch()) {
            plan = plan(project, course, extras, tests, junit, scratch.dir);
        } catch (IOException e) {
            throw new MigrationException("cannot compile in a scratch folder: " + e.getMessage(), e);
        }
        List<String> report = plan.report(d, project, tools);
        if (dryRun) {
            out.println("raytracer migrate --dry-run: nothing changed; a migration would do this:");
            report.forEach(out::println);
            return false;
        }
        apply(d, plan, report, layout.iml());
        report.forEach(out::println);
        return true;
    }

    /**
     * Takes back the migration of {@code dir}, as its manifest records it.
     *
     * @param dir the folder migrated
     * @throws MigrationException when there is none, or a file changed since (all named; nothing changed)
     */
    public void undo(Path dir) throws MigrationException {
        Path d = dir.toAbsolutePath().normalize();
        if (!Files.isDirectory(d)) throw new MigrationException(d + " is not a folder");
        try (RunLock held = RunLock.take(d)) {
            undoHeld(d);
        }
    }

    private void undoHeld(Path d) throws MigrationException {
        Path backup = d.resolve(Layout.BACKUP);
        boolean noManifest = !Files.exists(d.resolve(Manifest.FILE), LinkOption.NOFOLLOW_LINKS);
        if (noManifest && Files.isDirectory(backup, LinkOption.NOFOLLOW_LINKS)) deleteTemporaries(d);
        if (noManifest && Files.isDirectory(backup, LinkOption.NOFOLLOW_LINKS) && isEmptyFolder(backup)) {
            try {
                Files.delete(backup); // a migration stopped before its manifest was written: all it made
            } catch (IOException e) {
                throw new MigrationException("cannot remove the empty " + backup + ": " + e.getMessage(), e);
            }
            out.println("raytracer migrate --undo: " + d + " is as it was before the migration (it was stopped before it"
                    + " changed anything; its empty " + Layout.BACKUP + "/ removed)");
            return;
        }
        Manifest manifest = Manifest.load(d, faults);
        List<Manifest.Entry> taken = manifest.entries();
        Thread stopped = whenStopped("--undo of " + d + " was stopped part-way: run raytracer migrate --undo " + d + " again to finish it");
        try {
            List<String> conflicts = manifest.conflicts();
            if (!conflicts.isEmpty()) {
                String shown = conflicts.size() <= 5 ? String.join("; ", conflicts)
                        : String.join("; ", conflicts.subList(0, 5)) + "; and " + (conflicts.size() - 5) + " more";
                throw new MigrationException("cannot undo the migration of " + d + ": " + shown
                        + " (nothing was changed; put them back, or undo by hand from " + Layout.BACKUP + "/)");
            }
            manifest.undoAll();
            Files.deleteIfExists(d.resolve(Manifest.FILE));
            Files.deleteIfExists(d.resolve(REPORT));
            Manifest.deleteTemporariesInBackup(d);
            deleteEmptyFolders(d.resolve(Layout.BACKUP));
        } catch (IOException e) {
            throw new MigrationException("undo of " + d + " stopped part-way: " + e.getMessage()
                    + " (" + Manifest.FILE + " lists what is left; run raytracer migrate --undo " + d + " again to finish)", e, true);
        } finally {
            removeHook(stopped);
        }
        long moved = taken.stream().filter(e -> e.kind().equals(Manifest.Entry.MOVE)).count();
        long folders = taken.stream().filter(e -> e.kind().equals(Manifest.Entry.MKDIR)).count();
        out.println("raytracer migrate --undo: " + d + " is as it was before the migration (" + moved + " files moved back, "
                + (taken.size() - moved - folders) + " restored or removed)");
    }

    /**
     * Says in one line what to run when the JVM is stopped (Ctrl-C, a kill that lets it end)
     * while the files change; the manifest, written before each change, makes that possible.
     */
    private Thread whenStopped(String line) {
        Thread hook = new Thread(() -> progress.println("raytracer migrate: " + line), "raytracer migrate: stopped");
        Runtime.getRuntime().addShutdownHook(hook);
        return hook;
    }

    private static void removeHook(Thread hook) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is ending: the hook runs, and its line is what the user needs
        }
    }

    /** A run stopped while it wrote its first manifest left only its temporary file in course-backup/. */
    private static void deleteTemporaries(Path d) throws MigrationException {
        try {
            Manifest.deleteTemporariesInBackup(d);
        } catch (IOException e) {
            throw new MigrationException("cannot read " + d.resolve(Layout.BACKUP) + ": " + e.getMessage(), e);
        }
    }

    private static boolean isEmptyFolder(Path folder) {
        try (Stream<Path> in = Files.list(folder)) {
            return in.findAny().isEmpty();
        } catch (IOException e) {
            return false;
        }
    }


    // ===== the plan: everything decided in a scratch folder before the project changes =====

    /** What was read of the project before the plan: its layout, encoding and libraries. */
    private record Project(Layout layout, SourceEncoding encoding, List<Path> strays, List<Libraries.Library> libraries,
            Map<Libraries.Library, Path> resolved, Map<String, String> relocated) {
    }

    /** A file that stays, with its text after the 2025–26 packages are folded, and where it goes. */
    private record Kept(SourceFile file, String text, Path target) {
        boolean changed() {
            return !text.equals(file.text()) || !target.equals(file.path());
        }
    }

    /** Everything a migration will do and say. */
    private record Plan(List<SourceFile> course, List<Kept> extras, Map<SourceFile, String> setAside, List<Kept> tests,
            Map<SourceFile, String> leftOut, Map<SourceFile, String> trimmed, List<CourseChoices.Choice> choices,
            BuildPlan build) {
        List<String> report(Path d, Project project, Toolchain tools) {
            Layout layout = project.layout;
            List<String> r = new ArrayList<>();
            r.add("raytracer migrate: " + d + " (" + layout.kind().label + ": " + Layout.names(d, layout.mainRoots())
                    + (layout.testRoots().isEmpty() ? "" : "; tests " + Layout.names(d, layout.testRoots()))
                    + "; Java release " + build.release() + "; sources in " + project.encoding.describe() + ")");
            if (!project.strays.isEmpty())
                r.add("Tests found outside the folders your build names, now test folders: " + Layout.names(d, project.strays));
            if (!project.libraries.isEmpty()) {
                r.add("Your libraries, now dependencies in pom.xml: " + project.libraries.size());
                project.libraries.forEach(l -> r.add("  " + l.describe() + (project.resolved.containsKey(l) ? ""
                        : l.systemPath() != null ? "; not in the project (never committed?): left out of pom.xml"
                        : "; not in " + tools.mavenRepository() + ", and mvn could not fetch it now (mvn test will try again)")));
            }
            if (!choices.isEmpty()) {
                r.add("Where your code chose otherwise than the library (docs/student-guide.md, \"Which course year?\"):");
                choices.forEach(c -> r.add("  " + c.line()));
            }
            List<SourceFile> courses = course.stream().filter(f -> Catalog.isCourseClass(f.className())).toList();
            List<SourceFile> namesakes = course.stream().filter(f -> !Catalog.isCourseClass(f.className())).toList();
            r.add("Moved to " + Layout.BACKUP + "/ (the library provides them): " + courses.size() + " classes");
            Map<String, List<String>> byPackage = new TreeMap<>();
            courses.forEach(f -> byPackage.computeIfAbsent(f.packageName(), p -> new ArrayList<>()).add(f.simpleName()
                    + (project.relocated.containsKey(f.className()) ? " (as the library's " + project.relocated.get(f.className()) + ")"
                            : "")));
            byPackage.forEach((p, names) -> r.add("  " + (p.isEmpty() ? "(no package)" : p) + ": " + String.join(", ", names)));
            if (!namesakes.isEmpty())
                r.add("Moved to " + Layout.BACKUP + "/ too (your own classes, named as classes inside the library, beside which they"
                        + " cannot stay; the library's BVH is always on in place of one of yours): " + String.join(", ",
                                namesakes.stream().map(SourceFile::className).toList()));
            List<Kept> keptCourse = extras.stream().filter(k -> Catalog.isCourseClassInCoursePackage(k.file.className())).toList();
            if (!keptCourse.isEmpty()) {
                r.add("Kept (course classes the library has no class for; they compile against it): " + keptCourse.size());
                keptCourse.forEach(k -> r.add("  " + d.relativize(k.target).toString().replace('\\', '/')));
            }
            r.add("Kept (your own classes; they compile against the library): " + (extras.size() - keptCourse.size()));
            extras.stream().filter(k -> !keptCourse.contains(k))
                    .forEach(k -> r.add("  " + d.relativize(k.target).toString().replace('\\', '/')));
            if (!setAside.isEmpty()) {
                r.add("Set aside into " + SET_ASIDE + " (they do not compile against the library): " + setAside.size());
                setAside.forEach((f, why) -> r.add("  " + why));
            }
            r.add("Tests kept: " + tests.size() + " files" + (leftOut.isEmpty() ? "" : "; left out of the build (the files"
                    + " stay where they are, excluded in pom.xml): " + leftOut.size()));
            leftOut.forEach((f, why) -> r.add("  " + why));
            if (tests.isEmpty() && leftOut.isEmpty())
                r.add("Warning: no JUnit test was found in this project (none in " + Layout.names(d, layout.mainRoots())
                        + (layout.testRoots().isEmpty() ? "" : ", " + Layout.names(d, layout.testRoots())) + " or any other folder):"
                        + " mvn test will run none; if your tests are elsewhere, name that folder in your .iml or pom and migrate again");
            if (!trimmed.isEmpty()) {
                r.add("Tests kept with some of their methods left out (each replaced by a comment line naming why): "
                        + trimmed.size() + " files");
                trimmed.forEach((f, why) -> r.add("  " + why));
            }
            long rewritten = Stream.concat(extras.stream(), tests.stream()).filter(Kept::changed).count();
            if (rewritten > 0)
                r.add("Rewritten (package and import lines pointed at the library's classes, or test methods taken out as said above): " + rewritten
                        + " files (originals in " + ORIGINALS + ")");
            r.add("pom.xml: " + (layout.pom() == null ? "written" : "updated") + " (" + build.library() + ", JUnit "
                    + build.junit() + ", Java release " + build.release() + ", every test class runs whatever its name)");
            if (layout.iml() != null)
                r.add(d.relativize(layout.iml()) + ": the library jar added (from " + tools.mavenRepository() + ")");
            if (!Files.isRegularFile(tools.installedJar())) {
                // Without it, mvn test ends in Maven's "Could not find artifact": the step comes first.
                r.add("The library is not installed in " + tools.mavenRepository() + " yet (mvn test would say \"Could not find"
                        + " artifact " + tools.coordinates() + "\"); install it first, and again after pulling a newer version:");
                r.add("  cd " + tools.libraryClone().map(Path::toString).orElse("<the raytracer clone>") + " && mvn -q install -DskipTests");
            }
            r.add("Next: cd " + d + " && mvn test   (IntelliJ: Build > Rebuild Project, then run your tests)");
            r.add("Undo: raytracer migrate --undo " + d + (Files.isDirectory(d.resolve(".git"))
                    ? "   (or with git: git status lists every change)" : ""));
            return r;
        }
    }

    private Plan plan(Project project, List<SourceFile> course, List<SourceFile> extras, List<SourceFile> tests,
            List<Path> junit, Path scratch) throws IOException, MigrationException {
        Layout layout = project.layout;
        Path d = layout.dir();
        Charset charset = project.encoding.charset();
        Javac javac = new Javac(charset);
        int jdk = tools.jdk();
        // JUnit 5 as the project's build had it (its lib/), and the project's other libraries.
        List<Path> projectJars = new ArrayList<>(layout.jars().stream()
                .filter(j -> isTestFramework(j) && Files.isRegularFile(j)).toList());
        projectJars.addAll(project.resolved.values());

        // 1. The project as it is must compile (else its errors would be blamed on the library).
        step("compiling " + d.getFileName() + " as it is (" + (course.size() + extras.size()) + " classes, " + tests.size()
                + " test files)");
        List<String> missing = project.libraries.stream().filter(l -> !project.resolved.containsKey(l))
                .map(Libraries.Library::describe).toList();
        AsIsCheck.require(javac, tools.jdk(), d, course, extras, tests, junit, projectJars, missing, scratch);

        List<CourseChoices.Choice> choices = new ArrayList<>(CourseChoices.find(course, tests, d));
        choices.addAll(CourseProbes.find(scratch.resolve(AsIsCheck.MAIN_CLASSES), course, tests, d));

        // 2. The extras against the library, folded and staged; those that fail are set aside.
        Map<String, String> own = new LinkedHashMap<>();
        course.forEach(f -> own.putIfAbsent(f.simpleName(), f.text()));
        List<Kept> keptExtras = extras.stream().map(f -> kept(f, project.relocated)).toList();
        Map<Path, Kept> staged = stage(keptExtras, d, scratch.resolve("stage-main"), charset);
        step("compiling your " + extras.size() + " own classes against the library");
        List<Path> libraryPath = new ArrayList<>(List.of(tools.library()));
        libraryPath.addAll(nonJUnit(projectJars));
        Javac.Outcome main = javac.compile(staged.keySet(), libraryPath, jdk, scratch.resolve("main"));
        Map<String, String> setAsideNames = new LinkedHashMap<>();
        main.failed().keySet().forEach(p -> setAsideNames.put(staged.get(p).file.simpleName(),
                "it does not compile against the library (" + SET_ASIDE + ")"));
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
            Kept k = kept(f, project.relocated);
            String name = namesakes.stream().filter(n -> mentions(k.text, n) > 0).findFirst().orElse(null);
            if (name == null) {
                keptTests.add(k);
                continue;
            }
            String why = "it uses your own " + name + ", moved to " + Layout.BACKUP + "/: the library has a class of that name inside"
                    + " it, which this test would run against instead";
            TestMethods.Trimmed t = TestMethods.without(k.text, linesMentioning(k.text, namesakes), why);
            if (t == null) {
                leftOutFirst.put(f, f.relative(d) + ":" + mentions(k.text, name) + ": " + why);
                continue;
            }
            keptTests.add(new Kept(f, t.text(), k.target));
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
            TestMethods.Trimmed t = TestMethods.without(k.text, e.getValue().stream().map(Javac.Problem::line).toList(),
                    reasons.explain(first, true));
            if (t == null) continue;
            Files.write(e.getKey(), t.text().getBytes(charset));
            retried.put(e.getKey(), new Kept(k.file, t.text(), k.target));
            trimmedLines.put(e.getKey(), trimmedLine(k.file, d, t, first.line() + ": " + reasons.explain(first, true)));
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
                    trimmed.put(retried.get(p).file, trimmedLines.get(p));
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
                buildPlan(project, extras, tests, leftOut.keySet(), release, d));
    }

    /** The summary's line for a test file kept without some of its methods. */
    private static String trimmedLine(SourceFile f, Path d, TestMethods.Trimmed t, String why) {
        int n = t.removed().size();
        return f.relative(d) + ": " + n + " test method" + (n == 1 ? "" : "s") + " left out (" + String.join("(), ", t.removed())
                + "()), the rest kept: " + why;
    }

    /** The first line (1-based) where {@code name} stands as a word in {@code text}, 0 when nowhere. */
    private static long mentions(String text, String name) {
        Matcher m = Pattern.compile("\\b" + Pattern.quote(name) + "\\b").matcher(text);
        return m.find() ? text.substring(0, m.start()).chars().filter(c -> c == '\n').count() + 1 : 0;
    }

    /** Every line (1-based) where one of {@code names} stands as a word. */
    private static List<Long> linesMentioning(String text, Set<String> names) {
        List<Long> lines = new ArrayList<>();
        long n = 0;
        for (String line : text.split("\n", -1)) {
            n++;
            for (String name : names)
                if (Pattern.compile("\\b" + Pattern.quote(name) + "\\b").matcher(line).find()) {
                    lines.add(n);
                    break;
                }
        }
        return lines;
    }

    /**
     * The file with 2025–26's {@code geometries.api/impl} and {@code lighting.api/impl} folded and
     * relocated course classes named as the library's, and its new place.
     */
    private static Kept kept(SourceFile f, Map<String, String> relocated) {
        String text = relocate(fold(f.text()), f.packageName(), relocated);
        Path target = f.path();
        String pkg = Catalog.libraryPackage(f.packageName());
        if (!pkg.equals(f.packageName()) && f.path().getParent().equals(f.root().resolve(f.packageName().replace('.', '/')))) {
            Path moved = f.root().resolve(pkg.replace('.', '/')).resolve(f.path().getFileName());
            if (!Files.exists(moved)) target = moved;
        }
        return new Kept(f, text, target);
    }

    static String fold(String text) {
        return text.replaceAll("(?m)^(\\s*(?:package|import)\\s+(?:static\\s+)?)(geometries|lighting)\\.(?:api|impl)\\s*;", "$1$2;")
                .replaceAll("\\b(geometries|lighting)\\.(?:api|impl)\\.", "$1.");
    }

    /**
     * {@code import lighting.Material;} becomes {@code import primitives.Material;} (and so does a
     * qualified use); a file that reached the class unqualified (in its package, or through
     * {@code import lighting.*;}) gets the library's import after its package line.
     */
    static String relocate(String text, String pkg, Map<String, String> relocated) {
        String t = text;
        for (Map.Entry<String, String> e : relocated.entrySet()) {
            String from = Catalog.libraryName(e.getKey()), to = e.getValue();
            String fromPkg = from.substring(0, from.lastIndexOf('.')), simple = from.substring(from.lastIndexOf('.') + 1);
            t = fold(t).replaceAll("\\b" + Pattern.quote(from) + "\\b", to);
            boolean unqualified = Catalog.libraryPackage(pkg).equals(fromPkg)
                    || Pattern.compile("(?m)^\\s*import\\s+" + Pattern.quote(fromPkg) + "\\.\\*\\s*;").matcher(t).find();
            if (!unqualified || !Pattern.compile("\\b" + Pattern.quote(simple) + "\\b").matcher(t).find()
                    || t.contains("import " + to + ";"))
                continue;
            Matcher p = Pattern.compile("(?m)^\\s*package\\s+[\\w.]+\\s*;[^\\n]*\\n").matcher(t);
            String line = "import " + to + ";\n";
            t = p.find() ? t.substring(0, p.end()) + line + t.substring(p.end()) : line + t;
        }
        return t;
    }

    /** Writes the files, as they will be, under {@code stage} at their paths in the project. */
    private static Map<Path, Kept> stage(List<Kept> files, Path d, Path stage, Charset charset) throws IOException {
        Map<Path, Kept> staged = new LinkedHashMap<>();
        for (Kept k : files) {
            Path p = stage.resolve(d.relativize(k.target).toString()).toAbsolutePath().normalize();
            Files.createDirectories(p.getParent());
            Files.write(p, k.text.getBytes(charset));
            staged.put(p, k);
        }
        return staged;
    }

    private static Map<SourceFile, String> explain(Map<Path, List<Javac.Problem>> failed, Map<Path, Kept> staged,
            Reasons reasons, Path d) {
        Map<SourceFile, String> lines = new LinkedHashMap<>();
        failed.forEach((p, problems) -> {
            SourceFile f = staged.get(p).file;
            Javac.Problem first = problems.get(0);
            lines.put(f, f.relative(d) + ":" + first.line() + ": " + reasons.explain(first, f.test())
                    + (problems.size() > 1 ? " (and " + (problems.size() - 1) + " more)" : ""));
        });
        return lines;
    }

    private BuildPlan buildPlan(Project project, List<SourceFile> extras, List<SourceFile> tests, Set<SourceFile> leftOut,
            int release, Path d) {
        Layout layout = project.layout;
        List<String> mainRoots = layout.mainRoots().stream().map(r -> rel(d, r)).toList();
        Set<Path> testRootPaths = new LinkedHashSet<>(layout.testRoots());
        tests.forEach(t -> testRootPaths.add(t.root()));
        List<String> testRoots = testRootPaths.stream().filter(r -> tests.stream().anyMatch(t -> t.root().equals(r)))
                .map(r -> rel(d, r)).toList();
        // Tests in a folder that also holds sources: out of the main compile, and the only part of
        // that folder the test compile takes.
        List<SourceFile> mixed = tests.stream().filter(t -> layout.mainRoots().contains(t.root())).toList();
        List<SourceFile> all = new ArrayList<>(extras);
        all.addAll(tests);
        List<String> mainExcludes = patterns(mixed, all);
        List<String> testIncludes = mixed.isEmpty() ? List.of() : patterns(tests, all);
        List<String> testExcludes = leftOut.stream().map(SourceFile::inRoot).sorted().toList();
        boolean junit4 = Libraries.JUnit4.usedBy(tests);
        return new BuildPlan(tools.coordinates(), tools.junitVersion(), release, mainRoots, testRoots, mainExcludes,
                testIncludes, testExcludes, project.libraries.stream().filter(l -> l.systemPath() == null || project.resolved.containsKey(l))
                        .toList(), junit4, project.encoding.charset().name());
    }

    /** Patterns for {@code chosen} within their folders: {@code unittests/**} where a whole top folder is chosen. */
    static List<String> patterns(List<SourceFile> chosen, List<SourceFile> all) {
        Set<String> out = new LinkedHashSet<>();
        for (SourceFile f : chosen) {
            String inRoot = f.inRoot();
            int slash = inRoot.indexOf('/');
            if (slash < 0) {
                out.add(inRoot);
                continue;
            }
            String top = inRoot.substring(0, slash + 1);
            boolean whole = all.stream().filter(a -> a.root().equals(f.root()) && a.inRoot().startsWith(top))
                    .allMatch(chosen::contains);
            out.add(whole ? top + "**" : inRoot);
        }
        return List.copyOf(out);
    }

    private static boolean isTestFramework(Path jar) {
        String name = jar.getFileName().toString();
        return TEST_FRAMEWORK_JARS.stream().anyMatch(name::startsWith);
    }

    // ===== applying the plan =====

    private void apply(Path d, Plan plan, List<String> report, Path imlFile) throws MigrationException {
        Manifest manifest = null;
        Thread stopped = whenStopped("the migration of " + d + " was stopped part-way: run raytracer migrate --undo " + d
                + " to take back what it did");
        try {
            manifest = Manifest.begin(d, faults);
            for (SourceFile f : plan.course) manifest.move(f.relative(d), Layout.BACKUP + "/" + f.relative(d));
            for (SourceFile f : plan.setAside.keySet()) manifest.move(f.relative(d), SET_ASIDE + f.relative(d));
            for (Kept k : Stream.concat(plan.extras.stream(), plan.tests.stream()).filter(Kept::changed).toList())
                manifest.replace(k.file.relative(d), rel(d, k.target), ORIGINALS + k.file.relative(d),
                        k.text.getBytes(Charset.forName(plan.build.encoding())));
            Path pom = d.resolve("pom.xml");
            if (Files.isRegularFile(pom)) {
                PomFile.Updated updated = PomFile.update(Files.readString(pom, StandardCharsets.UTF_8), plan.build);
                manifest.replace("pom.xml", "pom.xml", ORIGINALS + "pom.xml", updated.text());
            } else {
                manifest.create("pom.xml", PomFile.create(plan.build, d.getFileName().toString()));
            }
            // The module file read before the course classes moved (a project of course classes
            // only has no source left to read a layout from).
            if (imlFile != null) {
                String iml = Files.readString(imlFile, StandardCharsets.UTF_8);
                String added = ImlFile.addLibrary(iml, plan.build);
                if (added != null && !added.equals(iml))
                    manifest.replace(rel(d, imlFile), rel(d, imlFile), ORIGINALS + rel(d, imlFile), added);
            }
            Path compilerXml = d.resolve(".idea/compiler.xml");
            if (Files.isDirectory(d.resolve(".idea")) && !plan.leftOut.isEmpty()) {
                List<String> leftOut = plan.leftOut.keySet().stream().map(f -> f.relative(d)).toList();
                if (Files.isRegularFile(compilerXml)) {
                    String xml = Files.readString(compilerXml, StandardCharsets.UTF_8);
                    manifest.replace(".idea/compiler.xml", ".idea/compiler.xml", ORIGINALS + ".idea/compiler.xml",
                            ImlFile.exclude(xml, leftOut));
                } else {
                    manifest.create(".idea/compiler.xml", ImlFile.exclude(null, leftOut));
                }
            }
            faults.reach("write " + REPORT);
            Path reportFile = Inside.resolve(d, REPORT);
            Manifest.write(reportFile, (String.join("\n", report) + "\n").getBytes(StandardCharsets.UTF_8), reportFile, faults);
            manifest.finish();
        } catch (IOException | MigrationException | RuntimeException e) {
            try {
                if (manifest != null) manifest.undoAll();
                Files.deleteIfExists(d.resolve(Manifest.FILE));
                Files.deleteIfExists(d.resolve(REPORT));
                Manifest.deleteTemporariesInBackup(d);
                deleteEmptyFolders(d.resolve(Layout.BACKUP));
            } catch (IOException again) {
                e.addSuppressed(again);
                throw new MigrationException("the migration failed (" + e.getMessage() + ") and could not be taken back whole ("
                        + again.getMessage() + "): " + Manifest.FILE + " lists what is left; run raytracer migrate --undo " + d + " to take it back", e, true);
            }
            throw new MigrationException("the migration failed and was taken back, nothing changed: "
                    + (e.getMessage() == null ? e.toString() : e.getMessage()), e, true);
        } finally {
            removeHook(stopped);
        }
        for (Path root : emptiedRoots(d, plan)) {
            try {
                deleteEmptyFolders(root);
            } catch (IOException e) {
                // an empty package folder left behind changes nothing in the build
            }
        }
    }

    /** The folders the moved classes left: emptied package folders go, the source folder itself stays. */
    private static Set<Path> emptiedRoots(Path d, Plan plan) {
        Set<Path> roots = new LinkedHashSet<>();
        plan.course.forEach(f -> roots.add(f.root()));
        plan.setAside.keySet().forEach(f -> roots.add(f.root()));
        return roots;
    }

    /** Deletes the empty folders under {@code top} (deepest first), and {@code top} itself when it empties. */
    private static void deleteEmptyFolders(Path top) throws IOException {
        if (!Files.isDirectory(top)) return;
        List<Path> dirs;
        try (Stream<Path> walk = Files.walk(top)) {
            dirs = walk.filter(Files::isDirectory).sorted((a, b) -> b.getNameCount() - a.getNameCount()).toList();
        }
        for (Path dir : dirs) {
            try (Stream<Path> in = Files.list(dir)) {
                if (in.findAny().isEmpty() && (!dir.equals(top) || top.getFileName().toString().equals(Layout.BACKUP)))
                    Files.delete(dir);
            }
        }
    }

    // ===== the checks before anything changes =====

    private static void requireCleanGit(Path d) throws MigrationException {
        String status;
        try {
            Process git = new ProcessBuilder("git", "-C", d.toString(), "status", "--porcelain", "--", ".")
                    .redirectErrorStream(false).start();
            git.getOutputStream().close();
            status = new String(git.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            git.getErrorStream().readAllBytes();
            if (!git.waitFor(30, TimeUnit.SECONDS) || git.exitValue() != 0) return; // not a git folder
        } catch (IOException e) {
            // No git on the PATH: where the project is in a git folder, its state cannot be
            // checked, which is said rather than skipped; elsewhere there is nothing to compare with.
            for (Path p = d; p != null; p = p.getParent())
                if (Files.exists(p.resolve(".git")))
                    throw new MigrationException(d + " is in a git folder (" + p.resolve(".git") + "), but git is not on the PATH to"
                            + " check it has no uncommitted changes: install git, or run with --allow-dirty (nothing was changed)");
            return;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new MigrationException("interrupted while asking git for the folder's state (nothing was changed)", e);
        }
        if (!status.isBlank()) {
            long n = status.lines().count();
            throw new MigrationException(d + " has uncommitted changes (" + n + " in git status): commit or stash them first,"
                    + " so that git can show and take back what the migration changes, or pass --allow-dirty (nothing was changed)");
        }
    }

    /**
     * Refuses a project with a source whose path the manifest cannot hold (a tab or a line break
     * in a folder's name), before anything changes.
     */
    private static void requireNames(Path d, List<SourceFile> files) throws MigrationException {
        for (SourceFile f : files) {
            String problem = Inside.formProblem(f.relative(d));
            if (problem != null)
                throw new MigrationException(f.relative(d).replace("\t", "\\t").replace("\n", "\\n").replace("\r", "\\r")
                        + " is " + problem + ": rename it, then migrate (nothing was changed)");
        }
    }

    /** A pom of the student's that cannot be updated is said before the compile, not after it. */
    private static void requireReadablePom(Layout layout) throws MigrationException {
        if (layout.pom() == null) return;
        try {
            PomFile.check(Files.readString(layout.pom(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new MigrationException("cannot read " + layout.pom() + ": " + e.getMessage(), e);
        }
    }

    /**
     * Refuses a project whose source folders lie outside it ({@code $MODULE_DIR$/../shared-src} in
     * an {@code .iml}, {@code <sourceDirectory>../shared</sourceDirectory>}, or a link out): the
     * migration moves and rewrites files in them, and it changes nothing outside the project.
     */
    private static void requireInside(Path d, Layout layout) throws MigrationException {
        for (Path root : Stream.concat(layout.mainRoots().stream(), layout.testRoots().stream()).toList()) {
            boolean inside;
            try {
                inside = Inside.contains(d, root);
            } catch (IOException e) {
                throw new MigrationException("cannot read " + root + ": " + e.getMessage(), e);
            }
            if (!inside)
                throw new MigrationException("the source folder " + root + (layout.iml() != null ? " (of " + d.relativize(layout.iml()) + ")"
                        : layout.pom() != null ? " (of pom.xml)" : "") + " lies outside " + d + ": raytracer migrate changes files inside"
                        + " the project only; move the folder into it, or migrate the folder that holds both (nothing was changed)");
        }
    }

    private static void requireWritable(Path d, List<SourceFile> files, Layout layout) throws MigrationException {
        Set<Path> need = new LinkedHashSet<>();
        need.add(d);
        files.forEach(f -> need.add(f.path().getParent()));
        if (layout.pom() != null) need.add(layout.pom());
        if (layout.iml() != null) need.add(layout.iml());
        for (Path p : need)
            if (!Files.isWritable(p))
                throw new MigrationException("cannot write " + p + " (read-only): the migration moves and writes files there;"
                        + " nothing was changed");
    }

    /** javac's message in one line: {@code cannot find symbol (symbol: method f(), location: class A)}. */
    static String oneLine(String message) {
        List<String> lines = message.lines().map(String::strip).filter(l -> !l.isEmpty()).toList();
        return lines.isEmpty() ? "" : lines.get(0) + (lines.size() > 1 ? " (" + String.join(", ", lines.subList(1, lines.size())).replaceAll("\\s+", " ") + ")" : "");
    }

    private static String rel(Path d, Path p) {
        String r = d.relativize(p).toString().replace('\\', '/');
        return r.isEmpty() ? "." : r;
    }

    private static String relative(Path d, SourceFile f) {
        return f.relative(d);
    }

    private static List<Path> nonJUnit(List<Path> jars) {
        return jars.stream().filter(j -> !isTestFramework(j)).toList();
    }

    /** A scratch folder for the compile checks, deleted afterwards. */
    private static final class Scratch implements AutoCloseable {
        /** Its name's start, then the process's id: a folder of a process that is gone (killed) is stale. */
        private static final String SCRATCH = "raytracer-migrate-";
        private static final Pattern STALE = Pattern.compile(Pattern.quote(SCRATCH) + "(\\d+)-.*");
        final Path dir;

        /** The scratch folders of earlier runs that were killed (their process is gone): removed. */
        private static void deleteStaleScratch() {
            try (Stream<Path> in = Files.list(Path.of(System.getProperty("java.io.tmpdir")))) {
                for (Path p : in.toList()) {
                    Matcher m = STALE.matcher(p.getFileName().toString());
                    if (m.matches() && Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)
                            && ProcessHandle.of(Long.parseLong(m.group(1))).isEmpty())
                        Javac.deleteTree(p);
                }
            } catch (IOException | NumberFormatException e) {
                // another user's folder, or a name too long for a process id: left to the system
            }
        }

        Scratch() throws MigrationException {
            try {
                deleteStaleScratch();
                dir = Files.createTempDirectory(SCRATCH + ProcessHandle.current().pid() + "-");
            } catch (IOException e) {
                throw new MigrationException("cannot make a scratch folder: " + e.getMessage(), e);
            }
        }

        @Override
        public void close() {
            try {
                Javac.deleteTree(dir);
            } catch (IOException e) {
                // a scratch folder in the temporary folder: the system cleans it
            }
        }
    }
}
