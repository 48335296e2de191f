package app.migrate;

import java.io.ByteArrayOutputStream;
import java.nio.file.Path;

/**
 * A JVM that migrates the project in {@code args[0]} with the clean-tree check asked for, and
 * prints the refusal's line: run by {@code MigrationTest} with a PATH that has no git.
 */
final class MigrateWithoutGit {
    private MigrateWithoutGit() {
    }

    public static void main(String[] args) {
        Path dir = Path.of(args[0]);
        try {
            CourseProjects.migration(dir, new ByteArrayOutputStream(), new ByteArrayOutputStream()).migrate(dir, false, false);
            System.out.println("migrated");
        } catch (MigrationException e) {
            System.out.println(e.getMessage());
        }
    }
}
