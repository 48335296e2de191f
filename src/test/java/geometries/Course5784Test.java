package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;
import static primitives.Util.random;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import geometries.Intersectable.GeoPoint;
import geometries.Intersectable.Intersection;
import lighting.AmbientLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBase;
import renderer.SimpleRayTracer;
import scene.Scene;

/**
 * The 2023–24 (5784) course API, written the way that year's tests are written: its names only
 * ({@code findGeoIntersections}, {@code GeoPoint}, {@code SimpleRayTracer}, {@code setImageWriter},
 * {@code writeToImage()}, {@code Util.random}), one nested class per class under test. It lives in
 * package {@code geometries} because the course's tests call the protected hook there.
 */
class Course5784Test {

    @Nested
    @DisplayName("Util (5784)")
    class UtilTest {
        @Test
        @DisplayName("random(min, max) stays in [min, max) and covers it evenly")
        void randomIsUniformInRange() {
            double sum = 0;
            double lowest = Double.POSITIVE_INFINITY, highest = Double.NEGATIVE_INFINITY;
            int n = 20_000;
            for (int k = 0; k < n; ++k) {
                double x = random(2, 5);
                assertThat(x).isGreaterThanOrEqualTo(2).isLessThan(5);
                sum += x;
                lowest = Math.min(lowest, x);
                highest = Math.max(highest, x);
            }
            assertThat(sum / n).as("mean of uniform [2,5)").isCloseTo(3.5, within(0.05));
            assertThat(lowest).isLessThan(2.01);
            assertThat(highest).isGreaterThan(4.99);
        }

        @Test
        @DisplayName("random(x, x) is x")
        void emptyRange() {
            assertThat(random(7, 7)).isEqualTo(7);
        }

        @ParameterizedTest(name = "random({0}, {1}) is rejected")
        @CsvSource({ "5, 2, 2.0", "NaN, 1, NaN", "0, Infinity, Infinity" })
        void badBounds(double min, double max, String named) {
            assertThatIllegalArgumentException().isThrownBy(() -> random(min, max)).withMessageContaining(named);
        }
    }

    @Nested
    @DisplayName("GeoPoint and findGeoIntersections (5784)")
    class IntersectableTest {
        private final Sphere sphere = new Sphere(new Point(1, 0, 0), 1);

        @Test
        @DisplayName("the protected helper and the public query find the two points of a chord")
        void sphereChord() {
            Ray ray = new Ray(new Point(-1, 0.6, 0), new Vector(1, 0, 0));
            List<GeoPoint> expected = List.of(new GeoPoint(sphere, new Point(0.2, 0.6, 0)),
                    new GeoPoint(sphere, new Point(1.8, 0.6, 0)));
            assertThat(sphere.findGeoIntersectionsHelper(ray, Double.POSITIVE_INFINITY)).containsExactlyInAnyOrderElementsOf(expected);
            assertThat(sphere.findGeoIntersections(ray)).containsExactlyInAnyOrderElementsOf(expected);
            assertThat(ray.findClosestGeoPoint(sphere.findGeoIntersections(ray))).isEqualTo(expected.get(0));
        }

        @Test
        @DisplayName("no hit gives null, also for an empty Geometries")
        void noHitIsNull() {
            Ray away = new Ray(new Point(-1, 0, 0), new Vector(-1, 0, 0));
            assertThat(sphere.findGeoIntersections(away)).isNull();
            assertThat(new Geometries().findGeoIntersections(away)).isNull();
            assertThat(new Geometries(sphere).findIntersections(away)).isNull();
        }

        @Test
        @DisplayName("GeoPoints are equal by value, and never equal to a later year's Intersection")
        void geoPointEquality() {
            Point p = new Point(0.2, 0.6, 0);
            assertThat(new GeoPoint(sphere, p)).isEqualTo(new GeoPoint(sphere, new Point(0.2, 0.6, 0)));
            assertThat(new GeoPoint(sphere, p)).isNotEqualTo(new GeoPoint(new Sphere(new Point(1, 0, 0), 1), p));
            assertThat(new GeoPoint(sphere, p)).isNotEqualTo(new Intersection(sphere, p));
            assertThat(new Intersection(sphere, p)).isNotEqualTo(new GeoPoint(sphere, p));
        }

        /** A user's geometry with value equality of its own: every Label of one text is equal. */
        static final class Label extends Geometry {
            private final String text;

