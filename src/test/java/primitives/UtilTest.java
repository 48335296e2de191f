package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The zero tolerance is a binary-exponent test: |x| < 2^-40 is zero. The boundary values are
 * therefore powers of two, where a decimal literal such as 1e-12 would sit on either side by luck.
 */
class UtilTest {
    /** The smallest magnitude that is not zero. */
    private static final double THRESHOLD = Math.scalb(1.0, -40);

    @Nested
    @DisplayName("isZero")
    class IsZero {
        @ParameterizedTest(name = "{0} is zero")
        @ValueSource(doubles = { 0.0, -0.0, Double.MIN_VALUE, -Double.MIN_VALUE, 0x1p-41, -0x1p-41, 0x1.fffffffffffffp-41 })
        void valuesBelowTheThresholdAreZero(double x) {
            assertThat(Util.isZero(x)).isTrue();
        }

        @ParameterizedTest(name = "{0} is not zero")
        @ValueSource(doubles = { 0x1p-40, -0x1p-40, 1e-9, -1, 1e300, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN })
        void valuesAtOrAboveTheThresholdAreNotZero(double x) {
            assertThat(Util.isZero(x)).isFalse();
        }

        @Test
        @DisplayName("the boundary is exactly 2^-40: its predecessor is zero, it is not")
        void boundaryIsTwoToTheMinusForty() {
            assertThat(Util.isZero(Math.nextDown(THRESHOLD))).isTrue();
            assertThat(Util.isZero(THRESHOLD)).isFalse();
            assertThat(Util.isZero(-Math.nextDown(THRESHOLD))).isTrue();
            assertThat(Util.isZero(-THRESHOLD)).isFalse();
        }
    }

    @Nested
    @DisplayName("alignZero")
    class AlignZero {
        @ParameterizedTest(name = "{0} is aligned to 0")
        @ValueSource(doubles = { -0.0, 0x1p-41, -0x1p-41, Double.MIN_VALUE, 0x1.fffffffffffffp-41 })
        void tinyValuesBecomeExactlyZero(double x) {
            // Compare bits: -0.0 must become +0.0 as well, so that "== 0" and "> 0" tests agree.
            assertThat(Double.doubleToRawLongBits(Util.alignZero(x))).isEqualTo(Double.doubleToRawLongBits(0.0));
        }

        @ParameterizedTest(name = "{0} is kept")
        @ValueSource(doubles = { 0x1p-40, -0x1p-40, 1e-9, -3.5, 1e300 })
        void otherValuesAreKept(double x) {
            assertThat(Util.alignZero(x)).isEqualTo(x);
        }
    }

    @Nested
    @DisplayName("compareSign")
    class CompareSign {
        @ParameterizedTest(name = "compareSign({0}, {1}) = {2}")
        @CsvSource({
                "1, 2, true",
                "-1, -0.5, true",
                "1, -1, false",
                "-1, 1, false",
                "0, 1, false",
                "1, 0, false",
                "0, -1, false",
                "0, 0, false",
                "-0.0, -1, false",
        })
        void sameNonZeroSignOnly(double a, double b, boolean expected) {
            assertThat(Util.compareSign(a, b)).isEqualTo(expected);
        }
    }

    @Nested
    @DisplayName("argument checks name the bad value")
    class Requirements {
        @Test
        void requirePositive() {
            assertThat(Checks.requirePositive(2.5, "radius")).isEqualTo(2.5);
            assertThatIllegalArgumentException().isThrownBy(() -> Checks.requirePositive(0, "radius"))
                    .withMessageContaining("radius").withMessageContaining("0.0");
            assertThatIllegalArgumentException().isThrownBy(() -> Checks.requirePositive(Double.NaN, "radius"))
                    .withMessageContaining("NaN");
            assertThatIllegalArgumentException().isThrownBy(() -> Checks.requirePositive(Double.POSITIVE_INFINITY, "radius"))
                    .withMessageContaining("Infinity");
        }

        @Test
        void requireNonNegative() {
            assertThat(Checks.requireNonNegative(0, "spread")).isZero();
            assertThatIllegalArgumentException().isThrownBy(() -> Checks.requireNonNegative(-0.5, "spread"))
                    .withMessageContaining("spread").withMessageContaining("-0.5");
            assertThatIllegalArgumentException().isThrownBy(() -> Checks.requireNonNegative(Double.NaN, "spread"))
                    .withMessageContaining("NaN");
        }

        @Test
        void requireFinite() {
            assertThat(Checks.requireFinite(-7, "x")).isEqualTo(-7);
            assertThatIllegalArgumentException().isThrownBy(() -> Checks.requireFinite(Double.NEGATIVE_INFINITY, "x"))
                    .withMessageContaining("-Infinity");
        }
    }
}
