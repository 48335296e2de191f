package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Set;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * {@link SobolPoints}: the stratification a pixel's samples rely on, for any seed: every
 * power-of-two prefix is a (0, k, 2)-net, and a prefix of any length puts at most one point in a
 * cell of the net of the next power of two.
 */
class SobolPointsTest {
    private static final int[] SEEDS = { 0, 1, -1, 0x5eed, 0x7fff_ffff, 0x8000_0000, 123_456_789 };

    static Stream<Arguments> sizesAndSeeds() {
        return IntStream.rangeClosed(0, 8).boxed()
                .flatMap(k -> IntStream.of(SEEDS).mapToObj(seed -> Arguments.of(1 << k, seed)));
    }

    /** How many of the first n points fall in each cell of the columns × rows grid, row-major. */
    private static int[] counts(int n, int seed, int columns, int rows) {
        int[] cells = new int[columns * rows];
        for (int i = 0; i < n; ++i) {
            double x = SobolPoints.x(i, seed), y = SobolPoints.y(i, seed);
            assertThat(x).as("x of point %d", i).isGreaterThanOrEqualTo(0).isLessThan(1);
            assertThat(y).as("y of point %d", i).isGreaterThanOrEqualTo(0).isLessThan(1);
            ++cells[(int) (y * rows) * columns + (int) (x * columns)];
        }
        return cells;
    }

    @Nested
    @DisplayName("stratification")
    class Stratification {
        @ParameterizedTest(name = "the first {0} points under seed {1}: one in each cell of every grid of {0} cells")
        @MethodSource("renderer.SobolPointsTest#sizesAndSeeds")
        void powerOfTwoPrefixIsANet(int n, int seed) {
            for (int columns = 1; columns <= n; columns *= 2)
                assertThat(counts(n, seed, columns, n / columns)).as("%d x %d grid", columns, n / columns)
                        .containsOnly(1);
        }

        @ParameterizedTest(name = "the first {0} points under seed 42: at most one in each cell of the 4x4, 2x8 and 8x2 grids")
        @MethodSource("renderer.SobolPointsTest#between8And16")
        void otherCountsFillEmptyCells(int n) {
            for (int columns : new int[] { 2, 4, 8 })
                assertThat(counts(n, 42, columns, 16 / columns)).as("%d x %d grid", columns, 16 / columns)
                        .containsOnly(0, 1);
        }
    }

    static IntStream between8And16() {
        return IntStream.rangeClosed(9, 15);
    }

    @Nested
    @DisplayName("seeds")
    class Seeds {
        @Test
        @DisplayName("the same index and seed give the same point, on any call")
        void deterministic() {
            for (int i = 0; i < 64; ++i) {
                assertThat(SobolPoints.x(i, 77)).isEqualTo(SobolPoints.x(i, 77));
                assertThat(SobolPoints.y(i, 77)).isEqualTo(SobolPoints.y(i, 77));
            }
        }

        @Test
        @DisplayName("another seed gives other points: neighbouring pixels do not repeat one pattern")
        void seedsDecorrelate() {
            Set<Double> firstPoints = new HashSet<>();
            for (int seed = 0; seed < 100; ++seed) firstPoints.add(SobolPoints.x(0, seed));
            assertThat(firstPoints).as("point 0's x under 100 seeds").hasSize(100);
        }

        @Test
        @DisplayName("the two coordinates of one point are not the same number")
        void coordinatesDiffer() {
            for (int i = 0; i < 16; ++i) assertThat(SobolPoints.x(i, 9)).isNotEqualTo(SobolPoints.y(i, 9));
        }
    }
}
