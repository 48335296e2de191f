package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Components are compared exactly where the arithmetic is exact; the course's tolerant equals is tested in Course5786Test. */
class ColorTest {
    private final Color c = new Color(10, 20, 30);

    private static void assertRgb(Color actual, double r, double g, double b) {
        assertThat(new double[] { actual.getR(), actual.getG(), actual.getB() }).containsExactly(r, g, b);
    }

    @Nested
    @DisplayName("construction")
    class Construction {
        @ParameterizedTest(name = "({0},{1},{2}) is rejected")
        @CsvSource({ "-1, 0, 0", "0, -0.001, 0", "0, 0, -255", "NaN, 0, 0", "0, Infinity, 0" })
        void negativeOrNonFiniteComponentsAreRejected(double r, double g, double b) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Color(r, g, b))
                    .withMessageContaining("(" + r + "," + g + "," + b + ")");
        }

        @Test
        @DisplayName("zero and values above 255 are valid (light accumulates before clamping)")
        void boundaryComponentsAreValid() {
            assertRgb(new Color(0, 255, 1000), 0, 255, 1000);
            assertRgb(Color.BLACK, 0, 0, 0);
        }

        @Test
        void fromAwtColor() {
            assertRgb(new Color(new java.awt.Color(1, 128, 255)), 1, 128, 255);
        }
    }

    @Nested
    @DisplayName("getColor / toRgb clamp to 0..255")
    class Clamping {
        @Test
        void valuesInRangeAreRoundedDown() {
            java.awt.Color awt = new Color(0.9, 100.7, 254.99).getColor();
            assertThat(new int[] { awt.getRed(), awt.getGreen(), awt.getBlue() }).containsExactly(0, 100, 254);
        }

        @Test
        void valuesAboveRangeAreClamped() {
            java.awt.Color awt = new Color(255, 256, 1e9).getColor();
            assertThat(new int[] { awt.getRed(), awt.getGreen(), awt.getBlue() }).containsExactly(255, 255, 255);
            assertThat(new Color(300, 0, 255.5).toRgb()).isEqualTo(0xFF00FF);
        }

        @Test
        void toRgbPacksTheChannels() {
            assertThat(new Color(0x12, 0x34, 0x56).toRgb()).isEqualTo(0x123456);
        }
    }

    @Nested
    @DisplayName("arithmetic")
    class Arithmetic {
        @Test
        void addOneOrMany() {
            assertRgb(c.add(new Color(1, 2, 3)), 11, 22, 33);
            assertRgb(c.add(new Color(1, 2, 3), new Color(100, 0, 0)), 111, 22, 33);
            assertRgb(c.add(new Color[0]), 10, 20, 30);
        }

        @Test
        void scaleByScalarAndByTriple() {
            assertRgb(c.scale(0.5), 5, 10, 15);
            assertRgb(c.scale(0), 0, 0, 0);
            assertRgb(c.scale(new Double3(1, 0.5, 2)), 10, 10, 60);
        }

        @ParameterizedTest(name = "scale({0}) is rejected")
        @ValueSource(doubles = { -0.5, Double.NaN, Double.POSITIVE_INFINITY })
        void badScaleFactorIsRejected(double k) {
            assertThatIllegalArgumentException().isThrownBy(() -> c.scale(k)).withMessageContaining(String.valueOf(k));
            assertThatIllegalArgumentException().isThrownBy(() -> c.scale(new Double3(1, k, 1)));
        }

        @Test
        void reduceDividesEveryChannel() {
            assertRgb(c.reduce(10), 1, 2, 3);
            assertRgb(c.reduce(4.0), 2.5, 5, 7.5);
            assertRgb(c.reduce(1), 10, 20, 30);
        }

        @ParameterizedTest(name = "reduce({0}) is rejected")
        @ValueSource(ints = { 0, -2 })
        void nonPositiveReduceIsRejected(int k) {
            assertThatIllegalArgumentException().isThrownBy(() -> c.reduce(k)).withMessageContaining(String.valueOf(k));
            assertThatIllegalArgumentException().isThrownBy(() -> c.reduce((double) k));
        }

        @Test
        void operandsAreNotModified() {
            c.add(c).scale(2).reduce(3);
            assertRgb(c, 10, 20, 30);
        }
    }

    @Nested
    @DisplayName("distance: the largest per-channel difference")
    class Distance {
        @ParameterizedTest(name = "to ({0},{1},{2}) is {3}")
        @CsvSource({
                "10, 20, 30, 0",
                "13, 20, 30, 3",
                "10, 15, 30, 5",
                "10, 20, 37, 7",
                "12, 16, 31, 4",
        })
        void largestChannelDifference(double r, double g, double b, double expected) {
            Color other = new Color(r, g, b);
            assertThat(c.distance(other)).isEqualTo(expected);
            assertThat(other.distance(c)).isEqualTo(expected);
        }
    }
}
