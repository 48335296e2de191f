package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

/**
 * A migration or an undo stopped at any step, by a failure it sees or as a kill would stop it,
 * loses nothing: a failure is taken back at once; after a kill, {@code --undo} restores the
 * project byte for byte (an undo killed part-way finishes when run again). Every step where the
 * disk changes is a stop: each change written down, each folder made, each move, each copy of an
 * original, each write (the pom, the {@code .iml}, {@code .idea/compiler.xml}, the rewritten
 * sources, the report) and each rewrite of the manifest itself.
 */
@DisplayName("migrate and --undo stopped at every step")
class CrashTest {
    @TempDir
    Path root;

    /** What stops a run as a kill would: an error nothing in the migration catches, so nothing is taken back. */
    static final class Killed extends Error {
        private static final long serialVersionUID = 1L;

        Killed(String step) {
            super("killed at " + step);
        }
    }

    /** Stops the run at step {@code at} (counted from 0), with a failure or as a kill; -1: never, only counts. */
    static final class StopAt implements Faults {
        final int at;
        final boolean kill;
        final List<String> steps = new ArrayList<>();

        StopAt(int at, boolean kill) {
            this.at = at;
            this.kill = kill;
        }

        @Override
        public void reach(String step) throws IOException {
            steps.add(step);
            if (steps.size() - 1 != at) return;
            if (kill) throw new Killed(step);
            throw new IOException("failure injected at " + step);
        }
    }

    private static Migration migration(Path dir, Faults faults) {
        return CourseProjects.migration(dir, new ByteArrayOutputStream(), new ByteArrayOutputStream(), faults);
    }

    /** Every folder (with a trailing /) and every file's bytes under {@code dir}: a project as a whole. */
    static Map<String, String> tree(Path dir) throws IOException {
        Map<String, String> all = new TreeMap<>();
        try (Stream<Path> walk = Files.walk(dir)) {
            for (Path p : walk.filter(p -> !p.equals(dir)).toList()) {
                String name = dir.relativize(p).toString();
                if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) all.put(name + "/", "");
                else all.put(name, new String(Files.readAllBytes(p), StandardCharsets.ISO_8859_1));
            }
        }
        return all;
    }

    /** A fresh copy of the IntelliJ course project, with git's clean-tree check not asked for. */
    private Path project(String name) throws IOException {
        return CourseProjects.intellij(Files.createDirectories(root.resolve(name)));
    }

    /** The steps of a whole migration of the course project, then of its undo. */
    private List<List<String>> steps() throws Exception {
        Path dir = project("count");
        StopAt migrate = new StopAt(-1, false), undo = new StopAt(-1, false);
        assertThat(migration(dir, migrate).migrate(dir, true, false)).isTrue();
        migration(dir, undo).undo(dir);
        assertThat(migrate.steps).hasSizeGreaterThan(30)
                .contains("journal mkdir course-backup/src", "move src/primitives/Point.java", "write pom.xml", "write course.iml",
                        "write .idea/compiler.xml", "manifest done");
        return List.of(migrate.steps, undo.steps);
    }

    @TestFactory
    @DisplayName("a migration stopped at each step: a failure is taken back at once; after a kill, --undo restores every byte")
    Stream<DynamicTest> migrationStopped() throws Exception {
        List<String> steps = steps().get(0);
        return IntStream.range(0, steps.size()).mapToObj(i -> DynamicTest.dynamicTest(i + ": " + steps.get(i), () -> {
            Path failed = project("failed-" + i);
            Map<String, String> before = tree(failed);
            assertThatThrownBy(() -> migration(failed, new StopAt(i, false)).migrate(failed, true, false))
                    .isInstanceOf(MigrationException.class).hasMessageContaining("taken back, nothing changed");
            assertThat(tree(failed)).isEqualTo(before);

            Path killed = project("killed-" + i);
            assertThatThrownBy(() -> migration(killed, new StopAt(i, true)).migrate(killed, true, false)).isInstanceOf(Killed.class);
            if (Files.exists(killed.resolve(Layout.BACKUP)))
                migration(killed, Faults.NONE).undo(killed);
            else // killed before it made anything: nothing to undo, and --undo says so
                assertThatThrownBy(() -> migration(killed, Faults.NONE).undo(killed)).hasMessageContaining("nothing of raytracer migrate to undo");
            assertThat(tree(killed)).isEqualTo(before);
        }));
    }

    @Test
    @DisplayName("Ctrl-C during the changes: exit 130 with one line saying what to run, and --undo restores every byte")
    void ctrlC() throws Exception {
        Path dir = project("ctrl-c");
        Map<String, String> before = tree(dir);
        Process java = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), StoppedBySignal.class.getName(), dir.toString(), "12")
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        String err = new String(java.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(java.waitFor()).isEqualTo(130);
        assertThat(err.lines().filter(l -> !l.endsWith("...")).toList()).containsExactly("raytracer migrate: the migration of " + dir
                + " was stopped part-way: run raytracer migrate --undo " + dir + " to take back what it did");
        assertThat(Manifest.stateOf(dir)).isEqualTo(Manifest.State.APPLYING);
        migration(dir, Faults.NONE).undo(dir);
        assertThat(tree(dir)).isEqualTo(before);
    }

    @TestFactory
    @DisplayName("an undo stopped at each step, by a failure or a kill: --undo run again finishes, every byte as before the migration")
    Stream<DynamicTest> undoStopped() throws Exception {
        List<String> steps = steps().get(1);
        // one migration, copied for each stop: the manifest's paths are relative to the project
        Path migrated = project("migrated");
        Map<String, String> before = tree(migrated);
        assertThat(migration(migrated, Faults.NONE).migrate(migrated, true, false)).isTrue();
        return IntStream.range(0, steps.size()).mapToObj(i -> DynamicTest.dynamicTest(i + ": " + steps.get(i), () -> {
            for (boolean kill : new boolean[] {false, true}) {
                Path dir = copy(migrated, root.resolve((kill ? "killed-undo-" : "failed-undo-") + i));
                if (kill)
                    assertThatThrownBy(() -> migration(dir, new StopAt(i, true)).undo(dir)).isInstanceOf(Killed.class);
                else
                    assertThatThrownBy(() -> migration(dir, new StopAt(i, false)).undo(dir)).isInstanceOf(MigrationException.class)
                            .hasMessageContaining("again to finish");
                // a migrate run now says what to do (or, stopped before the undo began, that it is migrated), and changes nothing
                Map<String, String> stopped = tree(dir);
                if (Manifest.stateOf(dir) == Manifest.State.UNDOING)
                    assertThatThrownBy(() -> migration(dir, Faults.NONE).migrate(dir, true, false))
                            .hasMessageContaining("was stopped part-way").hasMessageContaining("raytracer migrate --undo " + dir);
                else
                    assertThat(migration(dir, Faults.NONE).migrate(dir, true, false)).as("already migrated").isFalse();
                assertThat(tree(dir)).isEqualTo(stopped);
                migration(dir, Faults.NONE).undo(dir);
                assertThat(tree(dir)).isEqualTo(before);
            }
        }));
    }

    /** A copy of a project as it is: modes and links kept. */
    private static Path copy(Path from, Path to) throws IOException {
        try (Stream<Path> walk = Files.walk(from)) {
            for (Path p : walk.toList())
                Files.copy(p, to.resolve(from.relativize(p).toString()), StandardCopyOption.COPY_ATTRIBUTES, LinkOption.NOFOLLOW_LINKS);
        }
        return to;
    }
}
