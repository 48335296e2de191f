package app.migrate;

import static app.migrate.CourseProjects.snapshot;
import static app.migrate.CourseProjects.write;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.Writer;
import java.lang.reflect.Proxy;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The cases a survey of real course projects found {@code migrate} refusing or losing tests on,
 * each as a small project of its own: a 2025–26 project whose course {@code Double3} needs Java 21,
 * a test that needs Java 21, IntelliJ's annotations, JUnit 4, the project's {@code lib/} jars, a
 * stale top-level module file, a {@code unittest/} folder, and sources in windows-1255. They run on
 * every JDK CI runs (17 and the newest), which is where the refusals differed.
 */
class SurveyCasesTest {
    @TempDir
    Path dir;
    private final ByteArrayOutputStream printed = new ByteArrayOutputStream();
    private final OutputStream steps = OutputStream.nullOutputStream();
    private static final int JDK = Runtime.version().feature();

    private boolean migrate() throws MigrationException {
        return CourseProjects.migration(dir, printed, steps).migrate(dir, false, false);
    }

    private String printed() {
        return printed.toString(StandardCharsets.UTF_8);
    }

    private String read(String path) throws IOException {
        return Files.readString(dir.resolve(path), StandardCharsets.UTF_8);
    }

    /** The course's Point and Vector, and a test of them that runs on the library, in {@code tests}. */
    private void courseProject(String tests) throws IOException {
        write(dir, "src/primitives/Point.java", CourseProjects.POINT);
        write(dir, "src/primitives/Vector.java", CourseProjects.vector("primitives", "0, 0, 1"));
        write(dir, tests + "/primitives/VectorTests.java", CourseProjects.vectorTest("primitives"));
    }

    @Nested
    @DisplayName("a 2025-26 project whose course Double3 is a record with a record pattern (Java 21)")
    class RecordPattern {
        @BeforeEach
        void project() throws IOException {
            write(dir, "src/primitives/Double3.java", """
                    package primitives;

                    public record Double3(double d1, double d2, double d3) {
                        @Override
                        public boolean equals(Object obj) {
                            return this == obj || (obj instanceof Double3(double a, double b, double c) && a == d1 && b == d2 && c == d3);
                        }
                    }
                    """);
            write(dir, "src/primitives/Point.java", """
                    package primitives;

                    public class Point {
                        protected final Double3 xyz;
                        public Point(double x, double y, double z) { xyz = new Double3(x, y, z); }
                        public Vector subtract(Point p) { return new Vector(xyz.d1() - p.xyz.d1(), 0, 0); }
                    }
                    """);
            write(dir, "src/primitives/Vector.java", """
                    package primitives;

                    public class Vector extends Point {
                        public Vector(double x, double y, double z) { super(x, y, z); }
                        public double length() { return Math.abs(xyz.d1()); }
                    }
                    """);
            write(dir, "src/geometries/api/Intersectable.java", "package geometries.api;\n\nimport primitives.Point;\n\n"
                    + "public abstract class Intersectable {\n    public abstract Point center();\n}\n");
            write(dir, "src/geometries/impl/RadialGeometry.java", "package geometries.impl;\n\nimport geometries.api.Intersectable;\n\n"
                    + "public abstract class RadialGeometry extends Intersectable {\n}\n");
            write(dir, "src/geometries/impl/Cube.java", "package geometries.impl;\n\nimport primitives.Point;\n\n"
                    + "public class Cube {\n    public Point corner() { return new Point(1, 1, 1); }\n}\n");
            write(dir, "unittests/primitives/VectorTests.java", CourseProjects.vectorTest("primitives"));
        }

        @Test
        @DisplayName("migrates on this JDK: the files that need Java 21 are course classes the library replaces")
        void migrates() throws Exception {
            assertThat(migrate()).isTrue();
            assertThat(dir.resolve("course-backup/src/primitives/Double3.java")).exists();
            assertThat(dir.resolve("course-backup/src/geometries/api/Intersectable.java")).exists();
            assertThat(read("src/geometries/Cube.java")).contains("package geometries;");
            assertThat(printed()).contains("Tests kept: 1 files").doesNotContain("left out of the build");
            // RadialGeometry (2023–25) the library has no class for: kept, and called the course's
            assertThat(printed()).contains("Kept (course classes the library has no class for; they compile against it): 1\n"
                    + "  src/geometries/RadialGeometry.java\n"
                    + "Kept (your own classes; they compile against the library): 1\n"
                    + "  src/geometries/Cube.java\n");
        }
    }

