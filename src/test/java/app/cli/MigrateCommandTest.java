package app.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
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
    @DisplayName("--help lists the options and the exit codes")
    void help() {
        Cli.Run run = Cli.run("migrate", "--help");
        assertThat(run.exitCode()).isZero();
        assertThat(run.out()).contains("--undo", "--dry-run", "--allow-dirty", "course-backup/");
    }
}
