package app.migrate;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/** The checks before anything changes: each refuses in one line, naming what is in the way. */
final class Preflight {
    private Preflight() {
    }

    /**
     * What an earlier run left in {@code course-backup/}: nothing (go on), a finished migration
     * with no course class back (true: already migrated), or a refusal.
     */
    static boolean alreadyMigrated(Path d, List<SourceFile> course) throws MigrationException {
        Path backup = d.resolve(Layout.BACKUP);
        if (Files.isDirectory(backup) && !Files.exists(d.resolve(Manifest.FILE))) Folders.deleteTemporaries(d);
        if (!Files.exists(backup) || Folders.isEmpty(backup)) return false; // empty: a run stopped before it wrote anything
        Manifest.State state = Manifest.stateOf(d);
        if (state == Manifest.State.APPLYING || state == Manifest.State.UNDOING)
            throw new MigrationException("a " + (state == Manifest.State.APPLYING ? "migration" : "--undo") + " of " + d
                    + " was stopped part-way (" + Manifest.FILE + " lists what is left to take back): run raytracer migrate --undo "
                    + d + " to put everything back, then migrate again (nothing was changed)");
        if (state == null)
            throw new MigrationException(backup + " is already there, and not from raytracer migrate: rename or remove it,"
                    + " then run migrate again (nothing was changed)");
        if (course.isEmpty()) return true;
        throw new MigrationException(d + " was migrated before (" + Manifest.FILE + "), and has course classes again ("
                + course.get(0).relative(d) + "): undo the earlier migration first (raytracer migrate --undo " + d
                + "), or move " + Layout.BACKUP + "/ away (nothing was changed)");
    }

    static void requireCleanGit(Path d) throws MigrationException {
        String status;
        try {
            Process git = new ProcessBuilder("git", "-C", d.toString(), "status", "--porcelain", "--", ".")
                    .redirectErrorStream(false).start();
            git.getOutputStream().close();
            try (InputStream stdout = git.getInputStream(); InputStream stderr = git.getErrorStream()) {
                status = new String(stdout.readAllBytes(), StandardCharsets.UTF_8);
                stderr.readAllBytes();
            }
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
    static void requireNames(Path d, List<SourceFile> files) throws MigrationException {
        for (SourceFile f : files) {
            String problem = Inside.formProblem(f.relative(d));
            if (problem != null)
                throw new MigrationException(f.relative(d).replace("\t", "\\t").replace("\n", "\\n").replace("\r", "\\r")
                        + " is " + problem + ": rename it, then migrate (nothing was changed)");
        }
    }

    /** A pom of the student's that cannot be updated is said before the compile, not after it. */
    static void requireReadablePom(Layout layout) throws MigrationException {
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
    static void requireInside(Path d, Layout layout) throws MigrationException {
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

    static void requireWritable(Path d, List<SourceFile> files, Layout layout) throws MigrationException {
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

    /** JUnit 5's API, from the Maven repository or the project's own lib/: the tests compile against it. */
    static void requireJUnit(Toolchain tools, List<Path> junit, Layout layout) throws MigrationException {
        if (junit.isEmpty() && layout.jars().stream().noneMatch(j -> j.getFileName().toString().startsWith("junit-jupiter-api")
                && Files.isRegularFile(j)))
            throw new MigrationException("JUnit 5 is not in " + tools.mavenRepository() + " and Maven could not fetch it"
                    + " (offline?): run mvn -q install in the library's clone first (its tests fetch JUnit), then migrate again");
    }
}
