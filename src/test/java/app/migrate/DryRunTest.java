package app.migrate;

import static app.migrate.CourseProjects.snapshot;
import static app.migrate.CourseProjects.write;
import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static java.nio.charset.StandardCharsets.UTF_8;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code --dry-run} shows the exact change a real run makes: every file's new text is in the plan
 * before anything is written, the real run writes those texts and nothing else, and the diff the
 * dry run prints, applied with {@code git apply} to a copy of the project, leaves what the real
 * run leaves (its manifest aside).
 */
@DisplayName("migrate --dry-run: the exact change, as a unified diff")
class DryRunTest {
    @TempDir
    Path root;

    /**
     * The kinds of project: only moves and build files; one whose kept sources are rewritten and
     * moved; the same with a source in windows-1255, a Hebrew comment beside a changed line.
     */
    private Path project(String kind) throws IOException {
        Path dir = Files.createDirectories(root.resolve(kind));
        if (kind.equals("intellij")) return CourseProjects.intellij(dir);
        if (kind.equals("windows-1255")) {
            project2025(dir);
            Files.write(dir.resolve("src/geometries/impl/Cube.java"), ("package geometries.impl;\n\nimport geometries.api.Intersectable;\n\n"
                    + "/** \u05e7\u05d5\u05d1\u05d9\u05d9\u05d4: a cube. */\npublic class Cube {\n"
                    + "    public static Intersectable unit() { return null; }\n}\n").getBytes(Charset.forName("windows-1255")));
            return dir;
        }
        return project2025(dir);
    }

    private static Path project2025(Path dir) throws IOException {
        CourseProjects.apiImpl(dir);
        write(dir, "unittests/geometries/impl/CubeTest.java", "package geometries.impl;\n\nimport geometries.api.Intersectable;\n"
                + "import org.junit.jupiter.api.Test;\n\nclass CubeTest {\n    @Test\n    void unit() {\n"
                + "        Intersectable i = Cube.unit();\n    }\n}\n");
        write(dir, "course.iml", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<module type=\"JAVA_MODULE\" version=\"4\">\n"
                + "  <component name=\"NewModuleRootManager\" inherit-compiler-output=\"true\">\n    <exclude-output />\n"
                + "    <content url=\"file://$MODULE_DIR$\">\n      <sourceFolder url=\"file://$MODULE_DIR$/src\" isTestSource=\"false\" />\n"
                + "      <sourceFolder url=\"file://$MODULE_DIR$/unittests\" isTestSource=\"true\" />\n    </content>\n"
                + "    <orderEntry type=\"inheritedJdk\" />\n  </component>\n</module>");
        return dir;
    }

    private static Migration migration(Path dir, ByteArrayOutputStream printed) {
        return CourseProjects.migration(dir, printed, new ByteArrayOutputStream());
    }

    @ParameterizedTest(name = "{0} project")
    @ValueSource(strings = { "intellij", "2025-26", "windows-1255" })
    @DisplayName("the real run writes exactly the texts the plan holds, where it says, keeping each original")
    void planIsWhatIsWritten(String kind) throws Exception {
        Path dir = project(kind);
        Map<String, String> before = snapshot(dir);
        Migration.Planned planned = migration(dir, new ByteArrayOutputStream()).planned(dir, true, true, null);
        assertThat(snapshot(dir)).as("planning writes nothing").isEqualTo(before);

        assertThat(migration(dir, new ByteArrayOutputStream()).migrate(dir, true, false)).isTrue();
        for (Change c : planned.changes()) {
            assertThat(Files.readAllBytes(dir.resolve(c.to()))).as(c.to()).isEqualTo(c.bytes());
            if (!c.to().equals(c.path())) assertThat(dir.resolve(c.path())).as(c.path() + " moved away").doesNotExist();
            if (c.kind() == Change.Kind.REPLACE)
                assertThat(dir.resolve(c.backup())).as(c.backup()).hasBinaryContent(before.get(c.path()).getBytes(StandardCharsets.ISO_8859_1));
        }
        // Nothing else written: every file now is an untouched one, a planned one, or the manifest.
        Map<String, String> after = snapshot(dir);
        for (String file : after.keySet()) {
            boolean planned1 = planned.changes().stream().anyMatch(c -> c.to().equals(file)
                    || c.kind() == Change.Kind.REPLACE && c.backup().equals(file));
            boolean untouched = after.get(file).equals(before.get(file));
            assertThat(planned1 || untouched || file.equals(Manifest.FILE)).as(file + " is planned, untouched or the manifest").isTrue();
        }
    }

