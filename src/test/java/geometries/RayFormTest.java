package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The {@link Ray} forms of the lean queries, {@code closestHit(Ray, Hit)} and
 * {@code visitHits(Ray, double, HitVisitor)}, written once in {@link Intersectable}: an object of
 * the library's intersectable classes, or of a user's subclass of one, answers them through its
 * doubles forms; a user's own shape answers them through its course hook, even when it overrides
 * a doubles form too.
 */
class RayFormTest {
    private static final Ray DOWN = new Ray(new Point(0.1, 0.2, 10), new Vector(0, 0, -1));

    /** A user's sphere that is never hit: it overrides both doubles forms. */
    private static final class Ghost extends Sphere {
        Ghost() {
            super(Point.ZERO, 1);
        }

        @Override
        public boolean closestHit(Hit hit) {
            return false;
        }

        @Override
        public boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
            return true;
        }
    }

    /** A user's own shape whose course hook finds a hit at 5 along the ray, and whose doubles forms at 7. */
    private static final class TwoAnswers extends Geometry {
        @Override
        public Vector getNormal(Point point) {
            return new Vector(0, 0, 1);
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            return List.of(new GeoPoint(this, ray.getPoint(5)));
        }

        @Override
        public boolean closestHit(Hit hit) {
            hit.set(7, this, 0);
            return true;
        }

        @Override
        public boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
            return visitor.visit(this, 7);
        }
    }

    static Stream<Arguments> library() {
        Ray axis = new Ray(new Point(0.5, -1, 0), new Vector(0.2, 1, -0.3));
        Geometry sphere = new Sphere(new Point(1, -2, 0.5), 3);
        Geometry triangle = new Triangle(new Point(-5, -5, 0), new Point(5, -4, 1), new Point(0, 6, -1));
        return Stream.of(
                Arguments.of("sphere", sphere),
                Arguments.of("a user's sphere overriding nothing", new Sphere(new Point(1, -2, 0.5), 3) {
                }),
                Arguments.of("triangle", triangle),
                Arguments.of("polygon", new Polygon(new Point(-4, -4, 0), new Point(4, -4, 0), new Point(4, 4, 1),
                        new Point(-4, 4, 1))),
                Arguments.of("plane", new Plane(new Point(0, 0, -1), new Vector(0.1, 0.2, 1))),
                Arguments.of("tube", new Tube(2, axis)),
                Arguments.of("cylinder", new Cylinder(2, axis, 3)),
                Arguments.of("mesh", new TriangleMesh(new double[] { -5, -5, 0, 5, -5, 0.5, 0, 6, -1, 0, 0, 4 },
                        new int[] { 0, 1, 2, 0, 1, 3, 1, 2, 3, 2, 0, 3 })),
                Arguments.of("geometries", new Geometries(sphere, triangle)),
                Arguments.of("bvh", Bvh.build(new Geometries(sphere, triangle))));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("library")
    @DisplayName("a library intersectable: the Ray forms answer as the doubles forms, bit for bit")
    void libraryAnswersThroughTheDoublesForms(String name, Intersectable shape) {
        Random rnd = new Random(29);
        int hits = 0;
        for (int i = 0; i < 500; ++i) {
            Point from = RandomScenes.point(rnd, Point.ZERO, 15), to = RandomScenes.point(rnd, Point.ZERO, 3);
            Ray ray = new Ray(from, to.subtract(from));
            Hit viaRay = new Hit(), viaDoubles = new Hit().setRay(ray);
            boolean found = shape.closestHit(ray, viaRay);
            assertThat(shape.closestHit(viaDoubles)).as("%s", ray).isEqualTo(found);
            assertThat(viaRay.getT()).as("%s", ray).isEqualTo(viaDoubles.getT());
            assertThat(viaRay.getGeometry()).as("%s", ray).isSameAs(viaDoubles.getGeometry());
            List<Double> visitedViaRay = new ArrayList<>(), visitedViaDoubles = new ArrayList<>();
            shape.visitHits(ray, 30, (g, t) -> visitedViaRay.add(t));
            shape.visitHits(Hit.of(ray), 30, (g, t) -> visitedViaDoubles.add(t));
            assertThat(visitedViaRay).as("%s", ray).isEqualTo(visitedViaDoubles);
            if (found) ++hits;
        }
        assertThat(hits).as("rays that hit the %s", name).isGreaterThan(50);
    }

    @Test
    @DisplayName("a user's subclass of a library shape that overrides the doubles forms is answered through them")
    void subclassOverridingTheDoublesForms() {
        Geometry ghost = new Ghost();
        assertThat(new Sphere(Point.ZERO, 1).closestHit(DOWN, new Hit())).as("the library's sphere is hit").isTrue();
        assertThat(ghost.closestHit(DOWN, new Hit())).isFalse();
        assertThat(ghost.visitHits(DOWN, 100, (g, t) -> {
            throw new AssertionError("visited at " + t);
        })).isTrue();
    }

    @Test
    @DisplayName("a user's own shape is answered through its course hook, whatever its doubles forms say")
    void ownShapeThroughItsCourseHook() {
        Geometry shape = new TwoAnswers();
        Hit hit = new Hit();
        assertThat(shape.closestHit(DOWN, hit)).isTrue();
        assertThat(hit.getT()).isEqualTo(5);
        List<Double> visited = new ArrayList<>();
        shape.visitHits(DOWN, 100, (g, t) -> visited.add(t));
        assertThat(visited).containsExactly(5.0);
    }
}
