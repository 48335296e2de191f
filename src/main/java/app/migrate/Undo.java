package app.migrate;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.List;

/** Takes back a migration, as its manifest records it, refusing when a file changed since. */
final class Undo {
    private Undo() {
    }

    /** With the project's lock held. */
    static void undo(Path d, Faults faults, PrintStream out, PrintStream progress) throws MigrationException {
        Path backup = d.resolve(Layout.BACKUP);
        boolean noManifest = !Files.exists(d.resolve(Manifest.FILE), LinkOption.NOFOLLOW_LINKS);
        if (noManifest && Files.isDirectory(backup, LinkOption.NOFOLLOW_LINKS)) Folders.deleteTemporaries(d);
        if (noManifest && Files.isDirectory(backup, LinkOption.NOFOLLOW_LINKS) && Folders.isEmpty(backup)) {
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
        try (StopHook stopped = new StopHook(progress, "--undo of " + d + " was stopped part-way: run raytracer migrate --undo " + d
                + " again to finish it")) {
            List<String> conflicts = manifest.conflicts();
            if (!conflicts.isEmpty()) {
                String shown = conflicts.size() <= 5 ? String.join("; ", conflicts)
                        : String.join("; ", conflicts.subList(0, 5)) + "; and " + (conflicts.size() - 5) + " more";
                throw new MigrationException("cannot undo the migration of " + d + ": " + shown
                        + " (nothing was changed; put them back, or undo by hand from " + Layout.BACKUP + "/)");
            }
            manifest.undoAll();
            Files.deleteIfExists(d.resolve(Manifest.FILE));
            Files.deleteIfExists(d.resolve(Plan.REPORT));
            Manifest.deleteTemporariesInBackup(d);
            Folders.deleteEmpty(d.resolve(Layout.BACKUP));
        } catch (IOException | RuntimeException e) {
            throw new MigrationException("undo of " + d + " stopped part-way: " + (e.getMessage() == null ? e.toString() : e.getMessage())
                    + " (" + Manifest.FILE + " lists what is left; run raytracer migrate --undo " + d + " again to finish)", e, true);
        }
        long moved = taken.stream().filter(e -> e.kind().equals(Manifest.Entry.MOVE)).count();
        long folders = taken.stream().filter(e -> e.kind().equals(Manifest.Entry.MKDIR)).count();
        out.println("raytracer migrate --undo: " + d + " is as it was before the migration (" + moved + " files moved back, "
                + (taken.size() - moved - folders) + " restored or removed)");
    }
}
