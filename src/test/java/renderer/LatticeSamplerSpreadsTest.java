package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * ADAPTIVE's corner test, {@link LatticeSampler#spreads}: it must decide as the formula with
 * {@link Math#min} and {@link Math#max} it replaced decides, on every input, or the images change.
 */
class LatticeSamplerSpreadsTest {
    /** The formula as it was written before: each value clamped to 255, then largest minus smallest. */
    private static boolean withMinAndMax(double[] ch, double threshold) {
        double va = Math.min(ch[0], 255), vb = Math.min(ch[1], 255), vc = Math.min(ch[2], 255), vd = Math.min(ch[3], 255);
        return Math.max(Math.max(va, vb), Math.max(vc, vd)) - Math.min(Math.min(va, vb), Math.min(vc, vd)) > threshold;
    }

    private static boolean spreads(double[] ch, double threshold) {
        return LatticeSampler.spreads(ch, 0, 1, 2, 3, threshold);
    }

    @ParameterizedTest(name = "{0}, {1}, {2}, {3} over {4}: {5}")
    @CsvSource({
            "10, 20, 30, 40, 29.9, true", // 40 - 10
            "10, 20, 30, 40, 30, false", // not above the threshold
            "40, 30, 20, 10, 29.9, true", // the order of the corners does not matter
            "250, 300, 900, 252, 5, false", // over-exposed values count as 255: 255 - 250
            "250, 300, 900, 249, 5, true", // 255 - 249
            "0, -0.0, 0, -0.0, -1, true", // zeros of either sign: a spread of 0, above a negative threshold
            "NaN, 0, 255, 0, 1, false", // a NaN makes Math.min and max NaN: never a spread
            "-Infinity, 0, 0, 0, 1e300, true", // an infinite spread
            "Infinity, 0, 0, 0, 254.9, true", // +∞ counts as 255
    })
    void examples(double a, double b, double c, double d, double threshold, boolean expected) {
        double[] ch = { a, b, c, d };
        assertThat(withMinAndMax(ch, threshold)).as("the old formula").isEqualTo(expected);
        assertThat(spreads(ch, threshold)).isEqualTo(expected);
    }

    @Test
    @DisplayName("decides as the Math.min and Math.max formula on random corners: NaN, infinities, signed zeros and ties included")
    void asTheFormulaWithMinAndMax() {
        Random rnd = new Random(41);
        double[] special = { Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0.0, -0.0, 255, 254.5, 256 };
        double[] thresholds = { 8, 32, 128, 0, -0.0, -1, Double.POSITIVE_INFINITY };
        int yes = 0, no = 0;
        for (int i = 0; i < 300_000; ++i) {
            double[] ch = new double[4];
            for (int k = 0; k < 4; ++k) {
                int kind = rnd.nextInt(8);
                ch[k] = kind == 0 ? special[rnd.nextInt(special.length)]
                        : kind == 1 && k > 0 ? ch[rnd.nextInt(k)] // a tie with an earlier corner
                        : 400 * rnd.nextDouble() - 50;
            }
            double threshold = rnd.nextInt(4) == 0 ? thresholds[rnd.nextInt(thresholds.length)] : 300 * rnd.nextDouble();
            boolean expected = withMinAndMax(ch, threshold);
            assertThat(spreads(ch, threshold)).as("corners %s, threshold %s", Arrays.toString(ch), threshold).isEqualTo(expected);
            if (expected) ++yes;
            else ++no;
        }
        // Both answers must occur often, or the comparison proves little.
        assertThat(yes).isGreaterThan(30_000);
        assertThat(no).isGreaterThan(30_000);
    }
}