    @Nested
    @DisplayName("a project that compiles only on a newer JDK than this one, or not at all")
    class NewerRelease {
        @Test
        @DisplayName("a test that uses List.getFirst is left out with the release it needs below Java 21, kept from 21 on")
        void getFirst() throws Exception {
            courseProject("unittests");
            write(dir, "unittests/primitives/ListTests.java", """
                    package primitives;

                    import static org.junit.jupiter.api.Assertions.assertEquals;

                    import java.util.List;
                    import org.junit.jupiter.api.Test;

                    class ListTests {
                        @Test
                        void first() {
                            assertEquals(new Point(1, 2, 3), List.of(new Point(1, 2, 3)).getFirst());
                        }
                    }
                    """);
            assertThat(migrate()).isTrue();
            if (JDK < 21)
                assertThat(printed()).contains("unittests/primitives/ListTests.java:11: needs Java 21 (List.getFirst/getLast), and this JDK is "
                        + JDK + ": run migrate with JDK 21 or newer, or port it");
            else
                assertThat(printed()).contains("Tests kept: 2 files").doesNotContain("left out of the build");
        }

        @Test
        @DisplayName("a true error is refused naming its file, not a knock-on in another")
        void trueError() throws IOException {
            courseProject("unittests");
            write(dir, "src/renderer/Broken.java", "package renderer;\n\nimport primitives.Point;\n\n"
                    + "public class Broken {\n    Point p = new Point(1, 2);\n}\n");
            write(dir, "src/renderer/User.java", "package renderer;\n\npublic class User {\n    Broken b = new Broken();\n}\n");
            Map<String, String> before = snapshot(dir);
            assertThatThrownBy(SurveyCasesTest.this::migrate).isInstanceOf(MigrationException.class)
                    .hasMessageContaining("does not compile as it is (src/renderer/Broken.java:6: constructor Point in class"
                            + " primitives.Point cannot be applied to given types;")
                    .hasMessageContaining("fix it first (nothing was changed)");
            assertThat(snapshot(dir)).isEqualTo(before);
        }
    }

    @Nested
    @DisplayName("where the tests are")
    class TestFolders {
        @Test
        @DisplayName("a plain project's unittest/ folder is read as tests")
        void unittest() throws Exception {
            courseProject("unittest");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("tests unittest/", "Tests kept: 1 files");
            assertThat(read("pom.xml")).contains("<testSourceDirectory>unittest</testSourceDirectory>");
        }

        @Test
        @DisplayName("tests in a folder the build does not name are found, added and said")
        void stray() throws Exception {
            courseProject("unittests");
            write(dir, "extra-tests/renderer/MoreTests.java", CourseProjects.vectorTest("renderer").replace("VectorTests", "MoreTests"));
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Tests found outside the folders your build names, now test folders: extra-tests/",
                    "Tests kept: 2 files");
            assertThat(read("pom.xml")).contains("<source>extra-tests</source>");
        }

        @Test
        @DisplayName("a project with no JUnit test anywhere is warned, not passed silently")
        void none() throws Exception {
            write(dir, "src/primitives/Point.java", CourseProjects.POINT);
            write(dir, "src/primitives/Vector.java", CourseProjects.vector("primitives", "0, 0, 1"));
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Tests kept: 0 files", "Warning: no JUnit test was found in this project (none in src/ or any"
                    + " other folder): mvn test will run none");
        }

        @Test
        @DisplayName("the module .idea/modules.xml names is read and gets the library, not a stale one at the top")
        void modulesXml() throws Exception {
            courseProject("unittests");
            String stale = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<module type=\"JAVA_MODULE\" version=\"4\">\n"
                    + "  <component name=\"NewModuleRootManager\" inherit-compiler-output=\"true\">\n"
                    + "    <content url=\"file://$MODULE_DIR$\">\n"
                    + "      <sourceFolder url=\"file://$MODULE_DIR$/src\" isTestSource=\"false\" />\n    </content>\n"
                    + "    <orderEntry type=\"inheritedJdk\" />\n  </component>\n</module>\n";
            write(dir, "course.iml", stale);
            write(dir, ".idea/course.iml", stale.replace("    </content>",
                    "      <sourceFolder url=\"file://$MODULE_DIR$/unittests\" isTestSource=\"true\" />\n    </content>"));
            write(dir, ".idea/modules.xml", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<project version=\"4\">\n"
                    + "  <component name=\"ProjectModuleManager\">\n    <modules>\n"
                    + "      <module fileurl=\"file://$PROJECT_DIR$/.idea/course.iml\" filepath=\"$PROJECT_DIR$/.idea/course.iml\" />\n"
                    + "    </modules>\n  </component>\n</project>\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("tests unittests/", "Tests kept: 1 files", ".idea/course.iml: the library jar added");
            assertThat(read("course.iml")).isEqualTo(stale);
            assertThat(read(".idea/course.iml")).contains(ImlFile.LIBRARY_NAME);
        }
    }

