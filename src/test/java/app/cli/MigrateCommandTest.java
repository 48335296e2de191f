package app.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code raytracer migrate} as the command line runs it: exit codes and one-line refusals. */
class MigrateCommandTest {
    @TempDir
    Path dir;

    @Test
    @DisplayName("a folder that is not a course project: exit 2, one line naming it")
    void notAProject() throws IOException {
        Files.writeString(dir.resolve("notes.txt"), "hello");
        Cli.Run run = Cli.run("migrate", dir.toString());
        assertThat(run.exitCode()).isEqualTo(RenderCommand.BAD_INPUT);
        assertThat(run.errLines()).singleElement().asString()
                .startsWith("raytracer migrate: " + dir.toRealPath() + " is not a course project");
    }

    @Test
    @DisplayName("--undo of a folder never migrated: exit 2, one line")
    void undoNothing() {
        Cli.Run run = Cli.run("migrate", "--undo", dir.toString());
        assertThat(run.exitCode()).isEqualTo(RenderCommand.BAD_INPUT);
        assertThat(run.errLines()).singleElement().asString().contains("nothing of raytracer migrate to undo");
    }

    @Test
    @DisplayName("under LANG=C, a project in a folder named in Hebrew: exit 2, one line with the command's prefix saying to use a UTF-8 locale")
    void asciiLocale() throws Exception {
        // the course project of the migration's integration test, in a folder named in Hebrew
        Path project = Files.createDirectories(dir.resolve("\u05E4\u05E8\u05D5\u05D9\u05E7\u05D8"));
        Path course = app.Project.file("src/it/migrate/course");
        try (var files = Files.walk(course)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                Path to = project.resolve(course.relativize(f).toString());
                Files.createDirectories(to.getParent());
                Files.copy(f, to);
            }
        }
        ProcessBuilder child = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), Main.class.getName(), "migrate", "--allow-dirty", project.toString());
        child.environment().put("LANG", "C");
        child.environment().put("LC_ALL", "C");
        child.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        Process java = child.start();
        String err = new String(java.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(java.waitFor()).as(err).isEqualTo(RenderCommand.BAD_INPUT);
        assertThat(project.resolve("course-backup")).doesNotExist();
        assertThat(err.lines().toList()).singleElement().asString()
                .startsWith("raytracer migrate: cannot name ").endsWith("run it with a UTF-8 locale, such as LANG=C.UTF-8 (nothing was changed)");
    }

    @Test
    @DisplayName("--dry-run: exit 0, the summary then the exact change as a unified diff, and nothing changed")
    void dryRun() throws IOException {
        Path course = app.Project.file("src/it/migrate/course");
        try (var files = Files.walk(course)) {
            for (Path f : files.filter(Files::isRegularFile).toList()) {
                Path to = dir.resolve(course.relativize(f).toString());
                Files.createDirectories(to.getParent());
                Files.copy(f, to);
            }
        }
        Cli.Run run = Cli.run("migrate", "--dry-run", dir.toString());
        assertThat(run.exitCode()).as(run.err()).isZero();
        assertThat(run.out()).startsWith("raytracer migrate --dry-run: nothing changed; a migration would do this:\n")
                .contains("\nThe exact change, as a unified diff (paths relative to " + dir.toRealPath() + "; git apply takes it):\n"
                        + "diff --git a/src/geometries/Geometry.java b/course-backup/src/geometries/Geometry.java\n",
                        "diff --git a/pom.xml b/pom.xml\nnew file mode 100644\n");
        assertThat(dir.resolve("course-backup")).doesNotExist();
        assertThat(dir.resolve("pom.xml")).doesNotExist();
    }

    @Test
    @DisplayName("--help lists the options and the exit codes")
    void help() {
        Cli.Run run = Cli.run("migrate", "--help");
        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).contains("--undo", "--dry-run", "--allow-dirty", "course-backup/");
    }
}
