package app.migrate;

import static app.migrate.CourseProjects.snapshot;
import static app.migrate.CourseProjects.write;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.platform.testkit.engine.EngineTestKit;

import renderer.Camera;

/**
 * {@code raytracer migrate} on course projects built for the test ({@link CourseProjects}): each
 * layout, what moves, what stays, what is left out and why, the pom, the undo, and every refusal
 * with nothing changed.
 */
class MigrationTest {
    @TempDir
    Path dir;
    private final ByteArrayOutputStream printed = new ByteArrayOutputStream();
    private final ByteArrayOutputStream steps = new ByteArrayOutputStream();

    /** The library of this build (target/classes), JUnit from the test's own class path, an empty Maven repository. */
    private Migration migration() {
        return CourseProjects.migration(dir, printed, steps);
    }

    private String printed() {
        return printed.toString(StandardCharsets.UTF_8);
    }

    private String read(String path) throws IOException {
        return Files.readString(dir.resolve(path), StandardCharsets.UTF_8);
    }

    @Nested
    @DisplayName("an IntelliJ course project (src/, unittests/, an .iml, no pom)")
    class IntelliJ {
        private Map<String, String> before;

        @BeforeEach
        void migrate() throws Exception {
            CourseProjects.intellij(dir);
            before = snapshot(dir);
            assertThat(migration().migrate(dir, false, false)).isTrue();
        }

        @Test
        @DisplayName("moves the course classes the library provides into course-backup/, keeping their paths")
        void movesCourseClasses() {
            assertThat(dir.resolve("src/primitives")).doesNotExist();
            assertThat(dir.resolve("course-backup/src/primitives/Vector.java")).hasContent(before.get("src/primitives/Vector.java"));
            assertThat(dir.resolve("course-backup/src/primitives/Point.java")).exists();
            assertThat(dir.resolve("course-backup/src/geometries/Geometry.java")).exists();
        }

        @Test
        @DisplayName("keeps an extra shape on the course API and an extra package")
        void keepsExtraShapeAndPackage() {
            assertThat(dir.resolve("src/geometries/Cube.java")).exists();
            assertThat(dir.resolve("src/parser/Points.java")).exists();
            assertThat(printed()).contains("Tests kept: 4 files", "  src/parser/Points.java",
                    "  junit:junit:4.13.2, tests (your code imports it; your IDE supplied it)");
        }

        @Test
        @DisplayName("says, before the next step, how to install the library when the Maven repository lacks it")
        void installStep() {
            Path clone = app.Project.file("pom.xml").toAbsolutePath().getParent();
            assertThat(printed()).contains("yet (mvn test would say \"Could not find artifact io.github.raytracer:raytracer:",
                    "install it first, and again after pulling a newer version:\n  cd " + clone + " && mvn -q install -DskipTests\n"
                            + "Next: cd ");
        }

        @Test
        @DisplayName("keeps the left-out test out of IntelliJ's compile too")
        void excludesInIdea() throws IOException {
            assertThat(read(".idea/compiler.xml")).contains("<excludeFromCompile>",
                    "<file url=\"file://$PROJECT_DIR$/unittests/primitives/RotateTest.java\" />");
        }

        @Test
        @DisplayName("keeps an extra class on the course API, sets aside one that uses the student's own method, with the reason")
        void keepsAndSetsAsideExtras() {
            assertThat(dir.resolve("src/renderer/PixelHelper.java")).exists();
            assertThat(dir.resolve("course-backup/set-aside/src/renderer/Turner.java")).exists();
            assertThat(printed()).contains(
                    "src/renderer/Turner.java:6: Vector.rotate(int) is your own method (not in the course API): port it or keep it aside");
        }

        @Test
        @DisplayName("leaves a test that calls the student's own method out of the build, untouched, naming the call and its line")
        void leavesOutTests() throws IOException {
            assertThat(dir.resolve("unittests/primitives/RotateTest.java")).hasContent(before.get("unittests/primitives/RotateTest.java"));
            assertThat(printed()).contains("unittests/primitives/RotateTest.java:10: Vector.rotate(int) is your own method"
                    + " (not in the course API): port the test or keep it aside");
            assertThat(read("pom.xml")).contains("<testExclude>primitives/RotateTest.java</testExclude>");
        }