    @Nested
    @DisplayName("a test file with one method on the student's own name")
    class MethodByMethod {
        @Test
        @DisplayName("leaves out that method only: a comment line names why, the others run, undo restores the file")
        void oneMethod() throws Exception {
            courseProject("unittests");
            String mixed = """
                    package primitives;

                    import static org.junit.jupiter.api.Assertions.assertEquals;

                    import org.junit.jupiter.api.Test;

                    class MixedTests {
                        @Test
                        void length() {
                            assertEquals(5, new Vector(3, 4, 0).length(), 1e-10);
                        }

                        /** The student's own rotate. */
                        @Test
                        void turns() {
                            assertEquals(new Vector(1, 0, 0), new Vector(1, 0, 0).rotate(90));
                        }
                    }
                    """;
            write(dir, "unittests/primitives/MixedTests.java", mixed);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Tests kept: 2 files", "Tests kept with some of their methods left out",
                    "  unittests/primitives/MixedTests.java: 1 test method left out (turns()), the rest kept: 16: Vector.rotate(int) is your"
                            + " own method (not in the course API): port the test or keep it aside")
                    .doesNotContain("left out of the build");
            assertThat(read("unittests/primitives/MixedTests.java")).isEqualTo(mixed.replace("""

                        /** The student's own rotate. */
                        @Test
                        void turns() {
                            assertEquals(new Vector(1, 0, 0), new Vector(1, 0, 0).rotate(90));
                        }
                    """, """

                        // raytracer migrate: turns() left out: Vector.rotate(int) is your own method (not in the course API): port the test or keep it aside
                    """));
            assertThat(read("course-backup/originals/unittests/primitives/MixedTests.java")).isEqualTo(mixed);
            CourseProjects.migration(dir, printed, steps).undo(dir);
            assertThat(read("unittests/primitives/MixedTests.java")).isEqualTo(mixed);
        }
    }

    @Nested
    @DisplayName("course-year choices the tests trip on, named with the tests")
    class Choices {
        @Test
        @DisplayName("a camera that defaults its location: named with the test that builds one without setLocation")
        void location() throws Exception {
            courseProject("unittests");
            write(dir, "src/renderer/Camera.java", """
                    package renderer;

                    import primitives.Point;

                    public class Camera {
                        private Point location;
                        public static Builder getBuilder() { return new Builder(); }
                        public static class Builder {
                            private Point location = new Point(0, 0, 0);
                            public Builder setLocation(Point p) { location = p; return this; }
                            public Camera build() { Camera c = new Camera(); c.location = location; return c; }
                        }
                    }
                    """);
            write(dir, "unittests/renderer/CameraTest.java", """
                    package renderer;

                    import org.junit.jupiter.api.Test;
                    import primitives.Point;

                    class CameraTest {
                        private final Camera.Builder builder = Camera.getBuilder();

                        @Test
                        void located() {
                            Camera.getBuilder().setLocation(new Point(0, 0, 1)).build();
                        }

                        @Test
                        void atTheOrigin() {
                            builder.build();
                        }
                    }
                    """);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("your camera defaults its location (to the origin) (src/renderer/Camera.java:9); the library:"
                    + " build() without setLocation throws MissingResourceException; 1 test file will change: CameraTest.java");
        }

        @Test
        @DisplayName("an ImageWriter that takes a blank name: named with the test that gives one")
        void blankName() throws Exception {
            courseProject("unittests");
            write(dir, "src/renderer/ImageWriter.java", "package renderer;\n\npublic class ImageWriter {\n"
                    + "    public ImageWriter(String name, int nX, int nY) { }\n}\n");
            write(dir, "unittests/renderer/ImageWriterTest.java", """
                    package renderer;

                    import org.junit.jupiter.api.Test;

                    class ImageWriterTest {
                        @Test
                        void grid() {
                            String name = "";
                            new ImageWriter(name, 10, 10);
                        }
                    }
                    """);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("your ImageWriter takes a blank image name (src/renderer/ImageWriter.java:1); the library: a"
                    + " blank image name is refused (IllegalArgumentException: image name must not be blank); 1 test file will change:"
                    + " ImageWriterTest.java");
        }

        @Test
        @DisplayName("an ImageWriter that takes a blank name is not named when no test gives one (most students' do)")
        void blankNameUntouched() throws Exception {
            courseProject("unittests");
            write(dir, "src/renderer/ImageWriter.java", "package renderer;\n\npublic class ImageWriter {\n"
                    + "    public ImageWriter(String name, int nX, int nY) { }\n}\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).doesNotContain("blank image name");
        }

        @ParameterizedTest(name = "a bottom-base normal of {0}: named {1}")
        @CsvSource({ "dir, true", "dir.scale(-1), false" })
        @DisplayName("a cylinder whose bottom-base normal is the axis direction is named, found by running the student's class")
        void cylinderBottomNormal(String bottom, boolean named) throws Exception {
            write(dir, "src/primitives/Point.java", """
                    package primitives;

                    public class Point {
                        protected final double x, y, z;
                        public Point(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }
                        public Vector subtract(Point p) { return new Vector(x - p.x, y - p.y, z - p.z); }
                    }
                    """);
            write(dir, "src/primitives/Vector.java", """
                    package primitives;

                    public class Vector extends Point {
                        public Vector(double x, double y, double z) { super(x, y, z); }
                        public double dotProduct(Vector v) { return x * v.x + y * v.y + z * v.z; }
                        public Vector scale(double k) { return new Vector(k * x, k * y, k * z); }
                    }
                    """);
            write(dir, "src/primitives/Ray.java", "package primitives;\n\npublic class Ray {\n    public final Point p0;\n"
                    + "    public final Vector dir;\n    public Ray(Point p0, Vector dir) { this.p0 = p0; this.dir = dir; }\n}\n");
            write(dir, "src/geometries/Cylinder.java", "package geometries;\n\nimport primitives.*;\n\npublic class Cylinder {\n"
                    + "    private final Vector dir;\n    public Cylinder(double radius, Ray axis, double height) { dir = axis.dir; }\n"
                    + "    public Vector getNormal(Point p) { return " + bottom + "; }\n}\n");
            write(dir, "unittests/geometries/CylinderTests.java", "package geometries;\n\nimport org.junit.jupiter.api.Test;\n\n"
                    + "class CylinderTests {\n    @Test\n    void normal() {\n        new Cylinder(1, null, 1).getNormal(null);\n    }\n}\n");
            assertThat(migrate()).isTrue();
            String line = "your Cylinder's normal at the centre of its bottom base is the axis direction (src/geometries/Cylinder.java);"
                    + " the library: the outward normal there, minus the axis direction; 1 test file will change: CylinderTests.java";
            if (named) assertThat(printed()).contains(line);
            else assertThat(printed()).doesNotContain("bottom base");
        }

        @Test
        @DisplayName("a cylinder probe that cannot tell (a student's class that loops) names nothing, within its time limit")
        void cylinderProbeLoops() throws Exception {
            courseProject("unittests");
            write(dir, "src/primitives/Ray.java", "package primitives;\n\npublic class Ray {\n"
                    + "    public Ray(Point p0, Vector dir) { }\n}\n");
            write(dir, "src/geometries/Cylinder.java", "package geometries;\n\nimport primitives.*;\n\npublic class Cylinder {\n"
                    + "    public Cylinder(double radius, Ray axis, double height) { }\n"
                    // Ends when interrupted (the probe's thread is, at its time limit), so that no
                    // spinning thread is left in the test JVM.
                    + "    public Vector getNormal(Point p) {\n        while (true) {\n            try {\n"
                    + "                Thread.sleep(10);\n            } catch (InterruptedException e) {\n                return null;\n"
                    + "            }\n        }\n    }\n}\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).doesNotContain("bottom base");
        }

        @Test
        @DisplayName("the light rule: a test that asks a light about the point it was built at, not inside assertThrows")
        void lightAtItsPosition() {
            assertThat(CourseChoices.asksLightAtItsPosition("PointLight l = new PointLight(WHITE, new Point(1, 2, 3));\n"
                    + "assertNull(l.getL(new Point(1,  2, 3)));")).isTrue();
            assertThat(CourseChoices.asksLightAtItsPosition("static final SpotLight LIGHT = new SpotLight(I0, POSITION, DIR);\n"
                    + "void t() { assertEquals(I0, LIGHT.getIntensity(POSITION)); }")).isTrue();
            assertThat(CourseChoices.asksLightAtItsPosition("SpotLight l = new SpotLight(I0, POSITION, DIR);\n"
                    + "void t() { assertThrows(IllegalArgumentException.class, () -> l.getL(POSITION)); }")).isFalse();
            assertThat(CourseChoices.asksLightAtItsPosition("PointLight l = new PointLight(WHITE, new Point(1, 2, 3));\n"
                    + "assertEquals(v, l.getL(new Point(1, 2, 4)));")).isFalse();
            assertThat(CourseChoices.asksLightAtItsPosition("assertEquals(v, light.getL(POSITION));")).isFalse();
        }

        @Test
        @DisplayName("the buildsWithoutLocation rule: per statement, through the builder's declaration")
        void buildsWithoutLocation() {
            String builder = "Camera.Builder b = Camera.getBuilder().setLocation(p);\n";
            assertThat(CourseChoices.buildsWithoutLocation(builder + "Camera c = b.setVpSize(1, 1).build();")).isFalse();
            assertThat(CourseChoices.buildsWithoutLocation("Camera.Builder b = Camera.getBuilder();\nCamera c = b.build();")).isTrue();
            assertThat(CourseChoices.buildsWithoutLocation("Camera c = Camera.getBuilder().setVpDistance(1)\n.setLocation(p).build();"))
                    .isFalse();
            assertThat(CourseChoices.buildsWithoutLocation("Camera c = new Camera.Builder().setVpDistance(1).build();")).isTrue();
        }
    }

    @Nested
    @DisplayName("javac itself failing")
    class CompilerFailures {
        /**
         * The JDK's compiler, whose tasks fail as javac does when it runs out of memory: it catches
         * the error, prints it to its output and reports no diagnostic.
         */
        private JavaCompiler outOfMemory() {
            JavaCompiler real = ToolProvider.getSystemJavaCompiler();
            return (JavaCompiler) Proxy.newProxyInstance(getClass().getClassLoader(), new Class<?>[] { JavaCompiler.class },
                    (proxy, method, args) -> {
                        if (!method.getName().equals("getTask")) return method.invoke(real, args);
                        Writer out = (Writer) args[0];
                        return Proxy.newProxyInstance(getClass().getClassLoader(), new Class<?>[] { JavaCompiler.CompilationTask.class },
                                (task, m, a) -> {
                                    if (!m.getName().equals("call")) return null;
                                    out.write("An exception has occurred in the compiler. java.lang.OutOfMemoryError: Java heap space");
                                    return false;
                                });
                    });
        }

        @Test
        @DisplayName("out of memory is said as such, with the heap and the largest file, not as a missing package")
        void outOfMemoryIsNamed() throws IOException {
            courseProject("unittests");
            Javac javac;
            try {
                javac = new Javac(StandardCharsets.UTF_8, outOfMemory());
            } catch (MigrationException e) {
                throw new AssertionError(e);
            }
            Path out = Files.createTempDirectory(dir.getParent(), "classes");
            assertThatThrownBy(() -> javac.compile(List.of(dir.resolve("src/primitives/Point.java"), dir.resolve("src/primitives/Vector.java")),
                    List.of(), 17, out))
                    .isInstanceOf(MigrationException.class)
                    .hasMessageStartingWith("javac ran out of memory (this Java's heap is ")
                    .hasMessageContaining(" MB) compiling 2 files, the largest Vector.java (0 kB): run migrate with a larger heap, e.g."
                            + " RAYTRACER_JAVA_OPTS=-Xmx2g (nothing was changed)");
        }
    }

    @Nested
    @DisplayName("what a left-out test is told")
    class Messages {
        @Test
        @DisplayName("a call to the student's own overload names it and what the library takes, in one line")
        void ownOverload() throws Exception {
            write(dir, "src/primitives/Point.java", CourseProjects.POINT);
            write(dir, "src/primitives/Vector.java", CourseProjects.vector("primitives", "0, 0, 1")
                    .replace("    public Vector rotate", "    public Vector scale(double k) { return this; }\n"
                            + "    public Vector scale(double k, double m) { return this; }\n    public Vector rotate"));
            write(dir, "unittests/primitives/ScaleTests.java", """
                    package primitives;

                    import static org.junit.jupiter.api.Assertions.assertEquals;

                    import org.junit.jupiter.api.Test;

                    class ScaleTests {
                        @Test
                        void twice() {
                            assertEquals(new Vector(2, 0, 0), new Vector(1, 0, 0).scale(2, 3));
                        }

                        @Test
                        void once() {
                            assertEquals(new Vector(2, 0, 0), new Vector(1, 0, 0).scale(2));
                        }
                    }
                    """);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("  unittests/primitives/ScaleTests.java: 1 test method left out (twice()), the rest kept: 10:"
                    + " Vector.scale(int, int) is your own overload (not in the course API; the library's takes (double)): port the test"
                    + " or keep it aside");
        }

        @Test
        @DisplayName("a method that clashes with one inside the library is said so, without naming the library's insides")
        void clashInside() throws Exception {
            courseProject("unittests");
            write(dir, "src/geometries/AABB.java", "package geometries;\n\npublic class AABB {\n}\n");
            write(dir, "src/geometries/Intersectable.java", "package geometries;\n\npublic abstract class Intersectable {\n"
                    + "    public AABB getBoundingBox() { return null; }\n}\n");
            write(dir, "src/geometries/BVHNode.java", "package geometries;\n\npublic abstract class BVHNode extends Intersectable {\n"
                    + "    @Override\n    public AABB getBoundingBox() { return new AABB(); }\n}\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("src/geometries/BVHNode.java:5: BVHNode.getBoundingBox() clashes with a method of that name"
                    + " inside the library, which its course classes inherit (return type AABB is not compatible with BoundingBox):"
                    + " rename yours").doesNotContain("BvhLeaf");
        }

        @Test
        @DisplayName("an @Override of a method only the student's course class had is named")
        void overrideOfOwn() throws Exception {
            courseProject("unittests");
            write(dir, "src/primitives/Material.java", "package primitives;\n\npublic class Material {\n"
                    + "    public Material setGlossy(double g) { return this; }\n}\n");
            write(dir, "src/renderer/Gold.java", "package renderer;\n\nimport primitives.Material;\n\npublic class Gold extends Material {\n"
                    + "    @Override\n    public Material setGlossy(double g) { return this; }\n}\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("src/renderer/Gold.java:6: setGlossy() is marked @Override, but nothing in the library has"
                    + " it to override (it overrode one of your own course classes): port it or keep it aside");
        }

        @Test
        @DisplayName("a constructor of the student's own is named as theirs")
        void constructor() throws Exception {
            courseProject("unittests");
            write(dir, "src/primitives/Ray.java", "package primitives;\n\npublic class Ray {\n"
                    + "    public Ray(Point p) { }\n    public Ray(Point p, Vector v) { }\n}\n");
            write(dir, "unittests/primitives/RayTests.java", """
                    package primitives;

                    import org.junit.jupiter.api.Test;

                    class RayTests {
                        @Test
                        void make() {
                            new Ray(new Point(1, 2, 3));
                        }
                    }
                    """);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("RayTests.java:8: Ray(Point) is your own overload (not in the course API");
        }
    }

    @Nested
    @DisplayName("classes that are not where the library keeps them, or not the course's")
    class Namesakes {
        @Test
        @DisplayName("a course class kept in another course package moves as the library's; what stays is pointed at it")
        void relocated() throws Exception {
            courseProject("unittests");
            write(dir, "src/lighting/Material.java", "package lighting;\n\npublic class Material {\n"
                    + "    public double kD;\n    public Material setKd(double kD) { this.kD = kD; return this; }\n}\n");
            String same = "package lighting;\n\nimport org.junit.jupiter.api.Test;\n\nclass MaterialTests {\n    @Test\n"
                    + "    void kd() {\n        new Material().setKd(0.5);\n    }\n}\n";
            String other = "package renderer;\n\nimport lighting.Material;\nimport org.junit.jupiter.api.Test;\n\nclass UseTests {\n"
                    + "    @Test\n    void kd() {\n        new Material().setKd(0.5);\n    }\n}\n";
            write(dir, "unittests/lighting/MaterialTests.java", same);
            write(dir, "unittests/renderer/UseTests.java", other);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("  lighting: Material (as the library's primitives.Material)", "Tests kept: 3 files")
                    .doesNotContain("left out");
            assertThat(dir.resolve("course-backup/src/lighting/Material.java")).exists();
            assertThat(read("unittests/lighting/MaterialTests.java"))
                    .isEqualTo(same.replace("package lighting;\n", "package lighting;\nimport primitives.Material;\n"));
            assertThat(read("unittests/renderer/UseTests.java")).isEqualTo(other.replace("import lighting.Material;", "import primitives.Material;"));
        }

        @Test
        @DisplayName("a class of the student's own named as one inside the library is said to be theirs, not the course's")
        void boundingBox() throws Exception {
            courseProject("unittests");
            write(dir, "src/geometries/BoundingBox.java", "package geometries;\n\npublic class BoundingBox {\n}\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Moved to course-backup/ (the library provides them): 2 classes",
                    "Moved to course-backup/ too (your own classes, named as classes inside the library, beside which they cannot stay;"
                            + " the library's BVH is always on in place of one of yours): geometries.BoundingBox");
        }

        @Test
        @DisplayName("a test method of the student's own namesake class goes: it would test the library's class instead")
        void namesakeTests() throws Exception {
            courseProject("unittests");
            write(dir, "src/geometries/BoundingBox.java", "package geometries;\n\npublic class BoundingBox {\n}\n");
            write(dir, "unittests/geometries/BoxTests.java", """
                    package geometries;

                    import static org.junit.jupiter.api.Assertions.assertNotNull;

                    import org.junit.jupiter.api.Test;

                    class BoxTests {
                        @Test
                        void box() {
                            assertNotNull(new BoundingBox());
                        }

                        @Test
                        void other() {
                            assertNotNull(new Object());
                        }
                    }
                    """);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Tests kept: 2 files", "  unittests/geometries/BoxTests.java: 1 test method left out (box()),"
                    + " the rest kept: it uses your own BoundingBox, moved to course-backup/: the library has a class of that name inside"
                    + " it, which this test would run against instead");
        }

        @Test
        @DisplayName("a helper of the student's named like a course class elsewhere stays theirs when the project has the course's too")
        void ownHelper() throws Exception {
            courseProject("unittests");
            write(dir, "src/primitives/Util.java", "package primitives;\n\npublic final class Util {\n"
                    + "    public static boolean isZero(double d) { return Math.abs(d) < 1e-10; }\n}\n");
            write(dir, "src/renderer/Util.java", "package renderer;\n\npublic final class Util {\n    public static int two() { return 2; }\n}\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("  src/renderer/Util.java").doesNotContain("as the library's");
        }
    }

    @Nested
    @DisplayName("the project's own libraries")
    class OwnLibraries {
        private static final String IML = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<module type=\"JAVA_MODULE\" version=\"4\">\n"
                + "  <component name=\"NewModuleRootManager\" inherit-compiler-output=\"true\">\n"
                + "    <content url=\"file://$MODULE_DIR$\">\n"
                + "      <sourceFolder url=\"file://$MODULE_DIR$/src\" isTestSource=\"false\" />\n"
                + "      <sourceFolder url=\"file://$MODULE_DIR$/unittests\" isTestSource=\"true\" />\n    </content>\n"
                + "    <orderEntry type=\"inheritedJdk\" />\nENTRIES  </component>\n</module>\n";

        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
                "$MAVEN_REPOSITORY$/org/jetbrains/annotations/24.1.0/annotations-24.1.0.jar | your IDE's module",
                "$APPLICATION_HOME_DIR$/lib/annotations.jar | IntelliJ's bundled annotations" })
        @DisplayName("IntelliJ's annotations, from the module's Maven library or IntelliJ's own lib/, become org.jetbrains:annotations")
        void annotations(String jar, String from) throws Exception {
            courseProject("unittests");
            CourseProjects.install(dir, "org.jetbrains:annotations:24.1.0");
            write(dir, "course.iml", IML.replace("ENTRIES", "    <orderEntry type=\"module-library\">\n      <library>\n"
                    + "        <CLASSES>\n          <root url=\"jar://" + jar + "!/\" />\n        </CLASSES>\n      </library>\n"
                    + "    </orderEntry>\n"));
            write(dir, "src/renderer/Names.java", "package renderer;\n\nimport org.jetbrains.annotations.NotNull;\n\n"
                    + "public class Names {\n    public static @NotNull String name() { return \"n\"; }\n}\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Your libraries, now dependencies in pom.xml: 1",
                    "  org.jetbrains:annotations:24.1.0 (" + from + ")", "Kept (your own classes; they compile against the library): 1");
            assertThat(read("pom.xml")).contains("<groupId>org.jetbrains</groupId>\n      <artifactId>annotations</artifactId>\n"
                    + "      <version>24.1.0</version>");
        }

        @Test
        @DisplayName("JUnit 4 tests get JUnit 4 and the Vintage engine beside Jupiter, and are kept")
        void junit4() throws Exception {
            courseProject("unittests");
            CourseProjects.install(dir, "junit:junit:4.13.2");
            CourseProjects.install(dir, "org.hamcrest:hamcrest-core:1.3");
            write(dir, "unittests/primitives/PointTest.java", """
                    package primitives;

                    import static org.junit.Assert.assertEquals;

                    import org.junit.Test;

                    public class PointTest {
                        @Test
                        public void subtract() {
                            assertEquals(new Vector(1, 1, 1), new Point(2, 2, 2).subtract(new Point(1, 1, 1)));
                        }
                    }
                    """);
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Tests kept: 2 files", "junit:junit:4.13.2, tests (your code imports it")
                    .doesNotContain("left out");
            assertThat(read("pom.xml")).contains("<artifactId>junit-vintage-engine</artifactId>\n      <scope>test</scope>",
                    "<groupId>junit</groupId>\n      <artifactId>junit</artifactId>\n      <version>4.13.2</version>\n"
                            + "      <scope>test</scope>");
        }

        @Test
        @DisplayName("lib/ jars: a known artifact by its coordinates, the project's own with system scope; JUnit's dropped")
        void libJars() throws Exception {
            courseProject("unittests");
            jar("lib/gson-2.10.1.jar", "com/google/gson/Gson.class");
            jar("lib/shapes.jar", "shapes/Star.class");
            jar("lib/junit-jupiter-api-5.8.1.jar", "org/junit/jupiter/api/Test.class");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("Your libraries, now dependencies in pom.xml: 2",
                    "  com.google.code.gson:gson:2.10.1 (lib/gson-2.10.1.jar)", "  lib/shapes.jar (lib/shapes.jar)");
            assertThat(read("pom.xml")).contains("<artifactId>gson</artifactId>\n      <version>2.10.1</version>",
                    "<systemPath>${project.basedir}/lib/shapes.jar</systemPath>").doesNotContain("junit-jupiter-api-5.8.1");
        }

        @Test
        @DisplayName("a library the project names that this machine lacks is named in the refusal it causes")
        void missingLibrary() throws Exception {
            courseProject("unittests");
            write(dir, "course.iml", IML.replace("ENTRIES", "    <orderEntry type=\"module-library\">\n      <library>\n"
                    + "        <CLASSES>\n          <root url=\"jar://$MAVEN_REPOSITORY$/com/google/code/gson/gson/2.10.1/"
                    + "gson-2.10.1.jar!/\" />\n        </CLASSES>\n      </library>\n    </orderEntry>\n"));
            write(dir, "src/renderer/Json.java", "package renderer;\n\nimport com.google.gson.Gson;\n\n"
                    + "public class Json {\n    public static Gson gson() { return new Gson(); }\n}\n");
            assertThatThrownBy(SurveyCasesTest.this::migrate).isInstanceOf(MigrationException.class)
                    .hasMessageContaining("does not compile as it is (src/renderer/Json.java:3: package com.google.gson does not exist):"
                            + " fix it first; your libraries this machine does not have: com.google.code.gson:gson:2.10.1 (your IDE's module)"
                            + " (nothing was changed)");
        }

        @Test
        @DisplayName("libraries named but absent: a known one stays in the pom for Maven to fetch, a jar never committed is left out")
        void absent() throws Exception {
            courseProject("unittests");
            write(dir, "course.iml", IML.replace("ENTRIES", "    <orderEntry type=\"library\" name=\"gson\" level=\"project\" />\n"
                    + "    <orderEntry type=\"library\" name=\"shapes\" level=\"project\" />\n"));
            write(dir, ".idea/libraries/gson.xml", "<component name=\"libraryTable\">\n  <library name=\"gson\" type=\"repository\">\n"
                    + "    <properties maven-id=\"com.google.code.gson:gson:2.10.1\" />\n  </library>\n</component>\n");
            write(dir, ".idea/libraries/shapes.xml", "<component name=\"libraryTable\">\n  <library name=\"shapes\">\n"
                    + "    <CLASSES>\n      <root url=\"jar://$PROJECT_DIR$/lib/shapes.jar!/\" />\n    </CLASSES>\n  </library>\n</component>\n");
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("  com.google.code.gson:gson:2.10.1 (your IDE's module); not in " + CourseProjects.repository(dir)
                    + ", and mvn could not fetch it now (mvn test will try again)",
                    "  lib/shapes.jar (lib/shapes.jar); not in the project (never committed?): left out of pom.xml");
            assertThat(read("pom.xml")).contains("<artifactId>gson</artifactId>").doesNotContain("shapes");
        }

        private void jar(String path, String entry) throws IOException {
            Path jar = dir.resolve(path);
            Files.createDirectories(jar.getParent());
            try (ZipOutputStream zip = new ZipOutputStream(Files.newOutputStream(jar))) {
                zip.putNextEntry(new ZipEntry(entry));
                zip.write(new byte[] { (byte) 0xCA, (byte) 0xFE });
                zip.closeEntry();
            }
        }
    }

    @Nested
    @DisplayName("sources in another encoding than UTF-8")
    class Encodings {
        private static final Charset HEBREW = Charset.forName("windows-1255");
        private static final String CUBE = "package geometries.impl;\n\nimport primitives.Point;\n\n"
                + "/** \u05e7\u05d5\u05d1\u05d9\u05d9\u05d4: a cube. */\npublic class Cube {\n"
                + "    public String name() { return \"\u05e7\u05d5\u05d1\u05d9\u05d9\u05d4\"; }\n"
                + "    public Point corner() { return new Point(1, 1, 1); }\n}\n";

        @BeforeEach
        void project() throws IOException {
            courseProject("unittests");
            Path cube = dir.resolve("src/geometries/impl/Cube.java");
            Files.createDirectories(cube.getParent());
            Files.write(cube, CUBE.getBytes(HEBREW));
        }

        @Test
        @DisplayName("windows-1255 is detected, written into the pom, and a rewritten file keeps it; undo restores the bytes")
        void detected() throws Exception {
            byte[] original = Files.readAllBytes(dir.resolve("src/geometries/impl/Cube.java"));
            assertThat(migrate()).isTrue();
            assertThat(printed()).contains("sources in windows-1255 (detected: not UTF-8)");
            assertThat(read("pom.xml")).contains("<project.build.sourceEncoding>windows-1255</project.build.sourceEncoding>");
            assertThat(new String(Files.readAllBytes(dir.resolve("src/geometries/Cube.java")), HEBREW))
                    .isEqualTo(CUBE.replace("package geometries.impl;", "package geometries;"));
            CourseProjects.migration(dir, printed, steps).undo(dir);
            assertThat(Files.readAllBytes(dir.resolve("src/geometries/impl/Cube.java"))).isEqualTo(original);
        }

        @Test
        @DisplayName("the encoding IntelliJ states is used; an unknown one named is refused in one line")
        void stated() throws Exception {
            write(dir, ".idea/encodings.xml", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<project version=\"4\">\n"
                    + "  <component name=\"Encoding\">\n    <file url=\"PROJECT\" charset=\"windows-1255\" />\n  </component>\n</project>\n");
            assertThatThrownBy(() -> CourseProjects.migration(dir, printed, steps).migrate(dir, false, true, "hebrew-9"))
                    .isInstanceOf(MigrationException.class)
                    .hasMessage("--encoding names the encoding \"hebrew-9\", which this Java does not know (UTF-8, windows-1255"
                            + " and ISO-8859-1 are; nothing was changed)");
            assertThat(CourseProjects.migration(dir, printed, steps).migrate(dir, false, true, null)).isFalse();
            assertThat(printed()).contains("sources in windows-1255 (.idea/encodings.xml)");
        }
    }
}
