package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.ByteArrayOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An unchecked exception (the JDK's, javac's, one of ours) never escapes the command's exit codes:
 * before any change it is a refusal (exit 2), while the files change it is taken back (exit 1),
 * each in one line.
 */
@DisplayName("migrate and --undo meeting an unchecked exception")
class UncheckedFailuresTest {
    @TempDir
    Path root;
    private Path dir;
    private Map<String, String> before;

    @BeforeEach
    void project() throws Exception {
        dir = CourseProjects.intellij(Files.createDirectories(root.resolve("course")));
        before = CrashTest.tree(dir);
    }

    /** A failure no one planned for, where the step named is reached. */
    private static Faults throwingAt(String step) {
        return reached -> {
            if (reached.equals(step)) throw new IllegalStateException("injected at " + reached);
        };
    }

    private Migration migration(Faults faults) {
        return CourseProjects.migration(dir, new ByteArrayOutputStream(), new ByteArrayOutputStream(), faults);
    }

    @Test
    @DisplayName("before any change (the library's classes cannot be asked for): a refusal in one line, exit 2, nothing changed")
    void beforeAnyChange() throws Exception {
        ClassLoader broken = new ClassLoader(null) {
            @Override
            protected Class<?> loadClass(String name, boolean resolve) {
                throw new IllegalStateException("class loader closed while asked for " + name);
            }
        };
        MigrationException e = catchThrowableOfType(() -> CourseProjects.migration(dir, new ByteArrayOutputStream(),
                new ByteArrayOutputStream(), Faults.NONE, broken).migrate(dir, true, false), MigrationException.class);
        assertThat(e.partWay()).as("exit 2").isFalse();
        assertThat(e.getMessage()).doesNotContain("\n").startsWith("failed before changing anything: java.lang.IllegalStateException:"
                + " class loader closed while asked for ").endsWith("(nothing was changed; please report it with the command you ran)");
        assertThat(CrashTest.tree(dir)).isEqualTo(before);
    }

    @Test
    @DisplayName("mid-apply (while the pom is written): taken back, in one line, exit 1, every byte as before")
    void midApply() throws Exception {
        MigrationException e = catchThrowableOfType(() -> migration(throwingAt("write pom.xml")).migrate(dir, true, false),
                MigrationException.class);
        assertThat(e.partWay()).as("exit 1").isTrue();
        assertThat(e.getMessage()).doesNotContain("\n")
                .isEqualTo("the migration failed and was taken back, nothing changed: injected at write pom.xml");
        assertThat(CrashTest.tree(dir)).isEqualTo(before);
    }

    @Test
    @DisplayName("mid-undo (while a class moves back): stopped part-way in one line, exit 1; --undo again finishes")
    void midUndo() throws Exception {
        assertThat(migration(Faults.NONE).migrate(dir, true, false)).isTrue();
        MigrationException e = catchThrowableOfType(() -> migration(throwingAt("move back course-backup/src/primitives/Point.java")).undo(dir),
                MigrationException.class);
        assertThat(e).as("the undo's steps name a move back of Point").isNotNull();
        assertThat(e.partWay()).as("exit 1").isTrue();
        assertThat(e.getMessage()).doesNotContain("\n").contains("stopped part-way: injected at move back course-backup/src/primitives/Point.java")
                .endsWith("run raytracer migrate --undo " + dir.toAbsolutePath().normalize() + " again to finish)");
        migration(Faults.NONE).undo(dir);
        assertThat(CrashTest.tree(dir)).isEqualTo(before);
    }
}
