package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The query ray a {@link Hit} carries as doubles, and the shading inputs it computes, are bit for
 * bit what the {@link Ray}, {@link Point} and {@link Vector} objects give: the renderer's images
 * depend on it.
 */
class HitTest {
    private static final long SEED = 20261124L;

    private static void assertRay(Hit hit, Ray ray) {
        assertThat(new double[] { hit.headX(), hit.headY(), hit.headZ(), hit.directionX(), hit.directionY(),
                hit.directionZ() }).as("%s", ray).containsExactly(ray.getHead().getX(), ray.getHead().getY(),
                ray.getHead().getZ(), ray.getDirection().getX(), ray.getDirection().getY(), ray.getDirection().getZ());
    }

    /**
     * A random vector of random scale, from 1e-10 to 1e200: beyond about 1e135 the normalization
     * takes its branch for huge vectors.
     */
    private static Vector anyVector(Random rnd) {
        double scale = Math.pow(10, rnd.nextInt(211) - 10);
        return new Vector(rnd.nextGaussian() * scale, rnd.nextGaussian() * scale, rnd.nextGaussian() * scale);
    }

    @Nested
    @DisplayName("setRay")
    class SetRay {
        @Test
        @DisplayName("(head, direction): the doubles of new Ray(head, direction), for directions of any length")
        void headAndDirection() {
            Random rnd = new Random(SEED);
            Hit hit = new Hit();
            for (int i = 0; i < 2000; ++i) {
                Point p = RandomScenes.point(rnd, Point.ZERO, 100);
                Vector d = i % 3 == 0 ? RandomScenes.direction(rnd) : anyVector(rnd);
                hit.setRay(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ());
                assertRay(hit, new Ray(p, d));
            }
        }

        @Test
        @DisplayName("(point, direction, normal): the doubles of new Ray(point, direction, normal), either side and tangent")
        void offsetFromASurface() {
            Random rnd = new Random(SEED + 1);
            Hit hit = new Hit();
            for (int i = 0; i < 2000; ++i) {
                Point p = RandomScenes.point(rnd, Point.ZERO, 100);
                Vector n = RandomScenes.direction(rnd);
                Vector d = i % 4 == 0 ? n.crossProduct(RandomScenes.direction(rnd)) // tangent: no offset
                        : anyVector(rnd);
                hit.setRay(p.getX(), p.getY(), p.getZ(), d.getX(), d.getY(), d.getZ(), n.getX(), n.getY(), n.getZ());
                assertRay(hit, new Ray(p, d, n));
            }
        }

        @Test
        @DisplayName("a tangent direction keeps the head; leaving and entering move it by ±DELTA along the normal")
        void offsetRule() {
            Hit hit = new Hit();
            hit.setRay(1, 2, 3, 1, 0, 0, 0, 0, 1);
            assertThat(new double[] { hit.headX(), hit.headY(), hit.headZ() }).containsExactly(1, 2, 3);
            hit.setRay(1, 2, 3, 0, 1, 1, 0, 0, 1);
            assertThat(hit.headZ()).isEqualTo(3 + Ray.DELTA);
            hit.setRay(1, 2, 3, 0, 1, -1, 0, 0, 1);
            assertThat(hit.headZ()).isEqualTo(3 - Ray.DELTA);
        }
    }

