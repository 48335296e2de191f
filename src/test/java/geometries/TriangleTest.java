package geometries;

import static geometries.Hits.assertHits;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.Random;
import java.util.function.Function;
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
 * The triangle (0,0,0), (4,0,0), (0,4,0) in the plane z = 0: its edges are x = 0, y = 0 and
 * x + y = 4, so every equivalence class is checked by hand. Each case runs on the Möller–Trumbore
 * {@link Triangle} and on a {@link Polygon} of the same vertices: the two kernels must agree,
 * boundary rules included.
 */
class TriangleTest implements GeometryContract {
    private static final Point A = new Point(0, 0, 0), B = new Point(4, 0, 0), C = new Point(0, 4, 0);
    private final Triangle triangle = new Triangle(A, B, C);

    @Override
    public Intersectable subject() {
        return triangle;
    }

    @Override
    public Ray knownHit() {
        return new Ray(new Point(1, 1, -1), new Vector(0, 0, 1));
    }

    @Override
    public Ray knownMiss() {
        return new Ray(new Point(3, 3, -1), new Vector(0, 0, 1));
    }

    @Override
    public Point focus() {
        return new Point(1.5, 1.5, 0);
    }

    @Override
    public double extent() {
        return 3;
    }

    /** Both kernels, by name, built over the same three vertices. */
    static Stream<Arguments> kernels() {
        return Stream.of(Arguments.of("Triangle", (Function<Point[], Polygon>) v -> new Triangle(v[0], v[1], v[2])),
                Arguments.of("Polygon", (Function<Point[], Polygon>) Polygon::new));
    }

    static Stream<Arguments> targets() {
        List<Object[]> cases = List.of(
                new Object[] { "inside", 1, 1, true },
                new Object[] { "inside, close to the hypotenuse", 1.99, 1.99, true },
                new Object[] { "outside against the hypotenuse", 3, 3, false },
                new Object[] { "outside against the edge x = 0", -1, 1, false },
                new Object[] { "outside against the edge y = 0", 1, -1, false },
                new Object[] { "outside against the vertex (4,0)", 5, -1, false },
                new Object[] { "outside against the vertex (0,4)", -1, 5, false },
                new Object[] { "outside against the vertex (0,0)", -1, -1, false },
                new Object[] { "exactly on the hypotenuse", 2, 2, false },
                new Object[] { "exactly on the edge y = 0", 1, 0, false },
                new Object[] { "exactly on the edge x = 0", 0, 3, false },
                new Object[] { "on the vertex (0,0)", 0, 0, false },
                new Object[] { "on the vertex (4,0)", 4, 0, false },
                new Object[] { "on the vertex (0,4)", 0, 4, false },
                new Object[] { "on the continuation of y = 0 beyond (4,0)", 5, 0, false },
                new Object[] { "on the continuation of y = 0 before (0,0)", -1, 0, false },
                new Object[] { "on the continuation of the hypotenuse", 6, -2, false },
                new Object[] { "on the continuation of x = 0", 0, 5, false });
        return kernels().flatMap(k -> cases.stream().map(c -> Arguments.of(k.get()[0], k.get()[1], c[0], c[1], c[2], c[3])));
    }

    @Nested
    @DisplayName("a ray through the triangle's plane")
    class ThroughThePlane {
        @ParameterizedTest(name = "{0}, {2}: hit = {5}")
        @MethodSource("geometries.TriangleTest#targets")
        void obliqueRay(String kernel, Function<Point[], Polygon> make, String name, double x, double y, boolean hit) {
            Polygon shape = make.apply(new Point[] { A, B, C });
            Point target = new Point(x, y, 0);
            Vector dir = new Vector(0.3, -0.2, 1);
            Ray ray = new Ray(target.add(dir.scale(-2)), dir);
            if (hit) assertHits(shape, ray, target);
            else assertHits(shape, ray);
        }

        @ParameterizedTest(name = "{0}, {2}: hit = {5}")
        @MethodSource("geometries.TriangleTest#targets")
        void orthogonalRayFromAbove(String kernel, Function<Point[], Polygon> make, String name, double x, double y, boolean hit) {
            Polygon shape = make.apply(new Point[] { A, B, C });
            Point target = new Point(x, y, 0);
            Ray ray = new Ray(new Point(x, y, 5), new Vector(0, 0, -1));
            if (hit) assertHits(shape, ray, target);
            else assertHits(shape, ray);
        }
    }