        @Test
        @DisplayName("writes a pom that builds the project where it stands and runs every test class whatever its name")
        void writesPom() throws IOException {
            String pom = read("pom.xml");
            assertThat(pom).contains("<sourceDirectory>src</sourceDirectory>", "<testSourceDirectory>unittests</testSourceDirectory>",
                    "<artifactId>junit-bom</artifactId>", "<artifactId>raytracer</artifactId>",
                    "<version>" + BuildPlan.COMPILER_VERSION + "</version>", "<version>" + BuildPlan.SUREFIRE_VERSION + "</version>",
                    "<include>**/*.java</include>", "<maven.compiler.release>17</maven.compiler.release>");
        }

        @Test
        @DisplayName("adds the library jar to the IntelliJ module, from the local Maven repository")
        void addsLibraryToIml() throws IOException {
            assertThat(read("course.iml")).contains(ImlFile.LIBRARY_NAME, "jar://$MAVEN_REPOSITORY$/io/github/raytracer/raytracer/")
                    .contains("<orderEntry type=\"sourceFolder\" forTests=\"false\" />");
        }

        @Test
        @DisplayName("the kept tests compile against the library and pass, the one not named *Test included")
        void keptTestsPass() throws Exception {
            Path classes = Files.createTempDirectory("migrated-tests");
            List<Path> sources = new ArrayList<>();
            for (String f : List.of("unittests/primitives/VectorTests.java", "unittests/renderer/CameraIntersectionIntegration.java",
                    "unittests/geometries/CubeTests.java", "src/renderer/PixelHelper.java", "src/geometries/Cube.java",
                    "src/parser/Points.java"))
                sources.add(dir.resolve(f));
            List<Path> classPath = new ArrayList<>(Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
                    .map(Path::of).toList());
            Javac.Outcome compiled = new Javac(StandardCharsets.UTF_8).compile(sources, classPath, 17, classes);
            assertThat(compiled.failed()).isEmpty();
            try (URLClassLoader loader = new URLClassLoader(new URL[] { classes.toUri().toURL() }, getClass().getClassLoader())) {
                var results = EngineTestKit.engine("junit-jupiter")
                        .selectors(selectClass(loader.loadClass("primitives.VectorTests")),
                                selectClass(loader.loadClass("renderer.CameraIntersectionIntegration")),
                                selectClass(loader.loadClass("geometries.CubeTests")))
                        .execute().testEvents();
                assertThat(results.succeeded().count()).isEqualTo(3);
                assertThat(results.failed().count()).isZero();
            }
        }

        @Test
        @DisplayName("says each step as it starts, apart from the summary")
        void announcesSteps() {
            assertThat(steps.toString(StandardCharsets.UTF_8)).contains("as it is (9 classes, 5 test files)...",
                    "compiling your 5 test files against the library...");
            assertThat(printed()).doesNotContain("compiling");
        }

        @Test
        @DisplayName("a second run changes nothing and says so")
        void secondRun() throws Exception {
            Map<String, String> after = snapshot(dir);
            printed.reset();
            assertThat(migration().migrate(dir, false, false)).isFalse();
            assertThat(snapshot(dir)).isEqualTo(after);
            assertThat(printed()).contains("is already migrated", "nothing changed");
        }

        @Test
        @DisplayName("--undo puts every file back as it was")
        void undo() throws Exception {
            migration().undo(dir);
            assertThat(snapshot(dir)).isEqualTo(before);
        }

        @Test
        @DisplayName("--undo refuses when a file changed since the migration, and changes nothing")
        void undoRefusesChangedFile() throws Exception {
            write(dir, "course-backup/src/primitives/Vector.java", "changed");
            Map<String, String> now = snapshot(dir);
            assertThatThrownBy(() -> migration().undo(dir)).isInstanceOf(MigrationException.class)
                    .hasMessageContaining("course-backup/src/primitives/Vector.java changed since the migration");
            assertThat(snapshot(dir)).isEqualTo(now);
        }
    }

