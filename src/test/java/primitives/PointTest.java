package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.assertThatNullPointerException;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class PointTest {
    private final Point p1 = new Point(1, 2, 3);
    private final Point p2 = new Point(2, 4, 6);
    private final Point p3 = new Point(2, 4, 5);

    @Nested
    @DisplayName("construction")
    class Construction {
        @ParameterizedTest(name = "{0}")
        @ValueSource(doubles = { Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY })
        @DisplayName("a NaN or infinite coordinate is refused, naming the point")
        void nonFinite(double bad) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Point(bad, 0, 0))
                    .withMessage("point coordinates must be finite, got (" + bad + ",0.0,0.0)");
            assertThatIllegalArgumentException().isThrownBy(() -> new Point(0, 0, bad));
            assertThatIllegalArgumentException().isThrownBy(() -> new Point(new Double3(0, bad, 0)));
        }

        @Test
        @DisplayName("a null triple is refused, naming it")
        void nullTriple() {
            assertThatNullPointerException().isThrownBy(() -> new Point((Double3) null))
                    .withMessage("point coordinates xyz");
        }
    }

    @Nested
    @DisplayName("subtract")
    class Subtract {
        @Test
        void givesTheVectorFromTheArgumentToThisPoint() {
            assertThat(p2.subtract(p1)).isEqualTo(new Vector(1, 2, 3));
            assertThat(p1.subtract(p2)).isEqualTo(new Vector(-1, -2, -3));
        }

        @Test
        @DisplayName("a point minus itself would be the zero vector: rejected")
        void samePointIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> p1.subtract(new Point(1, 2, 3)))
                    .withMessageContaining("zero vector");
        }

        @Test
        @DisplayName("points equal within the tolerance are rejected too")
        void pointsWithinToleranceAreRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> p1.subtract(new Point(1 + 0x1p-42, 2, 3)));
        }
    }

    @Nested
    @DisplayName("add")
    class Add {
        @Test
        void movesThePointByTheVector() {
            assertThat(p1.add(new Vector(-1, -2, -3))).isEqualTo(Point.ZERO);
            assertThat(p1.add(new Vector(1, 2, 3))).isEqualTo(p2);
        }

        @Test
        void addAndSubtractAreInverse() {
            assertThat(p1.add(p2.subtract(p1))).isEqualTo(p2);
        }
    }

    @Nested
    @DisplayName("distance")
    class Distance {
        @Test
        void distanceSquared() {
            assertThat(p1.distanceSquared(p3)).isEqualTo(9);
            assertThat(p3.distanceSquared(p1)).isEqualTo(9);
        }

        @Test
        void distance() {
            assertThat(p1.distance(p3)).isEqualTo(3);
            assertThat(new Point(0, 0, 0).distance(new Point(1, 1, 1))).isCloseTo(Math.sqrt(3), within(1e-15));
        }

        @Test
        @DisplayName("a point is at distance 0 from itself (boundary: no zero-vector failure)")
        void toItself() {
            assertThat(p1.distance(p1)).isZero();
            assertThat(p1.distanceSquared(p1)).isZero();
        }
    }

    @Test
    void equalsIsTolerant() {
        assertThat(new Point(1 + 0x1p-42, 2, 3)).isEqualTo(p1);
        assertThat(new Point(1 + 0x1p-39, 2, 3)).isNotEqualTo(p1);
    }

    @Test
    void double3ConstructorKeepsTheCoordinates() {
        Point p = new Point(new Double3(1, 2, 3));
        assertThat(new double[] { p.getX(), p.getY(), p.getZ() }).containsExactly(1, 2, 3);
        assertThat(new double[] { p.x(), p.y(), p.z() }).as("the record-style spellings").containsExactly(1, 2, 3);
    }
}
