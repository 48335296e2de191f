package app.migrate;

import static app.migrate.CourseProjects.snapshot;
import static app.migrate.CourseProjects.write;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.DisabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code migrate} and {@code --undo} change files inside the project only, whoever prepared it: no
 * write through a link, no path of a manifest out of the project, no source folder outside it,
 * one run at a time; and what they restore comes back as it was, mode and links included.
 */
@DisabledOnOs(value = OS.WINDOWS, disabledReason = "links and POSIX modes")
class ConfinementTest {
    @TempDir
    Path root;
    /** The course project, inside {@link #root}. */
    private Path dir;
    /** A folder beside the project, which nothing may change. */
    private Path outside;
    private final ByteArrayOutputStream printed = new ByteArrayOutputStream();

    private Migration migration() {
        return CourseProjects.migration(dir, printed, new ByteArrayOutputStream());
    }

    @BeforeEach
    void project() throws IOException {
        dir = CourseProjects.intellij(Files.createDirectories(root.resolve("project")));
        outside = Files.createDirectories(root.resolve("outside"));
        write(outside, "victim.txt", "a file outside the project\n");
    }

    @Test
    @DisplayName("a link planted under the old temporary name of the pom is neither written through nor removed")
    void plantedTemporaryName() throws Exception {
        Files.createSymbolicLink(dir.resolve("pom.xml.migrate-tmp"), Path.of("../outside/victim.txt"));
        assertThat(migration().migrate(dir, true, false)).isTrue();
        assertThat(outside.resolve("victim.txt")).hasContent("a file outside the project");
        assertThat(Files.isSymbolicLink(dir.resolve("pom.xml.migrate-tmp"))).isTrue();
        assertThat(dir.resolve("pom.xml")).content().contains("<artifactId>raytracer</artifactId>");
    }

    @Test
    @DisplayName(".idea a link out of the project: its compiler.xml is not written there; the migration is taken back")
    void folderLinkOut() throws Exception {
        Files.move(dir.resolve(".idea"), outside.resolve(".idea"));
        Files.createSymbolicLink(dir.resolve(".idea"), Path.of("../outside/.idea"));
        Map<String, String> before = snapshot(dir), outsideBefore = snapshot(outside);
        assertThatThrownBy(() -> migration().migrate(dir, true, false)).isInstanceOf(MigrationException.class)
                .hasMessageContaining(".idea/compiler.xml lies outside " + dir);
        assertThat(snapshot(outside)).isEqualTo(outsideBefore);
        assertThat(snapshot(dir)).isEqualTo(before);
    }

    @Test
    @DisplayName("a source folder that is a link out of the project: refused before anything changes")
    void sourceFolderOut() throws Exception {
        Files.move(dir.resolve("src"), outside.resolve("shared-src"));
        Files.createSymbolicLink(dir.resolve("src"), Path.of("../outside/shared-src"));
        Map<String, String> outsideBefore = snapshot(outside);
        assertThatThrownBy(() -> migration().migrate(dir, true, false)).isInstanceOf(MigrationException.class)
                .hasMessageStartingWith("the source folder " + dir.resolve("src") + " (of course.iml) lies outside " + dir)
                .hasMessageEndingWith("(nothing was changed)");
        assertThat(snapshot(outside)).isEqualTo(outsideBefore);
        assertThat(dir.resolve("course-backup")).doesNotExist();
    }

