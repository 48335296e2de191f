package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.MissingResourceException;
import java.util.function.Consumer;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import geometries.Intersectable.Intersection;
import lighting.AmbientLight;
import primitives.Color;
import primitives.Double3;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.RayTracerType;
import scene.Scene;

/**
 * The 2025–26 (5786) course API, written the way that year's tests are written: its names only
 * ({@code calcIntersections}, {@code Intersection}, {@code constructRay(j, i)},
 * {@code Ray.origin()/direction()}, {@code _d1()}, values checked by {@code build()}), one nested
 * class per class under test. In package {@code geometries} because the course's tests call the
 * protected hook there. (5786 puts Geometry and Intersectable in {@code geometries.api} and the
 * shapes in {@code geometries.impl}; the library keeps {@code geometries}: see the README.)
 */
class Course5786Test {
    private static Camera.Builder view() {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -5), new Vector(0, 2, 0));
    }

    @Nested
    @DisplayName("Camera (5786: testBuild, testConstructRay)")
    class CameraTest {
        @ParameterizedTest(name = "{0}x{1} pixels, view plane {2}: pixel ({3},{4}) -> ({5},{6},-10)")
        @CsvSource({ "4, 4, 8, 1, 1, -1, 1", "4, 4, 8, 0, 0, -3, 3", "4, 4, 8, 1, 0, -1, 3", "3, 3, 6, 0, 1, -2, 0" })
        @DisplayName("constructRay(j, i) uses the builder's resolution; j is the column")
        void constructRay(int nX, int nY, double size, int j, int i, double x, double y) {
            Camera camera = view().setVpSize(size, size).setVpDistance(10).setResolution(nX, nY)
                    .setRayTracer(new Scene("5786"), RayTracerType.SIMPLE).build();
            Ray ray = camera.constructRay(j, i);
            assertThat(ray.origin()).isEqualTo(Point.ZERO);
            assertThat(ray.direction()).isEqualTo(new Vector(x, y, -10).normalize());
        }

        @Test
        @DisplayName("EP01-EP03: build() without resolution or tracer succeeds (a 1x1 image)")
        void buildsWithDefaults() {
            Camera.Builder builder = view().setVpSize(8, 8).setVpDistance(10);
            assertThatCode(builder::build).doesNotThrowAnyException();
            assertThat(builder.build().constructRay(0, 0).direction()).isEqualTo(new Vector(0, 0, -1));
            assertThatIllegalArgumentException().isThrownBy(() -> builder.build().constructRay(1, 0)).withMessageContaining("1x1");
        }

        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = '|', value = { "BV05 setVpSize(0, 8)|width|0.0", "BV06 setVpSize(-8, 8)|width|-8.0",
                "BV07 setVpDistance(0)|distance|0.0", "BV08 setVpDistance(-1)|distance|-1.0",
                "BV09 setResolution(0, 1)|resolution|0x1", "BV10 setResolution(-1, 1)|resolution|-1x1" })
        @DisplayName("bad values: the setters accept them, build() throws IllegalArgumentException naming the value")
        void badValuesFailBuild(String name, String what, String value) {
            Camera.Builder builder = view().setVpSize(8, 8).setVpDistance(10);
            Consumer<Camera.Builder> bad = switch (name.substring(0, 4)) {
                case "BV05" -> b -> b.setVpSize(0, 8);
                case "BV06" -> b -> b.setVpSize(-8, 8);
                case "BV07" -> b -> b.setVpDistance(0);
                case "BV08" -> b -> b.setVpDistance(-1);
                case "BV09" -> b -> b.setResolution(0, 1);
                default -> b -> b.setResolution(-1, 1);
            };
            assertThatCode(() -> bad.accept(builder)).as("the setter").doesNotThrowAnyException();
            assertThatIllegalArgumentException().isThrownBy(builder::build).withMessageContaining(what)
                    .withMessageContaining(value);
        }

        @Test
        @DisplayName("a missing location or direction is a MissingResourceException")
        void missingViewIsMissingResource() {
            assertThatThrownBy(Camera.getBuilder().setDirection(new Point(0, 0, -1)).setVpSize(1, 1).setVpDistance(1)::build)
                    .isInstanceOf(MissingResourceException.class).hasMessageContaining("location");
            assertThatThrownBy(Camera.getBuilder().setLocation(Point.ZERO).setVpSize(1, 1).setVpDistance(1)::build)
                    .isInstanceOf(MissingResourceException.class).hasMessageContaining("direction");
        }

        @Test
        @DisplayName("Camera.getBuilder(camera) / new Camera.Builder(camera): the same rays; a changed copy leaves the camera be")
        void builderFromACamera() {
            Camera camera = view().setVpSize(8, 8).setVpDistance(10).setResolution(4, 4).build();
            Camera copy = Camera.getBuilder(camera).build();
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) assertThat(copy.constructRay(j, i)).isEqualTo(camera.constructRay(j, i));
            Camera wider = new Camera.Builder(camera).setVpSize(16, 16).setResolution(2, 2).build();
            assertThat(wider.constructRay(0, 0).direction()).isEqualTo(new Vector(-4, 4, -10).normalize());
            assertThat(camera.constructRay(0, 0).direction()).as("the original").isEqualTo(new Vector(-3, 3, -10).normalize());
            assertThatIllegalArgumentException().as("a copy's bad value is checked by build(), as for any builder")
                    .isThrownBy(new Camera.Builder(camera).setVpDistance(-1)::build).withMessageContaining("-1.0");
        }

        @Test
        @DisplayName("a missing view-plane size or distance is an IllegalArgumentException")
        void missingViewPlaneIsIllegalArgument() {
            assertThatIllegalArgumentException().isThrownBy(view().setVpDistance(1)::build).withMessageContaining("view plane size");
            assertThatIllegalArgumentException().isThrownBy(view().setVpSize(1, 1)::build)
                    .withMessageContaining("view plane distance");
        }
    }

    @Nested
    @DisplayName("Ray (5786)")
    class RayTest {
        private final Ray ray = new Ray(new Point(1, 2, 3), new Vector(0, 0, 2));

        @Test
        @DisplayName("origin() and direction() (unit)")
        void accessors() {
            assertThat(ray.origin()).isEqualTo(new Point(1, 2, 3));
            assertThat(ray.direction()).isEqualTo(new Vector(0, 0, 1));
        }

        @Test
        @DisplayName("findClosestIntersection: the nearest; null for null and for an empty list")
        void findClosestIntersection() {
            Sphere s = new Sphere(new Point(1, 2, 10), 1);
            List<Intersection> list = List.of(new Intersection(s, new Point(1, 2, 11)), new Intersection(s, new Point(1, 2, 9)),
                    new Intersection(s, new Point(1, 2, 20)));
            assertThat(ray.findClosestIntersection(list)).isSameAs(list.get(1));
            assertThat(ray.findClosestIntersection(null)).isNull();
            assertThat(ray.findClosestIntersection(List.of())).isNull();
        }
    }

    @Nested
    @DisplayName("Double3 (5786 record spelling)")
    class Double3Test {
        @Test
        @DisplayName("_d1(), _d2(), _d3()")
        void components() {
            Double3 d = new Double3(1.5, -2, 7);
            assertThat(new double[] { d._d1(), d._d2(), d._d3() }).containsExactly(1.5, -2, 7);
        }
    }

    @Nested
    @DisplayName("Color (5786: equals within the tolerance, hashCode)")
    class ColorTest {
        @Test
        @DisplayName("equal channel by channel within the zero tolerance; assertEquals works as the course's tests use it")
        void equalsWithinTolerance() {
            Color c = new Color(100, 50.5, 0);
            assertEquals(new Color(100, 50.5, 0), c);
            assertEquals(new Color(100 + 1e-13, 50.5, 1e-13), c);
            assertNotEquals(new Color(100 + 1e-9, 50.5, 0), c);
            assertNotEquals(new Color(100, 50.5, 1e-9), c);
            assertThat(c).isNotEqualTo(new java.awt.Color(100, 50, 0)).isNotEqualTo(null);
            assertThat(new Color(20, 40, 60).scale(0.5)).isEqualTo(new Color(10, 20, 30));
            assertThat(new Color(10, 20, 30).add(new Color(1, 2, 3))).isEqualTo(new Color(11, 22, 33));
        }

        @Test
        @DisplayName("hashCode: equal colours hash alike (a constant, as no finer hash follows a tolerance)")
        void hashCodeConsistent() {
            Color c = new Color(100, 50.5, 0), near = new Color(100 + 1e-13, 50.5, 0);
            assertThat(c).isEqualTo(near).hasSameHashCodeAs(near);
            Set<Color> set = new HashSet<>(List.of(c, new Color(1, 2, 3)));
            assertThat(set).contains(near, new Color(1, 2, 3)).doesNotContain(new Color(1, 2, 4));
        }

        @Test
        @DisplayName("not transitive: a ≈ b and b ≈ c, yet a ≠ c (why the library never relies on it)")
        void notTransitive() {
            double step = 0x1p-41; // just below the tolerance 2^-40
            Color a = new Color(1, 1, 1), b = new Color(1 + step, 1, 1), c = new Color(1 + 2 * step, 1, 1);
            assertThat(a).isEqualTo(b);
            assertThat(b).isEqualTo(c);
            assertThat(a).isNotEqualTo(c);
        }

        @Test
        @DisplayName("AmbientLight(c).getIntensity() equals c")
        void ambientIntensity() {
            Color c = new Color(200, 100, 50);
            assertEquals(c, new AmbientLight(c).getIntensity());
            assertEquals(Color.BLACK, AmbientLight.NONE.getIntensity());
        }
    }

    @Nested
    @DisplayName("Cylinder, Tube and the tree: calcIntersectionsHelper null, a ray along the side (5786)")
    class CylinderTest {
        private final Cylinder cylinder = new Cylinder(1, new Ray(Point.ZERO, new Vector(0, 0, 1)), 2);

        @Test
        @DisplayName("a ray lying on the side, parallel to the axis, meets nothing (a tangent is no hit)")
        void alongTheSide() {
            assertThat(cylinder.calcIntersections(new Ray(new Point(1, 0, -1), new Vector(0, 0, 1)))).isNull();
            assertThat(cylinder.calcIntersections(new Ray(new Point(0, 1, 3), new Vector(0, 0, -1)))).isNull();
            assertThat(new Tube(1, new Ray(Point.ZERO, new Vector(0, 0, 1)))
                    .calcIntersections(new Ray(new Point(-1, 0, -1), new Vector(0, 0, 1)))).isNull();
            assertThat(cylinder.calcIntersections(new Ray(new Point(0.5, 0, -1), new Vector(0, 0, 1))))
                    .as("just inside: both caps").containsExactly(new Intersection(cylinder, new Point(0.5, 0, 0)),
                            new Intersection(cylinder, new Point(0.5, 0, 2)));
            assertThat(cylinder.calcIntersections(new Ray(new Point(2, 0, 3), new Vector(-1, 0, -1))))
                    .as("through the rims, not along the side: both rim points")
                    .containsExactly(new Intersection(cylinder, new Point(1, 0, 2)), new Intersection(cylinder, new Point(-1, 0, 0)));
        }

        @Test
        @DisplayName("calcIntersectionsHelper returns null, not an empty list: cylinder, and the BVH over shapes")
        void helperNull() {
            Ray miss = new Ray(new Point(5, 5, 5), new Vector(1, 0, 0));
            assertThat(cylinder.calcIntersectionsHelper(miss, Double.POSITIVE_INFINITY)).isNull();
            Ray up = new Ray(new Point(0, 0, -1), new Vector(0, 0, 1));
            assertThat(cylinder.calcIntersectionsHelper(up, 0.5)).isNull();
            Bvh tree = Bvh.build(new Geometries(cylinder, new Sphere(new Point(10, 0, 0), 1)));
            assertThat(tree.calcIntersectionsHelper(miss, Double.POSITIVE_INFINITY)).isNull();
            assertThat(tree.calcIntersectionsHelper(up, 0.5)).isNull();
            assertThat(tree.findGeoIntersectionsHelper(up, 0.5)).isNull();
            assertThat(tree.calcIntersectionsHelper(up, 1)).containsExactly(new Intersection(cylinder, new Point(0, 0, 0)));
        }
    }

    @Nested
    @DisplayName("Intersectable (5786: calcIntersections)")
    class IntersectableTest {
        private final Triangle triangle = new Triangle(new Point(0, 0, 0), new Point(2, 0, 0), new Point(0, 2, 0));
        private final Ray down = new Ray(new Point(0.5, 0.5, 3), new Vector(0, 0, -1));

        @Test
        @DisplayName("the protected helper and the public query find the hit, as an Intersection with the material")
        void triangleHit() {
            Intersection expected = new Intersection(triangle, new Point(0.5, 0.5, 0));
            assertThat(triangle.calcIntersectionsHelper(down, Double.POSITIVE_INFINITY)).containsExactly(expected);
            assertThat(triangle.calcIntersections(down)).containsExactly(expected);
            assertThat(triangle.calcIntersections(down, 3)).as("exactly at maxDistance: included").containsExactly(expected);
            assertThat(triangle.calcIntersections(down).get(0).material).isSameAs(triangle.getMaterial());
        }

        @Test
        @DisplayName("no hit gives null: beyond maxDistance, outside the triangle, an empty Geometries")
        void noHitIsNull() {
            assertThat(triangle.calcIntersections(down, 2.9)).isNull();
            assertThat(triangle.calcIntersections(new Ray(new Point(3, 3, 3), new Vector(0, 0, -1)))).isNull();
            assertThat(new Geometries().calcIntersections(down)).isNull();
        }
    }

    /** A shape as a 5786 student writes it: only the 5786 hook, no bounding box. */
    static final class Ball extends Geometry {
        private final Sphere surface = new Sphere(UserGeometryScenes.CENTER, UserGeometryScenes.RADIUS);

        @Override
        public Vector getNormal(Point point) {
            return surface.getNormal(point);
        }

        @Override
        protected List<Intersection> calcIntersectionsHelper(Ray ray, double maxDistance) {
            List<Intersection> found = surface.calcIntersections(ray, maxDistance);
            if (found == null) return null;
            List<Intersection> mine = new ArrayList<>();
            for (Intersection i : found) mine.add(new Intersection(this, i.point));
            return mine;
        }
    }

    @Nested
    @DisplayName("a user's own geometry (5786 hook)")
    class UserGeometryTest implements UserShapeContract {
        @Override
        public Geometry newShape() {
            return new Ball();
        }
    }
}
