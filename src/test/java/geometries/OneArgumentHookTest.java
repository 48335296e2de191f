package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatIllegalStateException;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Intersectable.GeoPoint;
import geometries.Intersectable.Intersection;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The hooks without {@code maxDistance}, {@code findGeoIntersectionsHelper(Ray)},
 * {@code calculateIntersectionsHelper(Ray)} and {@code calcIntersectionsHelper(Ray)}: the form
 * the courses had before the bound, which a student's shape may override alone. Such a shape
 * answers every year's query, bounded or not, and the renderer draws it through that hook. In
 * package {@code geometries}, as the course's tests that call the protected hooks are.
 */
class OneArgumentHookTest {
    /** Straight down the z axis from z = 50: through the ball at z = 10 (t = 40) and z = −10 (t = 60). */
    private static final Ray THROUGH = new Ray(new Point(0, 0, 50), new Vector(0, 0, -1));
    private static final Point NEAR = new Point(0, 0, 10), FAR = new Point(0, 0, -10);
    private static final Sphere SURFACE = new Sphere(UserGeometryScenes.CENTER, UserGeometryScenes.RADIUS);

    /** The ball's hits with no bound, as the library's sphere finds them, made this shape's. */
    private static List<Point> surfaceHits(Ray ray) {
        return SURFACE.findIntersections(ray);
    }

    /** A 2023–24 student's ball written before maxDistance: only findGeoIntersectionsHelper(Ray). */
    static final class FindGeoBall extends Geometry {
        @Override
        public Vector getNormal(Point point) {
            return SURFACE.getNormal(point);
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray) {
            List<Point> points = surfaceHits(ray);
            return points == null ? null : points.stream().map(p -> new GeoPoint(this, p)).toList();
        }
    }

    /** A 2024–25 student's ball: only calculateIntersectionsHelper(Ray). */
    static final class CalculateBall extends Geometry {
        @Override
        public Vector getNormal(Point point) {
            return SURFACE.getNormal(point);
        }

        @Override
        protected List<Intersection> calculateIntersectionsHelper(Ray ray) {
            List<Point> points = surfaceHits(ray);
            return points == null ? null : points.stream().map(p -> new Intersection(this, p)).toList();
        }
    }

    /** A 2025–26 student's ball: only calcIntersectionsHelper(Ray), answering an empty list for a miss. */
    static final class CalcBall extends Geometry {
        @Override
        public Vector getNormal(Point point) {
            return SURFACE.getNormal(point);
        }

        @Override
        protected List<Intersection> calcIntersectionsHelper(Ray ray) {
            List<Point> points = surfaceHits(ray);
            List<Intersection> mine = new ArrayList<>();
            if (points != null) for (Point p : points) mine.add(new Intersection(this, p));
            return mine;
        }
    }

    static Stream<Arguments> balls() {
        return Stream.of(Arguments.of("findGeoIntersectionsHelper(Ray)", (Supplier<Geometry>) FindGeoBall::new),
                Arguments.of("calculateIntersectionsHelper(Ray)", (Supplier<Geometry>) CalculateBall::new),
                Arguments.of("calcIntersectionsHelper(Ray)", (Supplier<Geometry>) CalcBall::new));
    }

    @Nested
    @DisplayName("a user's shape overriding only a one-argument hook")
    class UserShape {
        @ParameterizedTest(name = "{0}: every year's unbounded query finds both hits")
        @MethodSource("geometries.OneArgumentHookTest#balls")
        void unboundedQueries(String hook, Supplier<Geometry> make) {
            Geometry ball = make.get();
            assertThat(ball.findIntersections(THROUGH)).containsExactlyInAnyOrder(NEAR, FAR);
            assertThat(ball.findGeoIntersections(THROUGH)).containsExactlyInAnyOrder(new GeoPoint(ball, NEAR),
                    new GeoPoint(ball, FAR));
            assertThat(ball.calculateIntersections(THROUGH)).containsExactlyInAnyOrder(new Intersection(ball, NEAR),
                    new Intersection(ball, FAR));
            assertThat(ball.calcIntersections(THROUGH)).containsExactlyInAnyOrder(new Intersection(ball, NEAR),
                    new Intersection(ball, FAR));
            assertThat(ball.findGeoIntersectionsHelper(THROUGH)).hasSize(2);
            assertThat(ball.calculateIntersectionsHelper(THROUGH)).hasSize(2);
            assertThat(ball.calcIntersectionsHelper(THROUGH)).hasSize(2);
        }

