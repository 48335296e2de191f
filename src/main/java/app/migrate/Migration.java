package app.migrate;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

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
 * Every file's new text is worked out before anything is written ({@link Changes}): a dry run
 * prints them as a unified diff, a real run writes exactly those ({@link Apply}). A failure while
 * changing files takes back what was changed; {@link #undo} takes back a whole migration, refusing
 * when a file changed since. This class only runs the steps in order; each lives in its own class
 * ({@link Preflight}, {@link Planner}, {@link SourceRewrite}, {@link PomPatterns}, {@link Report},
 * {@link Apply}, {@link Undo}), none of which calls back here.
 */
public final class Migration {
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
     * @throws MigrationException when the library this command runs with cannot be located or read
     */
    public static Migration ofThisProcess(PrintStream out, PrintStream progress) throws MigrationException {
        try {
            return new Migration(Toolchain.ofThisProcess(), Migration.class.getClassLoader(), out, progress);
        } catch (RuntimeException e) { // a -Dmaven.repo.local that is no path, say: not the student's folder's name
            throw unexpected(e);
        }
    }

    /**
     * Migrates the project in {@code dir}, printing its summary.
     *
     * @param dir        the course project's folder
     * @param allowDirty go on despite uncommitted changes in a git folder
     * @param dryRun     print what would change, as a unified diff; change nothing
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
     * @param dryRun     print what would change, as a unified diff; change nothing
     * @param encoding   the sources' character encoding ({@code windows-1255}), or null: as the
     *                   project states it, else detected
     * @return true when it changed the project; false when there was nothing to do (already migrated)
     * @throws MigrationException refused or taken back, with the one line to print; nothing changed
     */
    public boolean migrate(Path dir, boolean allowDirty, boolean dryRun, String encoding) throws MigrationException {
        try {
            if (dryRun) return migrateHeld(dir, allowDirty, true, encoding);
            Path d = dir.toAbsolutePath().normalize();
            if (!Files.isDirectory(d)) throw new MigrationException(d + " is not a folder");
            try (RunLock held = RunLock.take(d)) {
                return migrateHeld(dir, allowDirty, false, encoding);
            }
        } catch (InvalidPathException e) {
            throw e; // a name this locale cannot hold: the command says so in its own words
        } catch (RuntimeException e) {
            throw unexpected(e);
        }
    }

    /**
     * An unchecked exception that reached here (javac's, the JDK's, one of ours): {@link Apply}
     * and {@link Undo} take back or say how to finish whatever they changed and throw a
     * {@link MigrationException} for it, so one that gets here came before any change.
     */
    private static MigrationException unexpected(RuntimeException e) {
        return new MigrationException("failed before changing anything: " + Javac.oneLine(String.valueOf(e))
                + " (nothing was changed; please report it with the command you ran)", e);
    }

    /** The migration, with the project's lock held unless it is a dry run. */
    private boolean migrateHeld(Path dir, boolean allowDirty, boolean dryRun, String encoding) throws MigrationException {
        Planned planned = planned(dir, allowDirty, dryRun, encoding);
        if (planned == null) return false;
        Path d = planned.project().layout().dir();
        if (dryRun) {
            out.println("raytracer migrate --dry-run: nothing changed; a migration would do this:");
            planned.report().forEach(out::println);
            out.println();
            out.println("The exact change, as a unified diff (paths relative to " + d + "; git apply takes it):");
            out.flush();
            out.writeBytes(UnifiedDiff.bytes(planned.changes()));
            out.flush();
            return false;
        }
        Apply.apply(d, planned.changes(), Apply.emptiedRoots(planned.plan()), faults, progress);
        planned.report().forEach(out::println);
        return true;
    }

    /**
     * A migration worked out whole, nothing written yet.
     *
     * @param project what was read of the project
     * @param plan    what it decided
     * @param report  the summary
     * @param changes every file it changes, with the text it leaves, in order
     */
    record Planned(Project project, Plan plan, List<String> report, List<Change> changes) {
    }

    /**
     * Reads the project, checks it and works out every change, writing nothing into it.
     *
     * @return null when it is already migrated (said on {@code out})
     */
    Planned planned(Path dir, boolean allowDirty, boolean dryRun, String encoding) throws MigrationException {
        Layout named = Layout.read(dir, tools.mavenRepository());
        Path d = named.dir();
        Preflight.requireInside(d, named);
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
        Preflight.requireNames(d, files);
        Preflight.requireReadablePom(layout);
        Catalog.Sorted sorted = catalog.sort(files);
        List<SourceFile> course = sorted.course();

        if (Preflight.alreadyMigrated(d, course)) {
            out.println("raytracer migrate: " + d + " is already migrated (" + Manifest.FILE
                    + "); nothing changed. Undo: raytracer migrate --undo " + d);
            return null;
        }
        if (course.isEmpty())
            throw new MigrationException(d + " has no course class the library provides (such as primitives.Point or"
                    + " renderer.Camera, in " + Layout.names(d, layout.mainRoots()) + "): nothing to migrate");
        if (!allowDirty && !dryRun) Preflight.requireCleanGit(d);
        if (!dryRun) Preflight.requireWritable(d, files, layout);
        List<Path> junit = new ArrayList<>(tools.junitFetchedIfMissing());
        Preflight.requireJUnit(tools, junit, layout);

        List<Libraries.Library> libraries = Libraries.of(d, tools.mavenRepository(), layout.jars(), files);
        Map<Libraries.Library, Path> resolved = Libraries.resolved(libraries, d, tools, progress);
        if (libraries.stream().anyMatch(l -> l.artifact().equals("junit") && l.group().equals("junit")))
            tools.fetchIfMissing("org.hamcrest:hamcrest-core:1.3").ifPresent(junit::add);
        Project project = new Project(layout, charset, strays, libraries, resolved, sorted.relocated());

        Plan plan;
        try (Scratch scratch = new Scratch()) {
            plan = new Planner(tools, progress).plan(project, course, sorted.extras(), sorted.tests(), junit, scratch.dir);
        } catch (IOException e) {
            throw new MigrationException("cannot compile in a scratch folder: " + e.getMessage(), e);
        }
        Changes.Draft draft = Changes.of(project, plan);
        List<String> report = Report.lines(d, project, plan, draft.pomChanges(), tools);
        return new Planned(project, plan, report, draft.withReport(report));
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
            Undo.undo(d, faults, out, progress);
        } catch (InvalidPathException e) {
            throw e;
        } catch (RuntimeException e) {
            throw unexpected(e);
        }
    }
}
