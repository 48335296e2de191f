package app.migrate;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/** The folders a migration and its undo leave behind: emptied ones go, a stopped run's temporaries too. */
final class Folders {
    private Folders() {
    }

    /** Deletes the empty folders under {@code top} (deepest first), and {@code top} itself when it empties and is the backup. */
    static void deleteEmpty(Path top) throws IOException {
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

    /** Whether {@code folder} holds nothing; an unreadable one is taken as not empty, so nothing is decided on it. */
    static boolean isEmpty(Path folder) {
        try (Stream<Path> in = Files.list(folder)) {
            return in.findAny().isEmpty();
        } catch (IOException e) {
            return false;
        }
    }

    /** A run stopped while it wrote its first manifest left only its temporary file in course-backup/. */
    static void deleteTemporaries(Path d) throws MigrationException {
        try {
            Manifest.deleteTemporariesInBackup(d);
        } catch (IOException e) {
            throw new MigrationException("cannot read " + d.resolve(Layout.BACKUP) + ": " + e.getMessage(), e);
        }
    }
}