    @Nested
    @DisplayName("--undo of a manifest that names a path out of the project")
    class CraftedManifest {
        @ParameterizedTest(name = "{0}")
        @ValueSource(strings = {"move\t../outside/victim.txt\tcourse-backup/x.java\t\t0",
                "move\tsrc/x.java\t/tmp/x.java\t\t0",
                "create\t../outside/victim.txt\t\t\t0",
                "replace\tpom.xml\tpom.xml\t../outside/victim.txt\t0",
                "create\tsrc/./x.java\t\t\t0",
                "move\t\tcourse-backup/x.java\t\t0"})
        @DisplayName("is refused in one line, and nothing changes inside or outside")
        void refused(String line) throws Exception {
            assertThat(migration().migrate(dir, true, false)).isTrue();
            Path manifest = dir.resolve(Manifest.FILE);
            Files.writeString(manifest, Files.readString(manifest) + line + "\n");
            Map<String, String> inside = snapshot(dir), outsideBefore = snapshot(outside);
            assertThatThrownBy(() -> migration().undo(dir)).isInstanceOf(MigrationException.class)
                    .hasMessageContaining(Manifest.FILE + " names ")
                    .hasMessageContaining("this manifest is not one raytracer migrate wrote (nothing was changed");
            assertThat(snapshot(dir)).isEqualTo(inside);
            assertThat(snapshot(outside)).isEqualTo(outsideBefore);
        }
    }

    @Test
    @DisplayName("a rewritten file keeps its mode, and --undo gives the original back with its own")
    void modes() throws Exception {
        Path iml = dir.resolve("course.iml");
        Files.setPosixFilePermissions(iml, PosixFilePermissions.fromString("rw-------"));
        assertThat(migration().migrate(dir, true, false)).isTrue();
        assertThat(iml).content().contains("raytracer");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(iml))).isEqualTo("rw-------");
        migration().undo(dir);
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(iml))).isEqualTo("rw-------");
    }

    @Test
    @DisplayName("a rewritten file that was a link: the link's file is not written through, and --undo puts the link back")
    void links() throws Exception {
        Path iml = dir.resolve("course.iml");
        write(dir, "config/course.iml", Files.readString(iml, StandardCharsets.UTF_8));
        String original = Files.readString(iml, StandardCharsets.UTF_8);
        Files.delete(iml);
        Files.createSymbolicLink(iml, Path.of("config/course.iml"));
        assertThat(migration().migrate(dir, true, false)).isTrue();
        assertThat(dir.resolve("config/course.iml")).hasContent(original.strip());
        assertThat(Files.isSymbolicLink(iml)).as("the rewritten .iml is a file of its own").isFalse();
        migration().undo(dir);
        assertThat(Files.isSymbolicLink(iml)).isTrue();
        assertThat(Files.readSymbolicLink(iml)).isEqualTo(Path.of("config/course.iml"));
        assertThat(Files.exists(iml, LinkOption.NOFOLLOW_LINKS)).isTrue();
    }

    @Test
    @DisplayName("the scratch folder of a killed run (its process gone) is removed by the next run; a live one's is not")
    void staleScratch() throws Exception {
        Process gone = new ProcessBuilder("true").start();
        gone.waitFor();
        Path tmp = Path.of(System.getProperty("java.io.tmpdir"));
        Path stale = Files.createDirectories(tmp.resolve("raytracer-migrate-" + gone.pid() + "-killed"));
        write(stale, "classes/Point.class", "x");
        Path live = Files.createDirectories(tmp.resolve("raytracer-migrate-" + ProcessHandle.current().pid() + "-running"));
        try {
            assertThat(migration().migrate(dir, true, true)).isFalse(); // a dry run compiles in a scratch folder too
            assertThat(stale).doesNotExist();
            assertThat(live).exists();
        } finally {
            Files.deleteIfExists(live);
        }
    }

    @Test
    @DisplayName("one run at a time: a second migrate or --undo of the project while one runs is refused, and changes nothing")
    void oneAtATime() throws Exception {
        Map<String, String> before = snapshot(dir);
        try (RunLock held = RunLock.take(dir)) {
            assertThatThrownBy(() -> migration().migrate(dir, true, false)).isInstanceOf(MigrationException.class)
                    .hasMessageStartingWith("another raytracer migrate is running on " + dir)
                    .hasMessageEndingWith("(nothing was changed)");
            assertThatThrownBy(() -> migration().undo(dir)).hasMessageStartingWith("another raytracer migrate is running on ");
            assertThat(snapshot(dir)).isEqualTo(before);
        }
        assertThat(migration().migrate(dir, true, false)).as("free again once the first run ends").isTrue();
    }
}