            Label(String text) {
                this.text = text;
            }

            @Override
            public Vector getNormal(Point point) {
                return new Vector(0, 0, 1);
            }

            @Override
            protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                return null;
            }

            @Override
            public boolean equals(Object obj) {
                return obj instanceof Label other && text.equals(other.text);
            }

            @Override
            public int hashCode() {
                return text.hashCode();
            }
        }

        @Test
        @DisplayName("GeoPoint compares geometries by value; Intersection (5785+) needs the same instance")
        void valueVersusInstance() {
            Point p = new Point(1, 2, 3);
            Label a = new Label("x"), b = new Label("x");
            assertThat(new GeoPoint(a, p)).isEqualTo(new GeoPoint(b, p)).hasSameHashCodeAs(new GeoPoint(b, p));
            assertThat(new GeoPoint(a, p)).isNotEqualTo(new GeoPoint(new Label("y"), p));
            assertThat(new Intersection(a, p)).isNotEqualTo(new Intersection(b, p));
            assertThat(new Intersection(a, p)).isEqualTo(new Intersection(a, new Point(1, 2, 3)));
        }
    }

    /** A shape as a 5784 student writes it: only the 5784 hook, no bounding box. */
    static final class Ball extends Geometry {
        private final Sphere surface = new Sphere(UserGeometryScenes.CENTER, UserGeometryScenes.RADIUS);

        @Override
        public Vector getNormal(Point point) {
            return surface.getNormal(point);
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            List<GeoPoint> found = surface.findGeoIntersections(ray, maxDistance);
            if (found == null) return null;
            List<GeoPoint> mine = new ArrayList<>();
            for (GeoPoint gp : found) mine.add(new GeoPoint(this, gp.point));
            return mine;
        }
    }

    @Nested
    @DisplayName("a user's own geometry (5784 hook)")
    class UserGeometryTest implements UserShapeContract {
        @Override
        public Geometry newShape() {
            return new Ball();
        }
    }

    @Nested
    @DisplayName("SimpleRayTracer (5784)")
    class SimpleRayTracerTest {
        @Test
        @DisplayName("emission plus the ambient light (scaled by its kA) on a hit, the background on a miss")
        void traceRay() {
            Scene scene = new Scene("5784").setBackground(new Color(1, 2, 3))
                    .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
            scene.geometries.add(new Sphere(new Point(0, 0, -50), 10).setEmission(new Color(0, 0, 100)));
            RayTracerBase tracer = new SimpleRayTracer(scene);
            Color hit = tracer.traceRay(new Ray(Point.ZERO, new Vector(0, 0, -1)));
            assertThat(new double[] { hit.getR(), hit.getG(), hit.getB() }).containsExactly(25.5, 25.5, 125.5);
            Color miss = tracer.traceRay(new Ray(Point.ZERO, new Vector(0, 0, 1)));
            assertThat(new double[] { miss.getR(), miss.getG(), miss.getB() }).containsExactly(1, 2, 3);
        }
    }

    @Nested
    @DisplayName("Camera with an image writer (5784)")
    class CameraTest {
        @Test
        @DisplayName("setImageWriter, setRayTracer(tracer), renderImage, printGrid, writeToImage()")
        void renderAndWrite() throws Exception {
            Scene scene = new Scene("5784 camera").setBackground(new Color(0, 0, 255));
            ImageWriter writer = new ImageWriter("course-years/5784", 4, 3);
            Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                    .setVpSize(4, 3).setVpDistance(1).setImageWriter(writer).setRayTracer(new SimpleRayTracer(scene))
                    .setSummary(false).build().renderImage().printGrid(2, new Color(255, 0, 0)).writeToImage();
            assertThat(writer.getRgb(1, 1)).as("background").isEqualTo(0x0000FF);
            assertThat(writer.getRgb(2, 1)).as("grid column").isEqualTo(0xFF0000);
            assertThat(Files.exists(writer.getPath())).isTrue();
        }

        @Test
        @DisplayName("getBuilder(camera): a second view rendered into the same image writer, which setImageWriter shares")
        void secondViewSharesTheWriter() {
            Scene scene = new Scene("5784 views").setBackground(new Color(0, 255, 0));
            scene.geometries.add(new Sphere(new Point(0, 0, -10), 1).setEmission(new Color(255, 0, 0)));
            ImageWriter writer = new ImageWriter("course-years/5784-views", 3, 3);
            Camera front = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Vector.Y)
                    .setVpSize(3, 3).setVpDistance(10).setImageWriter(writer).setRayTracer(new SimpleRayTracer(scene))
                    .setSummary(false).build().renderImage();
            assertThat(writer.getRgb(1, 1)).as("the sphere ahead").isEqualTo(0xFF0000);
            Camera.getBuilder(front).setLocation(new Point(0, 0, -20)).build().renderImage();
            assertThat(writer.getRgb(1, 1)).as("from behind the sphere, looking away: the background").isEqualTo(0x00FF00);
        }

        @Test
        @DisplayName("constructRay(nX, nY, j, i): the corner pixel of a 3x3 view plane")
        void constructRay() {
            Camera camera = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                    .setVpSize(3, 3).setVpDistance(1).setImageWriter(new ImageWriter("unused", 3, 3))
                    .setRayTracer(new SimpleRayTracer(new Scene("unused"))).build();
            assertThat(camera.constructRay(3, 3, 0, 0)).isEqualTo(new Ray(Point.ZERO, new Vector(-1, 1, -1)));
        }
    }

    @Nested
    @DisplayName("PointLight and SpotLight (the setKC/KL/KQ spelling of some 5784 cohorts)")
    class LightTest {
        @Test
        @DisplayName("attenuation 1 / (kC + kL d + kQ d^2) set with the upper-case setters")
        void upperCaseSetters() {
            Color at2 = new PointLight(new Color(90, 90, 90), Point.ZERO).setKC(1).setKL(0.5).setKQ(0.25)
                    .getIntensity(new Point(2, 0, 0));
            assertThat(at2.getR()).isCloseTo(30, within(1e-12));
            SpotLight spot = new SpotLight(new Color(90, 90, 90), Point.ZERO, new Vector(1, 0, 0)).setKC(1).setKL(0.5)
                    .setKQ(0.25).setNarrowBeam(1);
            assertThat(spot.getIntensity(new Point(2, 0, 0)).getR()).isCloseTo(30, within(1e-12));
            assertThatIllegalArgumentException().isThrownBy(() -> new PointLight(Color.BLACK, Point.ZERO).setKL(-1))
                    .withMessageContaining("kL").withMessageContaining("-1");
        }

        @Test
        @DisplayName("the lower-case-k setters setkC/kL/kQ: the same attenuation, chaining on each light's own type")
        void lowerCaseKSetters() {
            PointLight point = new PointLight(new Color(90, 90, 90), Point.ZERO).setkC(1).setkL(0.5).setkQ(0.25);
            assertThat(point.getIntensity(new Point(2, 0, 0)).getR()).isCloseTo(30, within(1e-12));
            SpotLight spot = new SpotLight(new Color(90, 90, 90), Point.ZERO, new Vector(1, 0, 0)).setkC(1).setkL(0.5)
                    .setkQ(0.25).setNarrowBeam(1); // setNarrowBeam compiles only on a SpotLight
            assertThat(spot.getIntensity(new Point(2, 0, 0)).getR()).isCloseTo(30, within(1e-12));
            assertThatIllegalArgumentException().isThrownBy(() -> new SpotLight(Color.BLACK, Point.ZERO, Vector.X).setkQ(-0.5))
                    .withMessageContaining("kQ").withMessageContaining("-0.5");
            assertThatIllegalArgumentException().isThrownBy(() -> new PointLight(Color.BLACK, Point.ZERO).setkC(Double.NaN))
                    .withMessageContaining("kC").withMessageContaining("NaN");
        }

        @Test
        @DisplayName("a spot light's intensity at its own position: an IllegalArgumentException naming the point")
        void spotAtItsOwnPosition() {
            SpotLight spot = new SpotLight(new Color(90, 90, 90), new Point(1, 2, 3), new Vector(1, 0, 0));
            assertThatIllegalArgumentException().isThrownBy(() -> spot.getIntensity(new Point(1, 2, 3)))
                    .withMessageContaining("(1.0,2.0,3.0)").withMessageContaining("light's position");
            assertThatIllegalArgumentException().isThrownBy(() -> spot.getL(new Point(1, 2, 3)))
                    .withMessageContaining("(1.0,2.0,3.0)").withMessageContaining("light's position");
        }
    }

    @Nested
    @DisplayName("Material (5784 setters, and the kA that 5785 added)")
    class MaterialTest {
        @Test
        @DisplayName("the ambient light's kA and the material's kA compose: I_A * kA(light) * kA(material)")
        void ambientComposes() {
            Scene scene = new Scene("kA").setAmbientLight(new AmbientLight(new Color(200, 100, 50), 0.5));
            scene.geometries.add(new Sphere(new Point(0, 0, -50), 10).setMaterial(new Material().setKd(0.3).setKA(0.4)));
            Color c = new SimpleRayTracer(scene).traceRay(new Ray(Point.ZERO, new Vector(0, 0, -1)));
            assertThat(new double[] { c.getR(), c.getG(), c.getB() })
                    .containsExactly(new double[] { 40, 20, 10 }, within(1e-12));
        }

        @Test
        @DisplayName("the lower-case-k setters setkA/kD/kS/kT/kR (double and Double3) set the same fields")
        void lowerCaseKSetters() {
            Material m = new Material().setkA(0.1).setkD(new Double3(0.2, 0.3, 0.4)).setkS(0.5).setkT(new Double3(0.6))
                    .setkR(0.7);
            assertThat(m.kA).isEqualTo(new Double3(0.1));
            assertThat(m.kD).isEqualTo(new Double3(0.2, 0.3, 0.4));
            assertThat(m.kS).isEqualTo(new Double3(0.5));
            assertThat(m.kT).isEqualTo(new Double3(0.6));
            assertThat(m.kR).isEqualTo(new Double3(0.7));
            m.setkA(new Double3(1, 2, 3)).setkD(0.8).setkS(new Double3(0.9, 1, 1.1)).setkT(0.25).setkR(new Double3(0.5, 0, 1));
            assertThat(m.kA).isEqualTo(new Double3(1, 2, 3));
            assertThat(m.kD).isEqualTo(new Double3(0.8));
            assertThat(m.kS).isEqualTo(new Double3(0.9, 1, 1.1));
            assertThat(m.kT).isEqualTo(new Double3(0.25));
            assertThat(m.kR).isEqualTo(new Double3(0.5, 0, 1));
        }

        @Test
        @DisplayName("bad lower-case-k coefficients are rejected like their twins, naming them")
        void lowerCaseKBadValues() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setkD(-0.5)).withMessageContaining("kD")
                    .withMessageContaining("-0.5");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setkT(new Double3(0.5, 1.5, 0)))
                    .withMessageContaining("kT").withMessageContaining("1.5");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setkR(2)).withMessageContaining("kR")
                    .withMessageContaining("2.0");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setkA(Double.NaN))
                    .withMessageContaining("kA").withMessageContaining("NaN");
        }
    }

    @Nested
    @DisplayName("Vector.X, Y, Z (the axis names of several 5784 cohorts)")
    class VectorTest {
        @Test
        @DisplayName("the positive unit axes, the very objects AXIS_X/Y/Z")
        void axes() {
            assertThat(new double[] { Vector.X.getX(), Vector.X.getY(), Vector.X.getZ() }).containsExactly(1, 0, 0);
            assertThat(new double[] { Vector.Y.getX(), Vector.Y.getY(), Vector.Y.getZ() }).containsExactly(0, 1, 0);
            assertThat(new double[] { Vector.Z.getX(), Vector.Z.getY(), Vector.Z.getZ() }).containsExactly(0, 0, 1);
            assertThat(Vector.X).isSameAs(Vector.AXIS_X);
            assertThat(Vector.Y).isSameAs(Vector.AXIS_Y);
            assertThat(Vector.Z).isSameAs(Vector.AXIS_Z);
            assertThat(Vector.X.crossProduct(Vector.Y)).as("right-handed").isEqualTo(Vector.Z);
        }

        @Test
        @DisplayName("the lecturer's render tests: setDirection(Point.ZERO, Vector.Y) from (0,0,1000)")
        void lookAtTheOrigin() {
            Camera camera = Camera.getBuilder().setLocation(new Point(0, 0, 1000)).setDirection(Point.ZERO, Vector.Y)
                    .setVpSize(200, 200).setVpDistance(1000).setImageWriter(new ImageWriter("unused", 2, 2))
                    .setRayTracer(new SimpleRayTracer(new Scene("unused"))).build();
            assertThat(camera.getVTo()).isEqualTo(new Vector(0, 0, -1));
            assertThat(camera.getVUp()).isEqualTo(Vector.Y);
            assertThat(camera.getVRight()).isEqualTo(Vector.X);
            assertThat(camera.constructRay(2, 2, 0, 0)).isEqualTo(new Ray(new Point(0, 0, 1000), new Vector(-50, 50, -1000)));
        }
    }

    @Nested
    @DisplayName("findIntersections(ray, maxDistance) and the hook's null (5784)")
    class DistanceTest {
        private final Sphere sphere = new Sphere(new Point(0, 0, -5), 1);
        private final Ray down = new Ray(Point.ZERO, new Vector(0, 0, -1));

        @Test
        @DisplayName("findIntersections(ray, max): the points within max, the one at max included; none: null")
        void pointsWithinDistance() {
            assertThat(sphere.findIntersections(down, 10)).containsExactly(new Point(0, 0, -4), new Point(0, 0, -6));
            assertThat(sphere.findIntersections(down, 5)).containsExactly(new Point(0, 0, -4));
            assertThat(sphere.findIntersections(down, 4)).as("exactly at maxDistance").containsExactly(new Point(0, 0, -4));
            assertThat(sphere.findIntersections(down, 3.9)).isNull();
            assertThat(new Geometries(sphere, new Plane(new Point(0, 0, -2), new Vector(0, 0, 1))).findIntersections(down, 4.5))
                    .containsExactlyInAnyOrder(new Point(0, 0, -2), new Point(0, 0, -4));
        }

        @Test
        @DisplayName("findGeoIntersectionsHelper returns null, not an empty list, when both hits are beyond maxDistance")
        void helperNullBeyondDistance() {
            assertThat(sphere.findGeoIntersectionsHelper(down, 3)).isNull();
            assertThat(sphere.findGeoIntersectionsHelper(new Ray(Point.ZERO, new Vector(0, 0, 1)), 100)).isNull();
            Tube tube = new Tube(1, new Ray(new Point(0, 5, 0), Vector.X));
            assertThat(tube.findGeoIntersectionsHelper(new Ray(Point.ZERO, Vector.Y), 3)).isNull();
            assertThat(tube.findGeoIntersectionsHelper(new Ray(Point.ZERO, Vector.Y), 4)).containsExactly(
                    new GeoPoint(tube, new Point(0, 4, 0)));
        }
    }

    @Nested
    @DisplayName("Cylinder(height, radius, axis) (the order of one 5784 cohort)")
    class CylinderTest {
        @Test
        @DisplayName("the same cylinder as (radius, axis, height)")
        void heightRadiusAxis() {
            Ray axis = new Ray(Point.ZERO, Vector.Z);
            Cylinder cylinder = new Cylinder(2, 1, axis);
            assertThat(cylinder.getHeight()).isEqualTo(2);
            assertThat(cylinder.getRadius()).isEqualTo(1);
            assertThat(cylinder.getAxis()).isSameAs(axis);
            Ray across = new Ray(new Point(-3, 0, 1.5), Vector.X);
            assertThat(cylinder.findIntersections(across)).containsExactly(new Point(-1, 0, 1.5), new Point(1, 0, 1.5));
            assertThat(cylinder.findIntersections(new Ray(new Point(-3, 0, 2.5), Vector.X))).as("above the height").isNull();
        }

        @Test
        @DisplayName("(height, axis, radius) has the course's types: it builds the course's (radius, axis, height) cylinder")
        void ambiguousOrderIsTheCourses() {
            Cylinder cylinder = new Cylinder(2, new Ray(Point.ZERO, Vector.Z), 1);
            assertThat(cylinder.getRadius()).isEqualTo(2);
            assertThat(cylinder.getHeight()).isEqualTo(1);
        }

        @Test
        @DisplayName("bad values are rejected like the course order's, naming them")
        void badValues() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Cylinder(0, 1, new Ray(Point.ZERO, Vector.Z)))
                    .withMessageContaining("height").withMessageContaining("0.0");
            assertThatIllegalArgumentException().isThrownBy(() -> new Cylinder(2, -1, new Ray(Point.ZERO, Vector.Z)))
                    .withMessageContaining("radius").withMessageContaining("-1.0");
        }
    }
}