    @Nested
    @DisplayName("a 2025-26 project (geometries.api/impl, lighting.impl, the course's Main with _)")
    class Year5786 {
        @BeforeEach
        void project() throws IOException {
            CourseProjects.apiImpl(dir);
            write(dir, "src/test/Main.java", "package test;\n\npublic class Main {\n    public static void main(String[] args) {\n"
                    + "        try {\n            Integer.parseInt(\"x\");\n        } catch (Exception _) {\n        }\n    }\n}\n");
            write(dir, "unittests/geometries/impl/CubeTest.java", "package geometries.impl;\n\nimport geometries.api.Intersectable;\n"
                    + "import org.junit.jupiter.api.Test;\n\nclass CubeTest {\n    @Test\n    void unit() {\n"
                    + "        Intersectable i = Cube.unit();\n    }\n}\n");
        }

        @Test
        @DisplayName("moves impl/Sphere as the library's geometries.Sphere, folds the kept classes' api/impl lines and moves them")
        void foldsPackages() throws Exception {
            migration().migrate(dir, false, false);
            assertThat(dir.resolve("course-backup/src/geometries/impl/Sphere.java")).exists();
            assertThat(dir.resolve("course-backup/src/geometries/api/Intersectable.java")).exists();
            assertThat(read("src/geometries/Cube.java")).contains("package geometries;", "import geometries.Intersectable;");
            assertThat(read("unittests/geometries/CubeTest.java")).contains("package geometries;");
            assertThat(dir.resolve("course-backup/originals/src/geometries/impl/Cube.java")).exists();
        }

        @Test
        @DisplayName("names the course's Main with _ as needing Java 22 where the JDK is older, and keeps it where it is not")
        void unnamedVariable() throws Exception {
            migration().migrate(dir, false, false);
            if (Runtime.version().feature() < 22) {
                assertThat(dir.resolve("course-backup/set-aside/src/test/Main.java")).exists();
                assertThat(printed()).contains("src/test/Main.java:7: needs Java 22 (the unnamed variable _), and this JDK is "
                        + Runtime.version().feature());
            } else {
                assertThat(dir.resolve("src/test/Main.java")).exists();
                assertThat(read("pom.xml")).contains("<maven.compiler.release>" + Runtime.version().feature() + "<");
            }
        }
    }

    @Nested
    @DisplayName("tests kept inside src/ (one source folder, as the course template has it)")
    class MixedFolder {
        @Test
        @DisplayName("keeps the tests out of the main compile and makes them the only tests of that folder")
        void mixed() throws Exception {
            write(dir, "src/primitives/Point.java", CourseProjects.POINT);
            write(dir, "src/primitives/Vector.java", CourseProjects.vector("primitives", "0, 0, 1"));
            write(dir, "src/renderer/PixelHelper.java", CourseProjects.HELPER);
            write(dir, "src/unittests/primitives/VectorTests.java", CourseProjects.vectorTest("unittests.primitives"));
            migration().migrate(dir, false, false);
            String pom = read("pom.xml");
            assertThat(pom).contains("<sourceDirectory>src</sourceDirectory>", "<testSourceDirectory>src</testSourceDirectory>",
                    "<exclude>unittests/**</exclude>", "<testInclude>unittests/**</testInclude>")
                    .contains("<argLine>" + PomFile.VECTOR_MODULE + "</argLine>"); // the README's test JVM
        }
    }

