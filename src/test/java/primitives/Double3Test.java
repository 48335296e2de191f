package primitives;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class Double3Test {
    private final Double3 a = new Double3(1, 2, 3);
    private final Double3 b = new Double3(0.5, -4, 10);

    /** Exact component check: the arithmetic below is exact in binary, so no tolerance is needed. */
    private static void assertComponents(Double3 actual, double d1, double d2, double d3) {
        assertThat(new double[] { actual.getD1(), actual.getD2(), actual.getD3() }).containsExactly(d1, d2, d3);
    }

    @Nested
    @DisplayName("arithmetic, component by component")
    class Arithmetic {
        @Test
        void add() {
            assertComponents(a.add(b), 1.5, -2, 13);
        }

        @Test
        void subtract() {
            assertComponents(a.subtract(b), 0.5, 6, -7);
        }

        @Test
        void scale() {
            assertComponents(a.scale(-2), -2, -4, -6);
            assertComponents(a.scale(0), 0, 0, 0);
        }

        @Test
        void reduce() {
            assertComponents(a.reduce(4), 0.25, 0.5, 0.75);
        }

        @Test
        void product() {
            assertComponents(a.product(b), 0.5, -8, 30);
        }

        @Test
        void singleValueConstructorFillsAllComponents() {
            assertComponents(new Double3(0.7), 0.7, 0.7, 0.7);
        }

        @Test
        void isZeroOnlyForExactZero() {
            assertThat(Double3.ZERO.isZero()).isTrue();
            assertThat(new Double3(0, 0, 1e-300).isZero()).isFalse();
        }

        @Test
        void operandsAreNotModified() {
            a.add(b).scale(3).product(b);
            assertComponents(a, 1, 2, 3);
            assertComponents(b, 0.5, -4, 10);
        }
    }

    @Nested
    @DisplayName("lowerThan(double): all three strictly below")
    class LowerThanScalar {
        @ParameterizedTest(name = "({0},{1},{2}) < {3} is {4}")
        @CsvSource({
                "0.1, 0.2, 0.3, 0.5, true",
                "0.6, 0.2, 0.3, 0.5, false",
                "0.1, 0.6, 0.3, 0.5, false",
                "0.1, 0.2, 0.6, 0.5, false",
                // boundary: a component equal to k is not below it
                "0.5, 0.2, 0.3, 0.5, false",
                "0.1, 0.2, 0.5, 0.5, false",
                "0.4999999, 0.4999999, 0.4999999, 0.5, true",
        })
        void lowerThan(double d1, double d2, double d3, double k, boolean expected) {
            assertThat(new Double3(d1, d2, d3).lowerThan(k)).isEqualTo(expected);
        }
    }

    @Nested
    @DisplayName("lowerThan(Double3): each component below its counterpart")
    class LowerThanTriple {
        @ParameterizedTest(name = "({0},{1},{2}) < (1,2,3) is {3}")
        @CsvSource({
                "0, 1, 2, true",
                "1, 1, 2, false",
                "0, 2, 2, false",
                "0, 1, 3, false",
                "2, 0, 0, false",
                "0, 0, 4, false",
        })
        void lowerThan(double d1, double d2, double d3, boolean expected) {
            assertThat(new Double3(d1, d2, d3).lowerThan(new Double3(1, 2, 3))).isEqualTo(expected);
        }
    }

    @Nested
    @DisplayName("equals is tolerant within isZero")
    class Equality {
        @Test
        void differencesBelowTheToleranceAreEqual() {
            Double3 near = new Double3(1 + 0x1p-45, 2 - 0x1p-45, 3 + 0x1p-42);
            assertThat(near).isEqualTo(a);
            assertThat(a).isEqualTo(near);
            assertThat(near.hashCode()).isEqualTo(a.hashCode());
        }

        @ParameterizedTest(name = "a difference of 2^-40 in component {0} is not equal")
        @CsvSource({ "0", "1", "2" })
        void differencesAtTheToleranceAreNotEqual(int component) {
            double[] d = { 1, 2, 3 };
            d[component] += 0x1p-40;
            assertThat(new Double3(d[0], d[1], d[2])).isNotEqualTo(a);
        }

        @Test
        void notEqualToOtherTypes() {
            assertThat(a).isNotEqualTo(new Point(1, 2, 3)).isNotEqualTo(null);
        }
    }
}
