package app.migrate;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import app.Project;
import renderer.Camera;

/**
 * Course projects built for the migration tests, as students keep them: small, but each with the
 * parts a real one has (course classes of their own writing, an extra class, tests that use the
 * course API and one that uses the student's own method, a test class not named {@code *Test}).
 * The course classes compile on their own, as a student's do before the migration.
 */
final class CourseProjects {
    private CourseProjects() {
    }

    /** The student's own Vector (with a method of their own, {@code rotate}); {@code z} is their Z axis. */
    static String vector(String pkg, String z) {
        return "package " + pkg + ";\n\npublic class Vector extends Point {\n"
                + "    public static final Vector Z = new Vector(" + z + ");\n"
                + "    public Vector(double x, double y, double z) { super(x, y, z); }\n"
                + "    public double length() { return Math.sqrt(x * x + y * y + z * z); }\n"
                + "    public Vector rotate(int degrees) { return this; }\n}\n";
    }

    static final String POINT = """
            package primitives;

            public class Point {
                protected final double x, y, z;
                public Point(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }
                public Vector subtract(Point p) { return new Vector(x - p.x, y - p.y, z - p.z); }
            }
            """;

    /** A test that uses only the course API: it passes on the library. */
    static String vectorTest(String pkg) {
        return "package " + pkg + ";\n\nimport static org.junit.jupiter.api.Assertions.assertEquals;\n\n"
                + "import org.junit.jupiter.api.Test;\nimport primitives.*;\n\n"
                + "class VectorTests {\n    @Test\n    void length() {\n"
                + "        assertEquals(5, new Vector(3, 4, 0).length(), 1e-10);\n"
                + "        assertEquals(new Vector(1, 1, 1), new Point(2, 2, 2).subtract(new Point(1, 1, 1)));\n    }\n}\n";
    }



    /** An extra class of the student's on the course API: it compiles against the library. */
    static final String HELPER = """
            package renderer;

            import primitives.Point;
            import primitives.Vector;

            public class PixelHelper {
                public static Vector between(Point a, Point b) { return b.subtract(a); }
            }
            """;









    /**
     * A 2024–25 IntelliJ project (src/, unittests/, an .iml, no pom; .idea/ made here), from
     * {@code src/it/migrate/course}, the project the migration's integration test also runs Maven
     * on: the student's Point, Vector (with a {@code rotate} of their own), Ray, Intersectable and
     * Geometry; extras on the course API (a shape, a parser package, a helper) and one that uses
     * {@code rotate}; tests of the course API, one not named {@code *Test}, one that calls {@code rotate}.
     */
    static Path intellij(Path dir) throws IOException {
        Path from = Project.file("src/it/migrate/course");
        try (Stream<Path> walk = Files.walk(from)) {
            for (Path f : walk.filter(Files::isRegularFile).toList()) {
                Path to = dir.resolve(from.relativize(f).toString());
                Files.createDirectories(to.getParent());
                Files.copy(f, to);
            }
        }
        // IntelliJ's project folder, which the repository does not track (it is tool state): its
        // presence is what makes the migration keep left-out tests out of the IDE's compile too.
        write(dir, ".idea/misc.xml", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<project version=\"4\">\n</project>\n");
        // Its JUnit 4 test (PointJUnit4Test) compiles against JUnit 4 from the Maven repository, as the IDE had it.
        install(dir, "junit:junit:4.13.2");
        install(dir, "org.hamcrest:hamcrest-core:1.3");
        return dir;
    }