    static Stream<Arguments> shapes() {
        Ray axis = new Ray(new Point(0.5, -1, 0), new Vector(0.2, 1, -0.3));
        return Stream.of(
                Arguments.of("sphere", new Sphere(new Point(1, -2, 0.5), 3)),
                Arguments.of("plane", new Plane(new Point(0, 0, -1), new Vector(0.1, 0.2, 1))),
                Arguments.of("triangle", new Triangle(new Point(-5, -5, 0), new Point(5, -4, 1), new Point(0, 6, -1))),
                Arguments.of("polygon", new Polygon(new Point(-4, -4, 0), new Point(4, -4, 0), new Point(4, 4, 1),
                        new Point(-4, 4, 1))),
                Arguments.of("tube", new Tube(2, axis)),
                Arguments.of("cylinder (shell and caps)", new Cylinder(2, axis, 3)),
                Arguments.of("flat mesh", new TriangleMesh(new double[] { -5, -5, 0, 5, -5, 0.5, 0, 6, -1, 0, 0, 4 },
                        new int[] { 0, 1, 2, 0, 1, 3, 1, 2, 3, 2, 0, 3 })),
                Arguments.of("smooth mesh", new TriangleMesh(new double[] { -5, -5, 0, 5, -5, 0.5, 0, 6, -1, 0, 0, 4 },
                        new int[] { 0, 1, 2, 0, 1, 3, 1, 2, 3, 2, 0, 3 },
                        new double[] { -1, -1, 0.2, 1, -1, 0.3, 0, 1, -0.2, 0, 0, 1 })),
                Arguments.of("a user's shape (object defaults)", new Course5784Test.Ball()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("shapes")
    @DisplayName("computeSurface: the point and normal of hit.point(ray) and hit.normal(point), bit for bit")
    void surfaceAsTheObjectsGiveIt(String name, Geometry shape) {
        Random rnd = new Random(SEED + 2);
        Hit raw = new Hit(), viaObjects = new Hit();
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            // From around the shape toward its middle, so that most rays hit it.
            Point from = RandomScenes.point(rnd, Point.ZERO, 15), to = RandomScenes.point(rnd, Point.ZERO, 3);
            Ray ray = new Ray(from, to.subtract(from));
            raw.setRay(ray.getHead().getX(), ray.getHead().getY(), ray.getHead().getZ(), ray.getDirection().getX(),
                    ray.getDirection().getY(), ray.getDirection().getZ());
            boolean found = shape.closestHit(raw.reset(Double.POSITIVE_INFINITY));
            assertThat(shape.closestHit(ray, viaObjects.reset(Double.POSITIVE_INFINITY))).isEqualTo(found);
            if (!found) continue;
            ++hits;
            assertThat(raw.getT()).isEqualTo(viaObjects.getT());
            raw.computeSurface();
            Point p = viaObjects.point(ray);
            Vector n = viaObjects.normal(p);
            assertThat(new double[] { raw.pointX(), raw.pointY(), raw.pointZ(), raw.normalX(), raw.normalY(), raw.normalZ() })
                    .as("%s at t = %s", ray, raw.getT())
                    .containsExactly(p.getX(), p.getY(), p.getZ(), n.getX(), n.getY(), n.getZ());
        }
        assertThat(hits).as("rays that hit the %s", name).isGreaterThan(300);
    }

    /** A user's subclass of a library shape that redefines the normal (pointing inward). */
    private static final class InsideOut extends Sphere {
        InsideOut() {
            super(new Point(1, -2, 0.5), 3);
        }

        @Override
        public Vector getNormal(Point point) {
            return super.getNormal(point).scale(-1);
        }
    }

    /** A user's subclass of a library mesh that changes nothing: the mesh's own (smooth) normal stays. */
    private static final class MyMesh extends TriangleMesh {
        MyMesh(double[] positions, int[] indices, double[] normals) {
            super(positions, indices, normals);
        }
    }

    @Test
    @DisplayName("a user's subclass that overrides getNormal(Point) gets its normal used; one that does not keeps the library's")
    void userSubclassNormals() {
        double[] pos = { -5, -5, 0, 5, -5, 0.5, 0, 6, -1, 0, 0, 4 };
        int[] idx = { 0, 1, 2, 0, 1, 3, 1, 2, 3, 2, 0, 3 };
        double[] nrm = { -1, -1, 0.2, 1, -1, 0.3, 0, 1, -0.2, 0, 0, 1 };
        Geometry insideOut = new InsideOut(), myMesh = new MyMesh(pos, idx, nrm), mesh = new TriangleMesh(pos, idx, nrm);
        Random rnd = new Random(SEED + 3);
        Hit hit = new Hit(), plain = new Hit();
        int sphereHits = 0, meshHits = 0;
        for (int i = 0; i < 2000; ++i) {
            Point from = RandomScenes.point(rnd, Point.ZERO, 15), to = RandomScenes.point(rnd, Point.ZERO, 3);
            Ray ray = new Ray(from, to.subtract(from));
            if (insideOut.closestHit(ray, hit.reset(Double.POSITIVE_INFINITY))) {
                ++sphereHits;
                hit.computeSurface();
                Vector n = insideOut.getNormal(new Point(hit.pointX(), hit.pointY(), hit.pointZ()));
                assertThat(new double[] { hit.normalX(), hit.normalY(), hit.normalZ() }).as("inward normal for %s", ray)
                        .containsExactly(n.getX(), n.getY(), n.getZ());
            }
            if (myMesh.closestHit(ray, hit.reset(Double.POSITIVE_INFINITY))) {
                ++meshHits;
                assertThat(mesh.closestHit(ray, plain.reset(Double.POSITIVE_INFINITY))).isTrue();
                hit.computeSurface();
                plain.computeSurface();
                assertThat(new double[] { hit.normalX(), hit.normalY(), hit.normalZ() }).as("smooth normal for %s", ray)
                        .containsExactly(plain.normalX(), plain.normalY(), plain.normalZ());
            }
        }
        assertThat(sphereHits).isGreaterThan(200);
        assertThat(meshHits).isGreaterThan(200);
    }

    @Nested
    @DisplayName("its face outside the library")
    class Face {
        @Test
        @DisplayName("code holding a record reads it: the ray setters are protected, every public method final")
        void settersProtected() {
            java.lang.reflect.Method[] methods = Hit.class.getDeclaredMethods();
            assertThat(methods).filteredOn(m -> m.getName().equals("setRay") && m.getParameterCount() > 1)
                    .hasSize(2)
                    .allSatisfy(m -> assertThat(java.lang.reflect.Modifier.isProtected(m.getModifiers())).as(m.toString()).isTrue());
            assertThat(Hit.class.getMethods()).filteredOn(m -> m.getDeclaringClass() == Hit.class)
                    .isNotEmpty()
                    .allSatisfy(m -> assertThat(java.lang.reflect.Modifier.isFinal(m.getModifiers())).as(m.toString()).isTrue())
                    .noneSatisfy(m -> assertThat(m.getName()).startsWith("set"));
        }
    }
}
