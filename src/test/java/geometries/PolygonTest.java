package geometries;

import static geometries.Hits.assertHits;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

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
 * A convex pentagon in a tilted plane. Its vertices are given in the plane's own coordinates
 * (a along U, b along W), so that "inside", "on an edge" and "beyond a vertex" can be worked
 * out by hand in 2D: (0,0), (4,0), (5,3), (2,5), (-1,3), counter-clockwise.
 */
class PolygonTest implements GeometryContract {
    private static final Point O = new Point(1, -2, 3);
    private static final Vector U = new Vector(0.6, 0, 0.8);
    private static final Vector W = new Vector(0, 1, 0);
    /** U × W: the plane's normal for the counter-clockwise order. */
    private static final Vector N = new Vector(-0.8, 0, 0.6);

    /** The point with plane coordinates (a, b). */
    static Point at(double a, double b) {
        Point p = O;
        if (a != 0) p = p.add(U.scale(a));
        if (b != 0) p = p.add(W.scale(b));
        return p;
    }

    private final Polygon pentagon = new Polygon(at(0, 0), at(4, 0), at(5, 3), at(2, 5), at(-1, 3));

    @Override
    public Intersectable subject() {
        return pentagon;
    }

    @Override
    public Ray knownHit() {
        return rayTo(at(2, 2), new Vector(0.3, -0.2, 1));
    }

    @Override
    public Ray knownMiss() {
        return rayTo(at(6, 1), new Vector(0.3, -0.2, 1));
    }

    @Override
    public Point focus() {
        return at(2, 2.5);
    }

    @Override
    public double extent() {
        return 3.5;
    }

    /** A ray that reaches {@code target} after travelling 2·|dir|, coming from the back of the plane. */
    static Ray rayTo(Point target, Vector dir) {
        return new Ray(target.add(dir.scale(-2)), dir);
    }

    static Stream<Arguments> targets() {
        return Stream.of(
                Arguments.of("inside", 2, 2, true),
                Arguments.of("inside, near a vertex", 3.9, 0.1, true),
                Arguments.of("outside against an edge (bottom)", 2, -1, false),
                Arguments.of("outside against an edge (right)", 6, 1, false),
                Arguments.of("outside against a vertex (4,0)", 5, -1, false),
                Arguments.of("outside against a vertex (2,5)", 2, 6, false),
                Arguments.of("exactly on an edge (bottom midpoint)", 2, 0, false),
                Arguments.of("exactly on an edge (upper right midpoint)", 3.5, 4, false),
                Arguments.of("on a vertex (4,0)", 4, 0, false),
                Arguments.of("on a vertex (-1,3)", -1, 3, false),
                Arguments.of("on an edge's continuation beyond (4,0)", 6, 0, false),
                Arguments.of("on an edge's continuation before (0,0)", -2, 0, false),
                Arguments.of("on an edge's continuation beyond (5,3)", 6, 6, false));
    }

    @Nested
    @DisplayName("a ray through the polygon's plane")
    class ThroughThePlane {
        @ParameterizedTest(name = "{0}: hit = {3}")
        @MethodSource("geometries.PolygonTest#targets")
        void obliqueRay(String name, double a, double b, boolean hit) {
            Point target = at(a, b);
            Ray ray = rayTo(target, new Vector(0.3, -0.2, 1));
            if (hit) assertHits(pentagon, ray, target);
            else assertHits(pentagon, ray);
        }

        @ParameterizedTest(name = "{0}: hit = {3}")
        @MethodSource("geometries.PolygonTest#targets")
        void orthogonalRayFromTheFront(String name, double a, double b, boolean hit) {
            Point target = at(a, b);
            Ray ray = new Ray(target.add(N.scale(3)), N.scale(-1));
            if (hit) assertHits(pentagon, ray, target);
            else assertHits(pentagon, ray);
        }
    }

    @Nested
    @DisplayName("rays that do not cross the plane: never a hit")
    class NotCrossing {
        @Test
        void rayInThePlaneThroughTheInside() {
            assertHits(pentagon, new Ray(at(-3, 2), U));
        }

        @Test
        void rayParallelToThePlane() {
            assertHits(pentagon, new Ray(at(-3, 2).add(N), U));
        }

