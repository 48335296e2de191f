package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** {@link Geometry#isLibraryShape()}: exactly the library's shape classes, never a subclass or a user's shape. */
class LibraryShapeTest {
    private static final Point A = new Point(0, 0, 0), B = new Point(1, 0, 0), C = new Point(0, 1, 0);
    private static final Ray AXIS = new Ray(A, new Vector(0, 0, 1));

    /** A user's shape: a sphere under another name, which could answer anything. */
    private static final class Ball extends Sphere {
        Ball() {
            super(A, 1);
        }
    }

    static Stream<Geometry> library() {
        return Stream.of(new Sphere(A, 1), new Triangle(A, B, C), new Polygon(A, B, new Point(1, 1, 0), C),
                new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 }),
                new Plane(A, new Vector(0, 0, 1)), new Tube(1, AXIS), new Cylinder(1, AXIS, 2));
    }

    static Stream<Geometry> users() {
        return Stream.of(new Ball(), new Triangle(A, B, C) {
        }, new Polygon(A, B, C) {
        }, new Plane(A, new Vector(0, 0, 1)) {
        }, new Geometry() {
            @Override
            public Vector getNormal(Point point) {
                return new Vector(0, 0, 1);
            }

            @Override
            protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                return null;
            }
        });
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("library")
    @DisplayName("each library shape class")
    void library(Geometry g) {
        assertThat(g.isLibraryShape()).as(g.getClass().getName()).isTrue();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("users")
    @DisplayName("a subclass of a library shape, or a shape of the user's own")
    void users(Geometry g) {
        assertThat(g.isLibraryShape()).as(g.getClass().getName()).isFalse();
    }
}