    @Nested
    @DisplayName("rays that do not cross the plane: never a hit")
    class NotCrossing {
        @Test
        void rayInThePlane() {
            assertHits(triangle, new Ray(new Point(-1, 1, 0), new Vector(1, 0, 0)));
        }

        @Test
        void rayParallelToThePlane() {
            assertHits(triangle, new Ray(new Point(-1, 1, 1), new Vector(1, 0, 0)));
        }

        @Test
        void rayStartingOnTheTriangle() {
            assertHits(triangle, new Ray(new Point(1, 1, 0), new Vector(0.1, 0, 1)));
        }

        @Test
        void rayPointingAway() {
            assertHits(triangle, new Ray(new Point(1, 1, 1), new Vector(0, 0, 1)));
        }
    }

    @Test
    @DisplayName("the course triangle (0,0,1), (1,0,0), (0,1,0): inside, on an edge, against a vertex")
    void courseTriangle() {
        Triangle t = new Triangle(new Point(0, 0, 1), new Point(1, 0, 0), new Point(0, 1, 0));
        Vector down = new Vector(-1, -1, -1);
        assertHits(t, new Ray(new Point(1.25, 1.25, 1.5), down), new Point(0.25, 0.25, 0.5));
        assertHits(t, new Ray(new Point(1.5, 1.5, 1), down)); // through (0.5, 0.5, 0): on an edge
        assertHits(t, new Ray(new Point(2, 1, 1), down)); // through (1, 0, 0): on a vertex
        assertHits(t, new Ray(new Point(3, 1, -1), down)); // through (2, 0, -2): beyond a vertex
    }

    @Test
    @DisplayName("Möller–Trumbore agrees with the polygon's edge test for random rays (an independent method)")
    void kernelsAgreeOnRandomRays() {
        Random rnd = new Random(77);
        for (int i = 0; i < 300; ++i) {
            Point[] v = { randomPoint(rnd), randomPoint(rnd), randomPoint(rnd) };
            Triangle t;
            Polygon p;
            try {
                t = new Triangle(v[0], v[1], v[2]);
                p = new Polygon(v);
            } catch (IllegalArgumentException degenerate) {
                continue;
            }
            for (int k = 0; k < 20; ++k) {
                Ray ray = new Ray(randomPoint(rnd).add(new Vector(0, 0, 10)), randomPoint(rnd).subtract(new Point(0, 0, 10)));
                List<Hits.Visit> byTriangle = Hits.listed(t, ray, Double.POSITIVE_INFINITY);
                List<Hits.Visit> byPolygon = Hits.listed(p, ray, Double.POSITIVE_INFINITY);
                assertThat(byTriangle).as("hits of %s", ray).hasSameSizeAs(byPolygon);
                if (!byTriangle.isEmpty())
                    assertThat(byTriangle.get(0).t()).as("distance on %s", ray).isCloseTo(byPolygon.get(0).t(), within(1e-9));
            }
        }
    }

    private static Point randomPoint(Random rnd) {
        return new Point(10 * rnd.nextDouble() - 5, 10 * rnd.nextDouble() - 5, 10 * rnd.nextDouble() - 5);
    }

    @Nested
    @DisplayName("construction")
    class Construction {
        @Test
        void repeatedVerticesAreRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Triangle(A, A, C)).withMessageContaining("repeat");
            assertThatIllegalArgumentException().isThrownBy(() -> new Triangle(A, B, B)).withMessageContaining("repeat");
            assertThatIllegalArgumentException().isThrownBy(() -> new Triangle(A, B, A)).withMessageContaining("repeat");
        }

        @Test
        void collinearVerticesAreRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Triangle(A, B, new Point(9, 0, 0)))
                    .withMessageContaining("collinear");
            assertThatIllegalArgumentException().isThrownBy(() -> new Triangle(A, new Point(2, 2, 2), new Point(1, 1, 1)))
                    .withMessageContaining("collinear");
        }

        @Test
        void normalIsUnitAndOrthogonal() {
            Vector n = triangle.getNormal(new Point(1, 1, 0));
            assertThat(Math.abs(n.dotProduct(new Vector(0, 0, 1)))).isCloseTo(1, within(1e-15));
        }

        @Test
        void boundingBoxIsFlatForAnAxisAlignedTriangle() {
            BoundingBox b = triangle.getBoundingBox();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(0, 0, 0, 4, 4, 0);
        }
    }
}