    @ParameterizedTest(name = "{0} project")
    @ValueSource(strings = { "intellij", "2025-26", "windows-1255" })
    @DisplayName("the dry run's diff, applied by git apply to a copy, leaves every file as the real run does")
    void diffIsTheChange(String kind) throws Exception {
        Path dir = project(kind);
        Path copy = copy(dir, root.resolve(kind + "-copy"));
        Map<String, String> before = snapshot(dir);
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        assertThat(migration(dir, printed).migrate(dir, true, true)).isFalse();
        assertThat(snapshot(dir)).as("a dry run changes nothing").isEqualTo(before);
        // The diff as printed, byte for byte: each file's lines are in that file's own encoding.
        byte[] out = printed.toByteArray();
        String asLatin1 = new String(out, StandardCharsets.ISO_8859_1);
        byte[] diff = Arrays.copyOfRange(out, asLatin1.indexOf("diff --git "), out.length);
        if (kind.equals("windows-1255"))
            assertThat(new String(diff, StandardCharsets.ISO_8859_1)).as("the Hebrew context line, in the file's own bytes")
                    .contains(new String(" /** \u05e7\u05d5\u05d1\u05d9\u05d9\u05d4: a cube. */\n".getBytes(Charset.forName("windows-1255")),
                            StandardCharsets.ISO_8859_1));

        assertThat(migration(dir, new ByteArrayOutputStream()).migrate(dir, true, false)).isTrue();
        gitApply(copy, diff);
        Map<String, String> migrated = snapshot(dir);
        migrated.remove(Manifest.FILE);
        assertThat(snapshot(copy)).isEqualTo(migrated);
    }

    @Test
    @DisplayName("shows a moved class as a rename, a rewritten one as its original kept and a rename with changes, a new pom as a new file")
    void diffShape() throws Exception {
        Path dir = project("2025-26");
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        migration(dir, printed).migrate(dir, true, true);
        assertThat(printed.toString(StandardCharsets.UTF_8)).contains(
                "The exact change, as a unified diff (paths relative to " + dir.toAbsolutePath().normalize() + "; git apply takes it):\n"
                        + "diff --git a/src/geometries/api/Intersectable.java b/course-backup/src/geometries/api/Intersectable.java\n"
                        + "similarity index 100%\nrename from src/geometries/api/Intersectable.java\n"
                        + "rename to course-backup/src/geometries/api/Intersectable.java\n",
                "diff --git a/src/geometries/impl/Cube.java b/course-backup/originals/src/geometries/impl/Cube.java\n"
                        + "similarity index 100%\ncopy from src/geometries/impl/Cube.java\n"
                        + "copy to course-backup/originals/src/geometries/impl/Cube.java\n"
                        + "diff --git a/src/geometries/impl/Cube.java b/src/geometries/Cube.java\n"
                        + "rename from src/geometries/impl/Cube.java\nrename to src/geometries/Cube.java\n"
                        + "--- a/src/geometries/impl/Cube.java\n+++ b/src/geometries/Cube.java\n"
                        + "@@ -1,6 +1,6 @@\n-package geometries.impl;\n+package geometries;\n \n"
                        + "-import geometries.api.Intersectable;\n+import geometries.Intersectable;\n \n public class Cube {\n",
                "diff --git a/pom.xml b/pom.xml\nnew file mode 100644\n--- /dev/null\n+++ b/pom.xml\n@@ -0,0 +1,",
                "+++ b/course.iml\n", "\\ No newline at end of file\n");
    }

    @Nested
    @DisplayName("hunks")
    class Hunks {
        @Test
        @DisplayName("a change far from another is its own hunk, with three lines of context each side")
        void context() {
            String before = "1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n11\n12\n13\n14\n15\n";
            String after = "1\ntwo\n3\n4\n5\n6\n7\n8\n9\n10\n11\n12\n13\nfourteen\n15\n";
            assertThat(UnifiedDiff.hunks(before, after)).isEqualTo("@@ -1,5 +1,5 @@\n 1\n-2\n+two\n 3\n 4\n 5\n"
                    + "@@ -11,5 +11,5 @@\n 11\n 12\n 13\n-14\n+fourteen\n 15\n");
        }

        @Test
        @DisplayName("changes within six lines of each other share a hunk")
        void joined() {
            assertThat(UnifiedDiff.hunks("a\nb\nc\nd\ne\nf\ng\nh\n", "A\nb\nc\nd\ne\nf\ng\nH\n"))
                    .isEqualTo("@@ -1,8 +1,8 @@\n-a\n+A\n b\n c\n d\n e\n f\n g\n-h\n+H\n");
        }