    /**
     * A migration with the library of this build (target/classes), JUnit from the test's own class
     * path, and an empty Maven repository beside {@code dir} ({@link #repository}) that nothing is
     * fetched into: a library a fixture needs is put there by {@link #install}.
     */
    /**
     * The 2025–26 layout in DIR: {@code Point} and {@code Vector} in primitives, an abstract
     * {@code geometries.api.Intersectable}, and {@code geometries.impl}'s {@code Sphere} (a course
     * class) and {@code Cube} (the student's own, using the api).
     */
    static void apiImpl(Path dir) throws IOException {
        write(dir, "src/primitives/Point.java", POINT);
        write(dir, "src/primitives/Vector.java", vector("primitives", "0, 0, 1"));
        write(dir, "src/geometries/api/Intersectable.java", "package geometries.api;\n\npublic abstract class Intersectable {\n}\n");
        write(dir, "src/geometries/impl/Sphere.java",
                "package geometries.impl;\n\nimport geometries.api.Intersectable;\n\npublic class Sphere extends Intersectable {\n}\n");
        write(dir, "src/geometries/impl/Cube.java", "package geometries.impl;\n\nimport geometries.api.Intersectable;\n\n"
                + "public class Cube {\n    public static Intersectable unit() { return null; }\n}\n");
    }

    static Migration migration(Path dir, OutputStream printed, OutputStream steps) {
        return migration(dir, printed, steps, Faults.NONE);
    }

    /** As {@link #migration(Path, OutputStream, OutputStream)}, stopped where {@code faults} says. */
    static Migration migration(Path dir, OutputStream printed, OutputStream steps, Faults faults) {
        return migration(dir, printed, steps, faults, Camera.class.getClassLoader());
    }

    /** As {@link #migration(Path, OutputStream, OutputStream, Faults)}, the library's classes asked of {@code library}. */
    static Migration migration(Path dir, OutputStream printed, OutputStream steps, Faults faults, ClassLoader library) {
        Toolchain mine;
        Path classes;
        try {
            mine = Toolchain.ofThisProcess();
            classes = Toolchain.location(Camera.class);
        } catch (MigrationException e) {
            throw new IllegalStateException("the test's own library: " + e.getMessage(), e);
        }
        List<Path> junit = Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
                .filter(p -> p.matches(".*(junit-jupiter-api|junit-jupiter-params|junit-platform-commons|opentest4j|apiguardian).*\\.jar"))
                .map(Path::of).toList();
        Toolchain tools = new Toolchain(classes, junit, repository(dir), mine.coordinates(),
                mine.junitVersion(), mine.jdk(), null);
        PrintStream out = new PrintStream(printed, true, StandardCharsets.UTF_8);
        return new Migration(tools, library, out, new PrintStream(steps, true, StandardCharsets.UTF_8), faults);
    }

    /** The Maven repository of {@link #migration}'s toolchain. */
    static Path repository(Path dir) {
        return dir.resolveSibling(dir.getFileName() + "-m2");
    }

    /**
     * Puts a jar of the test's own class path ({@code junit-4.13.2.jar}) into that repository as
     * {@code group:artifact:version}, as a student's Maven or IntelliJ would have it.
     */
    static Path install(Path dir, String coordinates) throws IOException {
        String[] c = coordinates.split(":");
        String name = c[1] + "-" + c[2] + ".jar";
        Path jar = Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator)).map(Path::of)
                .filter(p -> p.getFileName().toString().equals(name)).findFirst()
                .orElseThrow(() -> new IllegalStateException(name + " is not on the test class path (a test dependency in pom.xml)"));
        Path to = repository(dir).resolve(c[0].replace('.', '/')).resolve(c[1]).resolve(c[2]).resolve(name);
        Files.createDirectories(to.getParent());
        return Files.copy(jar, to, StandardCopyOption.REPLACE_EXISTING);
    }

    static void write(Path dir, String path, String text) throws IOException {
        Path file = dir.resolve(path);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }

    /** Every file under {@code dir} and its bytes, as text: two equal snapshots are the same tree. */
    static Map<String, String> snapshot(Path dir) throws IOException {
        Map<String, String> files = new TreeMap<>();
        try (Stream<Path> walk = Files.walk(dir)) {
            for (Path f : walk.filter(Files::isRegularFile).toList())
                files.put(dir.relativize(f).toString(), Files.readString(f, StandardCharsets.ISO_8859_1));
        }
        return files;
    }
}