        @ParameterizedTest(name = "{0}: the bounded queries keep the hits within maxDistance, the bound included")
        @MethodSource("geometries.OneArgumentHookTest#balls")
        void boundedQueries(String hook, Supplier<Geometry> make) {
            Geometry ball = make.get();
            assertThat(ball.findGeoIntersections(THROUGH, 45)).containsExactly(new GeoPoint(ball, NEAR));
            assertThat(ball.calculateIntersections(THROUGH, 40)).as("a hit at exactly maxDistance counts")
                    .containsExactly(new Intersection(ball, NEAR));
            assertThat(ball.calcIntersections(THROUGH, 60)).hasSize(2);
            assertThat(ball.findIntersections(THROUGH, 39.5)).as("none in range: null").isNull();
            assertThat(ball.findGeoIntersectionsHelper(THROUGH, 39.5)).isNull();
            assertThat(ball.calcIntersectionsHelper(THROUGH, 45)).containsExactly(new Intersection(ball, NEAR));
            assertThat(new Geometries(ball).calculateIntersections(THROUGH, 45)).containsExactly(new Intersection(ball, NEAR));
        }

        @ParameterizedTest(name = "{0}: a miss is null from every query, whatever the hook returned")
        @MethodSource("geometries.OneArgumentHookTest#balls")
        void miss(String hook, Supplier<Geometry> make) {
            Geometry ball = make.get();
            Ray away = new Ray(new Point(0, 0, 50), new Vector(0, 0, 1));
            assertThat(ball.findIntersections(away)).isNull();
            assertThat(ball.findGeoIntersections(away)).isNull();
            assertThat(ball.calculateIntersections(away, 100)).isNull();
            assertThat(ball.calcIntersections(away)).isNull();
        }

        @ParameterizedTest(name = "{0}: the tracer renders it like the library's sphere, beside the BVH, with its shadow")
        @MethodSource("geometries.OneArgumentHookTest#balls")
        void rendered(String hook, Supplier<Geometry> make) {
            UserGeometryScenes.assertRendersLikeTheLibrarySphere(make.get());
        }
    }

    @Nested
    @DisplayName("which hook answers")
    class Precedence {
        /** Overrides both forms of the 2023–24 hook with different answers: the bounded one must win. */
        static final class Both extends Geometry {
            @Override
            public Vector getNormal(Point point) {
                return Vector.AXIS_Z;
            }

            @Override
            protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                return List.of(new GeoPoint(this, ray.getPoint(1)));
            }

            @Override
            protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray) {
                return List.of(new GeoPoint(this, ray.getPoint(2)));
            }
        }

        @Test
        @DisplayName("a class overriding a hook with maxDistance is asked through it; its one-argument hook only when called")
        void boundedWins() {
            Both both = new Both();
            assertThat(both.calcIntersections(THROUGH)).containsExactly(new Intersection(both, THROUGH.getPoint(1)));
            assertThat(both.findGeoIntersectionsHelper(THROUGH)).containsExactly(new GeoPoint(both, THROUGH.getPoint(2)));
        }

        @Test
        @DisplayName("the library's shapes answer the one-argument hooks with their bounded hook, unbounded")
        void libraryShapes() {
            Sphere sphere = new Sphere(Point.ZERO, 10);
            assertThat(sphere.findGeoIntersectionsHelper(THROUGH))
                    .containsExactlyInAnyOrderElementsOf(sphere.findGeoIntersectionsHelper(THROUGH, Double.POSITIVE_INFINITY));
            assertThat(sphere.calculateIntersectionsHelper(THROUGH)).containsExactlyInAnyOrder(
                    new Intersection(sphere, NEAR), new Intersection(sphere, FAR));
            assertThat(sphere.calcIntersectionsHelper(new Ray(new Point(0, 0, 50), new Vector(0, 0, 1)))).isNull();
        }

        /** A user's sphere that overrides the unbounded hook, below the sphere's bounded one. */
        static final class Shadowed extends Sphere {
            Shadowed() {
                super(Point.ZERO, 1);
            }

            @Override
            protected List<Intersection> calcIntersectionsHelper(Ray ray) {
                return null;
            }
        }

        @Test
        @DisplayName("a one-argument hook below a bounded one (a subclass of a library shape) fails at construction, naming both")
        void unaskedHookIsRefused() {
            assertThatIllegalStateException().isThrownBy(Shadowed::new)
                    .withMessageContaining("calcIntersectionsHelper(Ray)").withMessageContaining(Shadowed.class.getName())
                    .withMessageContaining(Sphere.class.getName()).withMessageContaining("override the form with maxDistance");
            assertThatCode(FindGeoBall::new).doesNotThrowAnyException();
        }

        @Test
        @DisplayName("a shape overriding no hook of either form still fails at construction, naming both forms")
        void noHook() {
            class Nothing extends Geometry {
                @Override
                public Vector getNormal(Point point) {
                    return Vector.AXIS_Z;
                }
            }
            assertThatIllegalStateException().isThrownBy(Nothing::new).withMessageContaining("Nothing")
                    .withMessageContaining("(Ray, double)").withMessageContaining("(Ray)");
        }
    }
}
