package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The per-sample random stream: a pure function of (seed, x, y, sample index). */
class SampleStreamTest {
    private static double[] draw(long seed, int x, int y, int index, int n) {
        SampleStream s = new SampleStream().reset(seed, x, y, index);
        double[] values = new double[n];
        for (int i = 0; i < n; ++i) values[i] = s.nextDouble();
        return values;
    }

    @Test
    @DisplayName("the same key gives the same sequence, from a fresh stream or a reused one")
    void sameKeySameSequence() {
        double[] first = draw(7, 12, 34, 5, 100);
        assertThat(draw(7, 12, 34, 5, 100)).isEqualTo(first);
        SampleStream reused = new SampleStream();
        reused.reset(99, 1, 2, 3).nextDouble(); // used for another sample in between
        reused.reset(7, 12, 34, 5);
        for (double expected : first) assertThat(reused.nextDouble()).isEqualTo(expected);
    }

    @ParameterizedTest(name = "(seed {0}, x {1}, y {2}, index {3}) vs (7, 12, 34, 5)")
    @CsvSource({
            "8, 12, 34, 5",
            "7, 13, 34, 5",
            "7, 12, 35, 5",
            "7, 12, 34, 6",
            "7, 34, 12, 5",
            "-7, 12, 34, 5",
            "7, 12, 34, -5",
            "7, 12, 5, 34"})
    @DisplayName("changing any part of the key (or swapping x and y) changes the sequence")
    void differentKeyDifferentSequence(long seed, int x, int y, int index) {
        double[] reference = draw(7, 12, 34, 5, 8), other = draw(seed, x, y, index, 8);
        for (int i = 0; i < 8; ++i)
            assertThat(other[i]).as("value %d", i).isNotEqualTo(reference[i]);
    }

    @Test
    @DisplayName("neighbouring pixels and samples get distinct first values (no collisions in a 64x64x16 block)")
    void neighboursDistinct() {
        Set<Double> firsts = new HashSet<>();
        SampleStream s = new SampleStream();
        for (int x = 0; x < 64; ++x)
            for (int y = 0; y < 64; ++y)
                for (int i = 0; i < 16; ++i) firsts.add(s.reset(0, x, y, i).nextDouble());
        assertThat(firsts).hasSize(64 * 64 * 16);
    }

    @Test
    @DisplayName("values lie in [0, 1) and are spread evenly over it")
    void uniformInUnitInterval() {
        int n = 200_000, bins = 20;
        int[] histogram = new int[bins];
        double sum = 0, min = 1, max = 0;
        SampleStream s = new SampleStream();
        for (int i = 0; i < n; ++i) {
            // A fresh key every 8 values, as the renderer uses it.
            if (i % 8 == 0) s.reset(3, i / 8 % 500, i / 4000, i % 3);
            double v = s.nextDouble();
            min = Math.min(min, v);
            max = Math.max(max, v);
            sum += v;
            histogram[(int) (v * bins)]++;
        }
        assertThat(min).isGreaterThanOrEqualTo(0).isLessThan(0.001);
        assertThat(max).isLessThan(1).isGreaterThan(0.999);
        assertThat(sum / n).isCloseTo(0.5, within(0.005));
        // Each bin expects 10 000 ± 95 (one standard deviation); allow 5 of them.
        for (int count : histogram) assertThat(count).isBetween(n / bins - 500, n / bins + 500);
    }
}