    @Nested
    @DisplayName("a Maven project with a pom of the student's")
    class Maven {
        @Test
        @DisplayName("keeps the student's settings and adds what is missing")
        void updatesPom() throws Exception {
            write(dir, "pom.xml", """
                    <?xml version="1.0" encoding="UTF-8"?>
                    <project xmlns="http://maven.apache.org/POM/4.0.0">
                      <modelVersion>4.0.0</modelVersion>
                      <groupId>me</groupId>
                      <artifactId>course</artifactId>
                      <version>2</version>
                      <!-- my own comment -->
                      <properties>
                        <my.setting>kept</my.setting>
                      </properties>
                      <build>
                        <plugins>
                          <plugin>
                            <artifactId>maven-surefire-plugin</artifactId>
                            <version>2.12.4</version>
                          </plugin>
                        </plugins>
                      </build>
                    </project>
                    """);
            write(dir, "src/main/java/primitives/Point.java", CourseProjects.POINT);
            write(dir, "src/main/java/primitives/Vector.java", CourseProjects.vector("primitives", "0, 0, 1"));
            write(dir, "src/test/java/primitives/VectorTests.java", CourseProjects.vectorTest("primitives"));
            migration().migrate(dir, false, false);
            String pom = read("pom.xml");
            assertThat(pom).contains("<!-- my own comment -->", "<my.setting>kept</my.setting>", "<groupId>me</groupId>",
                    "<version>" + BuildPlan.SUREFIRE_VERSION + "</version>", "<artifactId>raytracer</artifactId>")
                    .doesNotContain("2.12.4", "<sourceDirectory>");
            assertThat(dir.resolve("course-backup/originals/pom.xml")).content().contains("2.12.4");
            assertThat(pom).contains("<argLine>" + PomFile.VECTOR_MODULE + "</argLine>");
            // what the update changed, as PomFile recorded it: the too-old Surefire raised, the library added
            assertThat(printed()).containsPattern("pom\\.xml: updated \\(.*maven-surefire-plugin 2\\.12\\.4 -> "
                    + BuildPlan.SUREFIRE_VERSION.replace(".", "\\.") + ".*\\)\n")
                    .contains("dependency io.github.raytracer:raytracer:");
        }
    }

