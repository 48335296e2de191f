package app.migrate;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

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

    /** A test that calls the student's own {@code Vector.rotate}: it cannot compile against the library. */
    static String rotateTest(String pkg) {
        return "package " + pkg + ";\n\nimport org.junit.jupiter.api.Test;\nimport primitives.Vector;\n\n"
                + "class RotateTest {\n    @Test\n    void rotates() {\n\n        new Vector(1, 0, 0).rotate(90);\n    }\n}\n";
    }

    /** A test class whose name Surefire's default would not run. */
    static final String INTEGRATION = """
            package renderer;

            import static org.junit.jupiter.api.Assertions.assertEquals;

            import org.junit.jupiter.api.Test;
            import primitives.Vector;

            class CameraIntersectionIntegration {
                @Test
                void axis() {
                    assertEquals(1, Vector.Z.length(), 1e-10);
                }
            }
            """;

    /** An extra class of the student's on the course API: it compiles against the library. */
    static final String HELPER = """
            package renderer;

            import primitives.Point;
            import primitives.Vector;

            public class PixelHelper {
                public static Vector between(Point a, Point b) { return b.subtract(a); }
            }
            """;

    /** An extra class that uses the student's own method: set aside. */
    static final String TURNER = """
            package renderer;

            import primitives.Vector;

            public class Turner {
                public static Vector quarter(Vector v) { return v.rotate(90); }
            }
            """;

    /** The student's own Ray, Intersectable (5784's hook) and Geometry: what an extra shape of theirs extends. */
    static final String RAY = """
            package primitives;

            public class Ray {
                public Ray(Point head, Vector direction) { }
            }
            """;

    static final String INTERSECTABLE = """
            package geometries;

            import java.util.List;
            import primitives.Point;
            import primitives.Ray;

            public abstract class Intersectable {
                public static class GeoPoint {
                    public GeoPoint(Geometry geometry, Point point) { }
                }

                protected abstract List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance);
            }
            """;

    static final String GEOMETRY = """
            package geometries;

            import primitives.Point;
            import primitives.Vector;

            public abstract class Geometry extends Intersectable {
                public abstract Vector getNormal(Point point);
            }
            """;

    /** An extra shape on the course API (the 5784 hook): it compiles against the library's Geometry too. */
    static final String CUBE = """
            package geometries;

            import java.util.List;
            import primitives.Point;
            import primitives.Ray;
            import primitives.Vector;

            public class Cube extends Geometry {
                @Override
                public Vector getNormal(Point point) { return new Vector(0, 0, 1); }

                @Override
                protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) { return null; }
            }
            """;

    /** An extra package: a scene parser of the student's on the course API. */
    static final String PARSER = """
            package parser;

            import primitives.Point;

            public final class Points {
                public static Point parse(String text) {
                    String[] p = text.trim().split("\\s+");
                    return new Point(Double.parseDouble(p[0]), Double.parseDouble(p[1]), Double.parseDouble(p[2]));
                }
            }
            """;

    /** A test of the extra shape and the extra package: it passes on the library. */
    static final String CUBE_TEST = """
            package geometries;

            import static org.junit.jupiter.api.Assertions.assertEquals;

            import org.junit.jupiter.api.Test;
            import parser.Points;
            import primitives.Vector;

            class CubeTests {
                @Test
                void normal() {
                    assertEquals(new Vector(0, 0, 1), new Cube().getNormal(Points.parse("1 2 3")));
                }
            }
            """;

    /** The IntelliJ module file of a course project: src/ and unittests/. */
    static final String IML = """
            <?xml version="1.0" encoding="UTF-8"?>
            <module type="JAVA_MODULE" version="4">
              <component name="NewModuleRootManager" inherit-compiler-output="true">
                <exclude-output />
                <content url="file://$MODULE_DIR$">
                  <sourceFolder url="file://$MODULE_DIR$/src" isTestSource="false" />
                  <sourceFolder url="file://$MODULE_DIR$/unittests" isTestSource="true" />
                </content>
                <orderEntry type="inheritedJdk" />
                <orderEntry type="sourceFolder" forTests="false" />
              </component>
            </module>
            """;

    /** A 2024–25 IntelliJ project: src/, unittests/, an .iml, no pom. */
    static Path intellij(Path dir) throws IOException {
        write(dir, "course.iml", IML);
        write(dir, "src/primitives/Point.java", POINT);
        write(dir, "src/primitives/Vector.java", vector("primitives", "0, 0, 1"));
        write(dir, "src/renderer/PixelHelper.java", HELPER);
        write(dir, "src/renderer/Turner.java", TURNER);
        write(dir, "src/primitives/Ray.java", RAY);
        write(dir, "src/geometries/Intersectable.java", INTERSECTABLE);
        write(dir, "src/geometries/Geometry.java", GEOMETRY);
        write(dir, "src/geometries/Cube.java", CUBE);
        write(dir, "src/parser/Points.java", PARSER);
        write(dir, "unittests/geometries/CubeTests.java", CUBE_TEST);
        write(dir, ".idea/misc.xml", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<project version=\"4\">\n</project>\n");
        write(dir, "unittests/primitives/VectorTests.java", vectorTest("primitives"));
        write(dir, "unittests/primitives/RotateTest.java", rotateTest("primitives"));
        write(dir, "unittests/renderer/CameraIntersectionIntegration.java", INTEGRATION);
        return dir;
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