        @Test
        @DisplayName("a last line without a line break is marked, as diff and git mark it")
        void noNewline() {
            assertThat(UnifiedDiff.hunks("a\nb", "a\nb\n")).isEqualTo("@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+b\n");
        }

        @Test
        @DisplayName("a new file is one hunk of additions from line 0")
        void created() {
            assertThat(UnifiedDiff.hunks("", "x\ny\n")).isEqualTo("@@ -0,0 +1,2 @@\n+x\n+y\n");
        }

        @Test
        @DisplayName("lines added at the end are numbered after the last line kept")
        void appended() {
            assertThat(UnifiedDiff.hunks("a\nb\nc\nd\n", "a\nb\nc\nd\ne\n")).isEqualTo("@@ -2,3 +2,4 @@\n b\n c\n d\n+e\n");
        }
    }

    @Nested
    @DisplayName("paths git quotes")
    class QuotedPaths {
        @Test
        @DisplayName("a space and double quotes in a path, one starting with a quote: git apply moves, copies, rewrites and creates them")
        void gitApplies() throws Exception {
            Path dir = Files.createDirectories(root.resolve("quoted"));
            String moved = "\"my\" shapes/Old Cube.java", rewritten = "src/say \"hi\"/Sphere.java",
                    created = "src/new dir/pom x.xml";
            write(dir, moved, "class OldCube {}\n");
            write(dir, rewritten, "package a;\nclass Sphere {}\n");
            List<Change> changes = List.of(Change.move(moved, "course-backup/" + moved, "class OldCube {}\n", UTF_8),
                    Change.replace(rewritten, "src/b c/Sphere.java", "package a;\nclass Sphere {}\n",
                            "package b;\nclass Sphere {}\n", UTF_8),
                    Change.create(created, "<project/>\n"));

            gitApply(dir, UnifiedDiff.bytes(changes));

            assertThat(snapshot(dir)).isEqualTo(Map.of("course-backup/" + moved, "class OldCube {}\n",
                    Change.ORIGINALS + rewritten, "package a;\nclass Sphere {}\n", "src/b c/Sphere.java", "package b;\nclass Sphere {}\n",
                    created, "<project/>\n"));
        }

        @Test
        @DisplayName("a Hebrew folder name (quoted as its UTF-8 bytes in octal): git apply moves the file there")
        void nonAscii() throws Exception {
            // Java names files in the platform's encoding: under a C locale it cannot make a Hebrew name at all.
            assumeTrue(Charset.forName(System.getProperty("sun.jnu.encoding")).newEncoder().canEncode("\u05e6"),
                    "file names here are in " + System.getProperty("sun.jnu.encoding"));
            Path dir = Files.createDirectories(root.resolve("hebrew"));
            write(dir, "src/\u05e6\u05d5\u05e8\u05d5\u05ea/Cube.java", "class Cube {}\n");
            List<Change> changes = List.of(Change.move("src/\u05e6\u05d5\u05e8\u05d5\u05ea/Cube.java",
                    "course-backup/\u05e6\u05d5\u05e8\u05d5\u05ea/Cube.java", "class Cube {}\n", UTF_8));

            assertThat(UnifiedDiff.of(changes)).startsWith("diff --git \"a/src/\\327\\246");
            gitApply(dir, UnifiedDiff.bytes(changes));

            assertThat(snapshot(dir)).isEqualTo(Map.of("course-backup/\u05e6\u05d5\u05e8\u05d5\u05ea/Cube.java", "class Cube {}\n"));
        }
    }

    /** {@code git apply} of {@code diff} in {@code dir}, as a folder of no repository. */
    private static void gitApply(Path dir, byte[] diff) throws IOException, InterruptedException {
        Path patch = dir.resolveSibling(dir.getFileName() + ".diff");
        Files.write(patch, diff);
        ProcessBuilder git = new ProcessBuilder("git", "apply", "--whitespace=nowarn", patch.toString()).directory(dir.toFile())
                .redirectErrorStream(true);
        git.environment().put("GIT_CEILING_DIRECTORIES", dir.getParent().toString());
        Process p;
        try {
            p = git.start();
        } catch (IOException noGit) {
            assumeTrue(false, "git is not on the PATH: " + noGit.getMessage());
            return;
        }
        p.getOutputStream().close();
        String said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("git apply: " + said).isZero();
    }

    private static Path copy(Path from, Path to) throws IOException {
        try (Stream<Path> walk = Files.walk(from)) {
            for (Path p : walk.toList()) {
                Path t = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) Files.createDirectories(t);
                else Files.copy(p, t);
            }
        }
        return to;
    }
}
