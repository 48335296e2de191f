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

/** The plane x + y + z = 1, through (1,0,0), (0,1,0) and (0,0,1). */
class PlaneTest implements GeometryContract {
    private final Plane plane = new Plane(new Point(1, 0, 0), new Point(0, 1, 0), new Point(0, 0, 1));
    private static final Vector N = new Vector(1, 1, 1);

    @Override
    public Intersectable subject() {
        return plane;
    }

    @Override
    public Ray knownHit() {
        return new Ray(new Point(-1, -1, -1), N);
    }

    @Override
    public Ray knownMiss() {
        return new Ray(new Point(1, 1, 1), N);
    }

    @Override
    public Point focus() {
        return new Point(1.0 / 3, 1.0 / 3, 1.0 / 3);
    }

    @Override
    public double extent() {
        return 2;
    }

    @Override
    public boolean bounded() {
        return false;
    }

    @Nested
    @DisplayName("construction from three points")
    class Construction {
        @Test
        @DisplayName("the normal is unit length and orthogonal to the plane's edges")
        void normalIsUnitAndOrthogonal() {
            Vector n = plane.getNormal(new Point(1, 0, 0));
            assertThat(n.length()).isCloseTo(1, within(1e-15));
            assertThat(n.dotProduct(new Vector(-1, 1, 0))).isCloseTo(0, within(1e-15));
            assertThat(n.dotProduct(new Vector(-1, 0, 1))).isCloseTo(0, within(1e-15));
            assertThat(n).isEqualTo(N.normalize());
            assertThat(plane.getNormal()).isSameAs(n);
        }

        static Stream<Arguments> degenerate() {
            Point a = new Point(1, 2, 3), b = new Point(2, 4, 5), c = new Point(-1, 0, 7);
            return Stream.of(
                    Arguments.of("first and second repeated", a, a, c, "distinct"),
                    Arguments.of("first and third repeated", a, b, a, "distinct"),
                    Arguments.of("second and third repeated", a, b, b, "distinct"),
                    Arguments.of("all three repeated", a, a, a, "distinct"),
                    Arguments.of("collinear, third beyond", new Point(0, 0, 0), new Point(1, 1, 1), new Point(3, 3, 3), "collinear"),
                    Arguments.of("collinear, third between", new Point(0, 0, 0), new Point(2, 2, 2), new Point(1, 1, 1), "collinear"),
                    Arguments.of("collinear, far from the origin", new Point(1e4, 1e4, 0), new Point(1e4 + 1, 1e4 + 2, 0),
                            new Point(1e4 + 3, 1e4 + 6, 0), "collinear"));
        }

        @ParameterizedTest(name = "{0} is rejected")
        @MethodSource("geometries.PlaneTest$Construction#degenerate")
        void degeneratePointsAreRejected(String name, Point p1, Point p2, Point p3, String complaint) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Plane(p1, p2, p3))
                    .withMessageContaining(complaint).withMessageContaining(p1.toString());
        }

        @Test
        void pointAndNormalConstructorNormalizes() {
            Plane p = new Plane(new Point(0, 0, 5), new Vector(0, 0, 3));
            assertThat(p.getNormal()).isEqualTo(new Vector(0, 0, 1));
            assertThat(p.getQ()).isEqualTo(new Point(0, 0, 5));
        }

        @Test
        void hasNoBoundingBox() {
            assertThat(plane.getBoundingBox()).isNull();
        }
    }

    @Nested
    @DisplayName("the ray crosses the plane (neither parallel nor orthogonal)")
    class Crossing {
        @Test
        @DisplayName("towards it: one point")
        void towards() {
            assertHits(plane, new Ray(new Point(0, 0, -1), new Vector(0, 0, 1)), new Point(0, 0, 1));
        }

        @Test
        @DisplayName("away from it: none")
        void away() {
            assertHits(plane, new Ray(new Point(0, 0, 2), new Vector(0, 0, 1)));
        }
    }

    @Nested
    @DisplayName("the ray is parallel to the plane: never a hit")
    class Parallel {
        @Test
        @DisplayName("outside the plane")
        void outside() {
            assertHits(plane, new Ray(Point.ZERO, new Vector(1, -1, 0)));
        }

        @Test
        @DisplayName("inside the plane")
        void inside() {
            assertHits(plane, new Ray(new Point(1, 0, 0), new Vector(1, -1, 0)));
        }
    }

    @Nested
    @DisplayName("the ray is orthogonal to the plane")
    class Orthogonal {
        @Test
        @DisplayName("starts before: one point")
        void before() {
            assertHits(plane, new Ray(new Point(-1, -1, -1), N), new Point(1.0 / 3, 1.0 / 3, 1.0 / 3));
        }

        @Test
        @DisplayName("starts on the plane: none")
        void onPlane() {
            assertHits(plane, new Ray(new Point(0, 0.5, 0.5), N));
        }

        @Test
        @DisplayName("starts after: none")
        void after() {
            assertHits(plane, new Ray(new Point(1, 1, 1), N));
        }
    }

    @Nested
    @DisplayName("the ray starts on the plane, neither parallel nor orthogonal: none")
    class StartsOnPlane {
        @Test
        void fromAnyPoint() {
            assertHits(plane, new Ray(new Point(0, 0.5, 0.5), new Vector(0, 0, 1)));
        }

        @Test
        @DisplayName("from the plane's reference point")
        void fromTheReferencePoint() {
            assertHits(plane, new Ray(plane.getQ(), new Vector(0, 0, 1)));
        }
    }
}
