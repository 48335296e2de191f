package app.migrate;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Makes a plan's changes, each written into the {@link Manifest} first, and nothing but them:
 * every text written is one the plan holds. A failure takes back what was changed.
 */
final class Apply {
    private Apply() {
    }

    /**
     * @param changes the plan's changes, the report last
     * @param emptied the source folders that moves empty: their emptied package folders go afterwards
     * @throws MigrationException part-way (what changed was taken back, or the one line saying how to)
     */
    static void apply(Path d, List<Change> changes, Set<Path> emptied, Faults faults, PrintStream progress) throws MigrationException {
        Manifest manifest = null;
        try (StopHook stopped = new StopHook(progress, "the migration of " + d + " was stopped part-way: run raytracer migrate --undo "
                + d + " to take back what it did")) {
            try {
                manifest = Manifest.begin(d, faults);
                for (Change c : changes) {
                    switch (c.kind()) {
                        case MOVE -> manifest.move(c.path(), c.to());
                        case REPLACE -> manifest.replace(c.path(), c.to(), c.backup(), c.bytes());
                        case CREATE -> {
                            if (!c.path().equals(Plan.REPORT)) {
                                manifest.create(c.path(), c.after());
                                continue;
                            }
                            // Not written down: the undo deletes the report by its name, after the manifest.
                            faults.reach("write " + Plan.REPORT);
                            Path reportFile = Inside.resolve(d, Plan.REPORT);
                            Manifest.write(reportFile, c.bytes(), reportFile, faults);
                        }
                    }
                }
                manifest.finish();
            } catch (IOException | RuntimeException e) {
                takeBack(d, manifest, e);
            }
        }
        for (Path root : emptied) {
            try {
                Folders.deleteEmpty(root);
            } catch (IOException e) {
                // an empty package folder left behind changes nothing in the build
            }
        }
    }

    /** After {@code e}: every change made taken back, the manifest and report gone; always throws, in one line. */
    private static void takeBack(Path d, Manifest manifest, Exception e) throws MigrationException {
        try {
            if (manifest != null) manifest.undoAll();
            Files.deleteIfExists(d.resolve(Manifest.FILE));
            Files.deleteIfExists(d.resolve(Plan.REPORT));
            Manifest.deleteTemporariesInBackup(d);
            Folders.deleteEmpty(d.resolve(Layout.BACKUP));
        } catch (IOException again) {
            e.addSuppressed(again);
            throw new MigrationException("the migration failed (" + e.getMessage() + ") and could not be taken back whole ("
                    + again.getMessage() + "): " + Manifest.FILE + " lists what is left; run raytracer migrate --undo " + d
                    + " to take it back", e, true);
        }
        throw new MigrationException("the migration failed and was taken back, nothing changed: "
                + (e.getMessage() == null ? e.toString() : e.getMessage()), e, true);
    }

    /** The folders the moved classes left: emptied package folders go, the source folder itself stays. */
    static Set<Path> emptiedRoots(Plan plan) {
        Set<Path> roots = new LinkedHashSet<>();
        plan.course().forEach(f -> roots.add(f.root()));
        plan.setAside().keySet().forEach(f -> roots.add(f.root()));
        return roots;
    }
}
