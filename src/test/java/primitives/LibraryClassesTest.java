package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Cylinder;
import geometries.Geometry;
import geometries.LeanQueries;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightQueries;
import lighting.PointLight;
import lighting.SpotLight;

/**
 * The one rule by which the library tells its own objects from a user's ({@link LibraryClasses}):
 * an object of exactly one of the library's shape or light classes is the library's; an object of
 * any subclass is the user's, whether it overrides a course method or not. The library trusts its
 * own arithmetic for the first (packed copies in a tree, a tree or shadow occluder kept from one
 * ray or render to the next, a light's doubles forms) and asks the course methods of the second.
 */
class LibraryClassesTest {
    private static final Point A = new Point(0, 0, 0), B = new Point(1, 0, 0), C = new Point(0, 1, 0);
    private static final Ray AXIS = new Ray(A, new Vector(0, 0, 1));
    private static final double[] ONE_TRIANGLE = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };

    /** A user's sphere that overrides nothing: a sphere under another name, which could change. */
    private static final class Ball extends Sphere {
        Ball() {
            super(A, 1);
        }
    }

    /** A user's sphere that overrides the 2023–24 intersection hook. */
    private static final class Dented extends Sphere {
        Dented() {
            super(A, 1);
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            return null;
        }
    }

    /** A user's triangle that overrides the course normal. */
    private static final class Flipped extends Triangle {
        Flipped() {
            super(A, B, C);
        }

        @Override
        public Vector getNormal(Point point) {
            return super.getNormal(point).scale(-1);
        }
    }

    /** A user's mesh that overrides nothing. */
    private static final class MyMesh extends TriangleMesh {
        MyMesh() {
            super(ONE_TRIANGLE, new int[] { 0, 1, 2 });
        }
    }

    /** A user's spot light that overrides its falloff. */
    private static final class Dimmed extends SpotLight {
        Dimmed() {
            super(new Color(300, 200, 100), new Point(1, 2, 3), new Vector(0, 0, -1));
        }

        @Override
        protected double attenuation(Point p) {
            return 1 / (1 + p.distance(position));
        }
    }

    /** A user's point light that overrides nothing. */
    private static final class Lamp extends PointLight {
        Lamp() {
            super(new Color(1, 2, 3), A);
        }
    }

    /** A user's directional light that overrides its direction. */
    private static final class Tilted extends DirectionalLight {
        Tilted() {
            super(new Color(10, 20, 30), new Vector(0, 0, -1));
        }

        @Override
        public Vector getL(Point p) {
            return new Vector(1, 1, -1).normalize();
        }
    }

    static Stream<Arguments> objects() {
        return Stream.of(
                Arguments.of("Sphere", new Sphere(A, 1), true),
                Arguments.of("Triangle", new Triangle(A, B, C), true),
                Arguments.of("Polygon", new Polygon(A, B, new Point(1, 1, 0), C), true),
                Arguments.of("Plane", new Plane(A, new Vector(0, 0, 1)), true),
                Arguments.of("Tube", new Tube(1, AXIS), true),
                Arguments.of("Cylinder", new Cylinder(1, AXIS, 2), true),
                Arguments.of("TriangleMesh", new TriangleMesh(ONE_TRIANGLE, new int[] { 0, 1, 2 }), true),
                Arguments.of("AmbientLight", new AmbientLight(new Color(10, 10, 10)), true),
                Arguments.of("DirectionalLight", new DirectionalLight(new Color(1, 1, 1), new Vector(0, 0, -1)), true),
                Arguments.of("PointLight", new PointLight(new Color(1, 1, 1), A), true),
                Arguments.of("SpotLight", new SpotLight(new Color(1, 1, 1), A, new Vector(0, 0, -1)), true),
                Arguments.of("a sphere subclass overriding nothing", new Ball(), false),
                Arguments.of("a sphere subclass overriding an intersection hook", new Dented(), false),
                Arguments.of("a triangle subclass overriding the normal", new Flipped(), false),
                Arguments.of("an anonymous polygon subclass", new Polygon(A, B, C) {
                }, false),
                Arguments.of("an anonymous plane subclass", new Plane(A, new Vector(0, 0, 1)) {
                }, false),
                Arguments.of("an anonymous cylinder subclass", new Cylinder(1, AXIS, 2) {
                }, false),
                Arguments.of("a mesh subclass overriding nothing", new MyMesh(), false),
                Arguments.of("a shape of the user's own", new Geometry() {
                    @Override
                    public Vector getNormal(Point point) {
                        return new Vector(0, 0, 1);
                    }

                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return null;
                    }
                }, false),
                Arguments.of("a spot light subclass overriding its falloff", new Dimmed(), false),
                Arguments.of("a point light subclass overriding nothing", new Lamp(), false),
                Arguments.of("a directional light subclass overriding its direction", new Tilted(), false),
                Arguments.of("an anonymous ambient light subclass", new AmbientLight(new Color(1, 1, 1)) {
                }, false));
    }

    /** The library's answer for {@code object}, through the predicate its package uses. */
    private static boolean library(Object object) {
        if (object instanceof Geometry g) return LeanQueries.isLibraryShape(g);
        if (object instanceof PointLight || object instanceof DirectionalLight || object instanceof AmbientLight)
            return LightQueries.isLibraryLight(object); // a spot light is a point light
        throw new AssertionError("no predicate for " + object.getClass());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("objects")
    @DisplayName("exactly the library's shape and light classes are the library's; every subclass is the user's")
    void theOneRule(String name, Object object, boolean expected) {
        assertThat(library(object)).as(name).isEqualTo(expected);
        if (object instanceof Geometry g)
            assertThat(LeanQueries.isLibraryPrimitive(g)).as("%s: a library shape of one intersection test", name)
                    .isEqualTo(expected && !(g instanceof TriangleMesh));
    }

    @Nested
    @DisplayName("the mechanism")
    class Mechanism {
        private final LibraryClasses spheres = LibraryClasses.of(Sphere.class);

        @Test
        @DisplayName("contains: the exact class only")
        void exactAndInherited() {
            assertThat(spheres.contains(new Sphere(A, 1))).isTrue();
            assertThat(spheres.contains(new Ball())).isFalse();
        }

        @Test
        @DisplayName("and: the union; a class listed twice is refused")
        void union() {
            LibraryClasses both = spheres.and(Triangle.class);
            assertThat(both.contains(new Triangle(A, B, C))).isTrue();
            assertThat(both.contains(new Sphere(A, 1))).isTrue();
            assertThatIllegalArgumentException().isThrownBy(() -> both.and(Sphere.class));
        }
    }
}