    @Nested
    @DisplayName("the test JVM's options")
    class TestJvmOptions {
        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = '|', value = {
                "a property|<properties><argLine>-Xmx2g</argLine></properties>",
                "Surefire's configuration|<build><plugins><plugin><artifactId>maven-surefire-plugin</artifactId>"
                        + "<configuration><argLine>-Xmx2g</argLine></configuration></plugin></plugins></build>" })
        @DisplayName("a project's own argLine is kept, and no vector module is added beside it")
        void ownArgLineKept(String where, String xml) throws Exception {
            write(dir, "pom.xml", "<project xmlns=\"http://maven.apache.org/POM/4.0.0\"><modelVersion>4.0.0</modelVersion>"
                    + "<groupId>me</groupId><artifactId>course</artifactId><version>2</version>" + xml + "</project>\n");
            write(dir, "src/main/java/primitives/Point.java", CourseProjects.POINT);
            write(dir, "src/main/java/primitives/Vector.java", CourseProjects.vector("primitives", "0, 0, 1"));
            write(dir, "src/test/java/primitives/VectorTests.java", CourseProjects.vectorTest("primitives"));
            migration().migrate(dir, false, false);
            assertThat(read("pom.xml")).contains("<argLine>-Xmx2g</argLine>").doesNotContain(PomFile.VECTOR_MODULE);
        }
    }

    @Nested
    @DisplayName("where the student's code chose otherwise than the library")
    class Choices {
        @Test
        @DisplayName("a Vector.Z of (0, 0, -1) is named before anything moves, with the tests it changes")
        void minusZ() throws Exception {
            CourseProjects.intellij(dir);
            write(dir, "src/primitives/Vector.java", CourseProjects.vector("primitives", "0, 0, -1"));
            migration().migrate(dir, false, true);
            assertThat(printed()).contains("your Vector.Z is (0, 0, -1) (src/primitives/Vector.java:4)",
                    "1 test file will change: CameraIntersectionIntegration.java");
        }
    }

    @Nested
    @DisplayName("where the student's code chose otherwise than the library: the camera's rotate")
    class RotateChoice {
        private String rotated(String body) throws Exception {
            CourseProjects.intellij(dir);
            write(dir, "src/renderer/Camera.java", "package renderer;\n\nimport primitives.Vector;\n\npublic class Camera {\n"
                    + "    public static class Builder {\n        private Vector vTo, vUp, vRight;\n\n"
                    + "        public Builder rotate(double angle) {\n" + body + "            return this;\n        }\n    }\n}\n");
            migration().migrate(dir, false, true);
            return printed();
        }

        @Test
        @DisplayName("a rotate that turns the view direction is named")
        void yaw() throws Exception {
            assertThat(rotated("            vTo = vRight;\n")).contains(
                    "your Builder.rotate(degrees) turns the view direction (about the up vector) (src/renderer/Camera.java:9)");
        }

        @Test
        @DisplayName("a rotate that rolls about the view direction is not")
        void roll() throws Exception {
            assertThat(rotated("            vUp = vRight;\n            if (vTo == null) vRight = vUp;\n"))
                    .doesNotContain("turns the view direction");
        }
    }

    @Nested
    @DisplayName("where the student's code chose otherwise than the library: the cylinder")
    class CylinderChoice {
        @ParameterizedTest(name = "Cylinder({0}) is named")
        @ValueSource(strings = { "double h, Ray a, double r", "double height, Ray axis, double radius",
                "final double len, final Ray axis, final double rad", "Double h, Ray axis, double r" })
        void heightFirst(String parameters) throws Exception {
            CourseProjects.intellij(dir);
            write(dir, "src/geometries/Cylinder.java", "package geometries;\n\nimport primitives.Ray;\n\npublic class Cylinder {\n"
                    + "    public Cylinder(" + parameters + ") { }\n}\n");
            migration().migrate(dir, false, true);
            assertThat(printed()).contains("your Cylinder(height, axis, radius) takes the height first (src/geometries/Cylinder.java:6)");
        }

        @Test
        @DisplayName("the course's Cylinder(radius, axis, height) is not named")
        void radiusFirst() throws Exception {
            CourseProjects.intellij(dir);
            write(dir, "src/geometries/Cylinder.java", "package geometries;\n\nimport primitives.Ray;\n\npublic class Cylinder {\n"
                    + "    public Cylinder(double radius, Ray axis, double height) { }\n}\n");
            migration().migrate(dir, false, true);
            assertThat(printed()).doesNotContain("Cylinder(height, axis, radius)");
        }
    }

    @Nested
    @DisplayName("refuses in one line, and changes nothing,")
    class Refusals {
        private void refused(String message) throws IOException {
            Map<String, String> before = snapshot(dir);
            assertThatThrownBy(() -> migration().migrate(dir, false, false)).isInstanceOf(MigrationException.class)
                    .hasMessageContaining(message).satisfies(e -> assertThat(e.getMessage()).doesNotContain("\n"));
            assertThat(snapshot(dir)).isEqualTo(before);
        }

        @Test
        @DisplayName("a folder without Java sources")
        void notAProject() throws IOException {
            write(dir, "notes.txt", "hello");
            refused("is not a course project: no .java file");
        }

        @Test
        @DisplayName("a project with no course class")
        void noCourseClass() throws IOException {
            write(dir, "src/app/Hello.java", "package app;\n\nclass Hello {\n}\n");
            refused("has no course class the library provides");
        }

        @Test
        @DisplayName("a project that does not compile as it is")
        void doesNotCompile() throws IOException {
            CourseProjects.intellij(dir);
            write(dir, "src/renderer/Broken.java", "package renderer;\n\nclass Broken {\n    int x = y;\n}\n");
            refused("does not compile as it is (src/renderer/Broken.java:4: cannot find symbol");
        }

        @Test
        @DisplayName("a course-backup/ that is not the migration's")
        void foreignBackup() throws IOException {
            CourseProjects.intellij(dir);
            write(dir, "course-backup/mine.txt", "mine");
            refused("course-backup is already there, and not from raytracer migrate");
        }

        @Test
        @DisplayName("a read-only folder")
        void readOnly() throws IOException {
            CourseProjects.intellij(dir);
            Path src = dir.resolve("src/primitives");
            assumeTrue(src.toFile().setWritable(false) && !Files.isWritable(src), "the file system honours read-only (not root)");
            try {
                refused("(read-only)");
            } finally {
                src.toFile().setWritable(true);
            }
        }

        @Test
        @DisplayName("a git folder with uncommitted changes (unless allowed)")
        void dirtyGit() throws Exception {
            CourseProjects.intellij(dir);
            Process git = new ProcessBuilder("git", "init", "-q", dir.toString()).redirectErrorStream(true).start();
            git.getInputStream().readAllBytes();
            assumeTrue(git.waitFor() == 0, "git is installed");
            refused("has uncommitted changes");
        }

        @Test
        @DisplayName("a pom that is not well-formed: said with its line and column before anything compiles")
        void badPom() throws IOException {
            CourseProjects.intellij(dir);
            write(dir, "pom.xml", "<project>\n  <build><sourceDirectory>src</sourceDirectory><testSourceDirectory>unittests"
                    + "</testSourceDirectory></build>\n  <dependencies>\n</project>\n");
            refused("pom.xml is not well-formed XML (line 4, column 3: ");
            assertThat(steps.toString(StandardCharsets.UTF_8)).as("no compile before the refusal").doesNotContain("compiling");
        }

        @ParameterizedTest(name = "a folder named \"{0}\"")
        @ValueSource(strings = {"a\tb", "a\nb"})
        @DisplayName("a source in a folder whose name has a tab or a line break, which the manifest cannot hold")
        void tabInName(String folder) throws IOException {
            CourseProjects.intellij(dir);
            write(dir, "src/" + folder + "/Extra.java", "class Extra {\n}\n");
            refused("is a path with a tab or a line break in a name: rename it, then migrate (nothing was changed)");
        }

        @Test
        @DisplayName("a git folder, but no git on the PATH: said, not skipped (unless allowed)")
        void noGit(@TempDir Path emptyPath) throws Exception {
            CourseProjects.intellij(dir);
            Files.createDirectories(dir.resolve(".git"));
            // a child JVM whose PATH holds no git (the migration asks the PATH it runs with)
            ProcessBuilder child = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                    System.getProperty("java.class.path"), MigrateWithoutGit.class.getName(), dir.toString()).redirectErrorStream(true);
            child.environment().put("PATH", emptyPath.toString());
            Process java = child.start();
            String said = new String(java.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(java.waitFor()).as(said).isZero();
            assertThat(said).contains("is in a git folder (" + dir.resolve(".git") + "), but git is not on the PATH")
                    .contains("run with --allow-dirty (nothing was changed)");
            assertThat(dir.resolve("course-backup")).doesNotExist();
        }

        @Test
        @DisplayName("--undo where nothing was migrated")
        void undoWithoutMigration() throws IOException {
            CourseProjects.intellij(dir);
            assertThatThrownBy(() -> migration().undo(dir)).hasMessageContaining("nothing of raytracer migrate to undo");
        }
    }

    @Nested
    @DisplayName("pieces")
    class Pieces {
        @Test
        @DisplayName("release needed: the unnamed variable, record patterns, sequenced collections")
        void releaseNeeded() {
            Path none = Path.of("none");
            assertThat(Reasons.releaseNeeded(new Javac.Problem(none, 1, "compiler.err.underscore.as.identifier", "x"))).isEqualTo(22);
            assertThat(Reasons.releaseNeeded(new Javac.Problem(none, 1, "compiler.err.cant.resolve.location.args",
                    "cannot find symbol\n  symbol:   method getFirst()\n  location: variable l of type List<Point>"))).isEqualTo(21);
            assertThat(Reasons.releaseNeeded(new Javac.Problem(none, 1, "compiler.err.feature.not.supported.in.source.plural",
                    "records are not supported in -source 8\n  (use -source 16 or higher to enable records)"))).isEqualTo(16);
            assertThat(Reasons.releaseNeeded(new Javac.Problem(none, 1, "compiler.err.cant.resolve", "cannot find symbol"))).isZero();
        }

        @Test
        @DisplayName("versions compare numerically")
        void versions() {
            assertThat(PomFile.compareVersions("2.12.4", "3.0")).isNegative();
            assertThat(PomFile.compareVersions("3.5.2", "3.0")).isPositive();
            assertThat(PomFile.compareVersions("3.0", "3.0.0")).isZero();
        }
    }
}