        @Test
        void rayStartingOnThePolygon() {
            assertHits(pentagon, new Ray(at(2, 2), N));
        }

        @Test
        void rayPointingAway() {
            assertHits(pentagon, new Ray(at(2, 2).add(N), N));
        }
    }

    @Nested
    @DisplayName("normal")
    class Normal {
        @Test
        void isUnitAndOrthogonalToTheEdges() {
            Vector n = pentagon.getNormal(at(2, 2));
            assertThat(n.length()).isCloseTo(1, within(1e-12));
            assertThat(n.dotProduct(at(4, 0).subtract(at(0, 0)))).isCloseTo(0, within(1e-12));
            assertThat(n.dotProduct(at(2, 5).subtract(at(5, 3)))).isCloseTo(0, within(1e-12));
            assertThat(Math.abs(n.dotProduct(N))).isCloseTo(1, within(1e-12));
        }

        @Test
        void boundingBoxEnclosesTheVerticesTightly() {
            BoundingBox b = new Polygon(new Point(0, 0, 1), new Point(2, 0, 1), new Point(3, 2, 1), new Point(-1, 3, 1))
                    .getBoundingBox();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(-1, 0, 1, 3, 3, 1);
        }
    }

    static Stream<Arguments> invalid() {
        Point a = new Point(0, 0, 0), b = new Point(4, 0, 0), c = new Point(4, 4, 0), d = new Point(0, 4, 0);
        Point[] star = new Point[5];
        for (int k = 0; k < 5; ++k) {
            double angle = 2 * Math.PI * (2 * k % 5) / 5; // every second vertex of a regular pentagon
            star[k] = new Point(Math.cos(angle), Math.sin(angle), 0);
        }
        return Stream.of(
                Arguments.of("no vertex", new Point[0], "at least 3"),
                Arguments.of("one vertex", new Point[] { a }, "at least 3"),
                Arguments.of("two vertices", new Point[] { a, b }, "at least 3"),
                Arguments.of("three collinear vertices", new Point[] { a, b, new Point(8, 0, 0) }, "collinear"),
                Arguments.of("three collinear vertices among four", new Point[] { a, new Point(2, 0, 0), b, c }, "collinear"),
                Arguments.of("collinear vertices later in the list", new Point[] { a, b, new Point(4, 2, 0), c, d }, "collinear"),
                Arguments.of("a vertex repeated consecutively", new Point[] { a, b, b, c }, "repeat"),
                Arguments.of("the last vertex repeating the first", new Point[] { a, b, c, a }, "repeat"),
                Arguments.of("a vertex repeated non-consecutively", new Point[] { a, b, c, d, b }, "convex"),
                Arguments.of("a vertex off the plane", new Point[] { a, b, c, new Point(0, 4, 0.5) }, "not in the plane"),
                Arguments.of("a concave (arrow) outline", new Point[] { a, b, c, new Point(2, 1, 0), d }, "convex"),
                Arguments.of("wrong order (bow-tie)", new Point[] { a, b, d, c }, "convex"),
                Arguments.of("self-crossing star (turns all one way)", star, "self-crossing"));
    }

    @Nested
    @DisplayName("construction")
    class Construction {
        @ParameterizedTest(name = "{0} is rejected")
        @MethodSource("geometries.PolygonTest#invalid")
        void invalidVertexListsAreRejected(String name, Point[] vertices, String complaint) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Polygon(vertices)).withMessageContaining(complaint);
        }

        @Test
        void nullIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Polygon((Point[]) null)).withMessageContaining("at least 3");
        }

        @Test
        @DisplayName("both windings are accepted")
        void bothWindings() {
            Point a = new Point(0, 0, 0), b = new Point(4, 0, 0), c = new Point(4, 4, 0), d = new Point(0, 4, 0);
            Polygon ccw = new Polygon(a, b, c, d), cw = new Polygon(d, c, b, a);
            Ray down = new Ray(new Point(1, 1, 1), new Vector(0, 0, -1));
            assertHits(ccw, down, new Point(1, 1, 0));
            assertHits(cw, down, new Point(1, 1, 0));
        }
    }
}
