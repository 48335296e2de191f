package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class VectorTest {
    private static final double EPS = 1e-12;
    private final Vector v1 = new Vector(1, 2, 3);
    private final Vector v2 = new Vector(-2, -4, -6); // parallel to v1, opposite
    private final Vector v3 = new Vector(0, 3, -2); // orthogonal to v1

    @Nested
    @DisplayName("construction")
    class Construction {
        @Test
        void zeroVectorIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Vector(0, 0, 0))
                    .withMessageContaining("zero vector");
            assertThatIllegalArgumentException().isThrownBy(() -> new Vector(Double3.ZERO));
        }

        @Test
        @DisplayName("components all below the tolerance count as the zero vector (boundary 2^-40)")
        void nearZeroVectorIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Vector(0x1p-41, -0x1p-41, 0x1p-41));
            assertThat(new Vector(0x1p-40, 0, 0).getX()).isEqualTo(0x1p-40);
        }

        @ParameterizedTest(name = "({0},{1},{2}) is rejected")
        @CsvSource({ "NaN, 0, 0", "0, Infinity, 0", "1, 1, -Infinity" })
        void nonFiniteComponentsAreRejected(double x, double y, double z) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Vector(x, y, z)).withMessageContaining("finite");
        }

        @Test
        void axesAreUnitVectors() {
            assertThat(Vector.AXIS_X.length()).isEqualTo(1);
            assertThat(Vector.AXIS_Y.dotProduct(Vector.AXIS_Z)).isZero();
            assertThat(Vector.AXIS_X.crossProduct(Vector.AXIS_Y)).isEqualTo(Vector.AXIS_Z);
        }
    }

    @Nested
    @DisplayName("add and subtract")
    class AddSubtract {
        @Test
        void add() {
            assertThat(v1.add(v3)).isEqualTo(new Vector(1, 5, 1));
            assertThat(v1.add(v2)).isEqualTo(new Vector(-1, -2, -3));
        }

        @Test
        void addingTheOppositeGivesTheZeroVector() {
            assertThatIllegalArgumentException().isThrownBy(() -> v1.add(new Vector(-1, -2, -3)));
        }

        @Test
        void subtract() {
            assertThat(v1.subtract(v3)).isEqualTo(new Vector(1, -1, 5));
            assertThat(v1.subtract(v2)).isEqualTo(new Vector(3, 6, 9));
        }

        @Test
        void subtractingItselfGivesTheZeroVector() {
            assertThatIllegalArgumentException().isThrownBy(() -> v1.subtract(v1));
        }
    }

    @Nested
    @DisplayName("scale")
    class Scale {
        @ParameterizedTest(name = "by {0}")
        @CsvSource({ "2", "-1", "0.5" })
        void scalesEveryComponent(double k) {
            assertThat(v1.scale(k)).isEqualTo(new Vector(k, 2 * k, 3 * k));
        }

        @Test
        @DisplayName("by 0 would give the zero vector: rejected")
        void byZeroIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> v1.scale(0));
        }
    }

    @Nested
    @DisplayName("dot product")
    class Dot {
        @Test
        void orthogonalVectorsGiveZero() {
            assertThat(v1.dotProduct(v3)).isZero();
        }

        @Test
        void acuteAndObtuseAnglesGiveTheSign() {
            assertThat(v1.dotProduct(new Vector(1, 1, 1))).isEqualTo(6);
            assertThat(v1.dotProduct(v2)).isEqualTo(-28);
        }

        @Test
        void withItselfIsTheLengthSquared() {
            assertThat(v1.dotProduct(v1)).isEqualTo(v1.lengthSquared()).isEqualTo(14);
        }
    }

    @Nested
    @DisplayName("cross product")
    class Cross {
        @Test
        @DisplayName("the result is orthogonal to both operands and |a||b|sinθ long")
        void orthogonalAndOfTheRightLength() {
            Vector r = v1.crossProduct(v3);
            assertThat(r.length()).isCloseTo(v1.length() * v3.length(), within(EPS)); // θ = 90°
            assertThat(r.dotProduct(v1)).isCloseTo(0, within(EPS));
            assertThat(r.dotProduct(v3)).isCloseTo(0, within(EPS));

            Vector w = new Vector(1, 0, 0), u = new Vector(1, 1, 0); // θ = 45°
            assertThat(w.crossProduct(u).length()).isCloseTo(Math.sqrt(2) * Math.sin(Math.PI / 4), within(EPS));
        }

        @Test
        void isAntiCommutativeAndRightHanded() {
            assertThat(v1.crossProduct(v3)).isEqualTo(v3.crossProduct(v1).scale(-1));
            assertThat(Vector.AXIS_Y.crossProduct(Vector.AXIS_Z)).isEqualTo(Vector.AXIS_X);
            assertThat(Vector.AXIS_Z.crossProduct(Vector.AXIS_X)).isEqualTo(Vector.AXIS_Y);
        }

        @Test
        @DisplayName("parallel operands (same or opposite direction) are rejected")
        void parallelIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> v1.crossProduct(v2)).withMessageContaining("parallel");
            assertThatIllegalArgumentException().isThrownBy(() -> v1.crossProduct(v1.scale(3)));
            assertThatIllegalArgumentException().isThrownBy(() -> v1.crossProduct(v1));
        }
    }

    @Nested
    @DisplayName("length and normalize")
    class Length {
        @Test
        void length() {
            assertThat(new Vector(0, 3, 4).length()).isEqualTo(5);
            assertThat(new Vector(0, 3, 4).lengthSquared()).isEqualTo(25);
        }

        @Test
        void normalizeGivesAUnitVectorInTheSameDirection() {
            Vector u = v1.normalize();
            assertThat(u.length()).isCloseTo(1, within(EPS));
            assertThat(u.dotProduct(v1)).isCloseTo(v1.length(), within(EPS)); // same direction, not opposite
            assertThatIllegalArgumentException().isThrownBy(() -> u.crossProduct(v1)); // parallel
        }

        @Test
        void normalizeKeepsAUnitVector() {
            assertThat(Vector.AXIS_Z.normalize()).isEqualTo(Vector.AXIS_Z);
            assertThat(new Vector(0, 0, 1e-6).normalize()).isEqualTo(Vector.AXIS_Z);
        }
    }

    @Nested
    @DisplayName("a Vector is a Point (the course design)")
    class AsAPoint {
        @Test
        void aVectorIsUsableAsAPoint() {
            Point p = new Vector(1, 2, 3);
            Point moved = p.add(new Vector(1, 1, 1));
            assertThat(new double[] { moved.getX(), moved.getY(), moved.getZ() }).containsExactly(2, 3, 4);
        }

        @Test
        @DisplayName("equality between a point and a vector of the same coordinates is symmetric")
        void equalsIsSymmetric() {
            Point p = new Point(1, 2, 3);
            Vector v = new Vector(1, 2, 3);
            assertThat(p.equals(v)).isEqualTo(v.equals(p));
            assertThat(p.hashCode()).isEqualTo(v.hashCode());
        }
    }
}
