package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicIntegerArray;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The build's chunked loops: every index once, and a failure reads as in a sequential loop. */
class RangesTest {
    private static final ForkJoinPool POOL = new ForkJoinPool(2);

    @AfterAll
    static void stopPool() {
        POOL.shutdown();
    }

    private static ForkJoinPool pool(boolean parallel) {
        return parallel ? POOL : null;
    }

    @ParameterizedTest(name = "n {0}, grain {1}, in a pool {2}")
    @CsvSource({ "0, 4, true", "1, 4, true", "4, 4, true", "5, 4, true", "1000, 7, true", "1000, 1, true", "1000, 7, false" })
    @DisplayName("every index of [0, n) is visited exactly once; in a pool in chunks of at most the grain, else at once")
    void everyIndexOnce(int n, int grain, boolean parallel) {
        AtomicIntegerArray visits = new AtomicIntegerArray(n);
        AtomicInteger largest = new AtomicInteger();
        Ranges.run(pool(parallel), n, grain, (from, to) -> {
            largest.accumulateAndGet(to - from, Math::max);
            for (int i = from; i < to; ++i) visits.incrementAndGet(i);
        });
        for (int i = 0; i < n; ++i) assertThat(visits.get(i)).as("visits of %d", i).isEqualTo(1);
        assertThat(largest.get()).isEqualTo(parallel ? Math.min(n, grain) : n);
    }

    @ParameterizedTest(name = "in a pool {0}")
    @CsvSource({ "true", "false" })
    @DisplayName("of two failing indices, the lower one's exception is rethrown, itself")
    void firstFailureRethrown(boolean parallel) {
        IllegalStateException first = new IllegalStateException("index 123");
        IllegalArgumentException later = new IllegalArgumentException("index 900");
        assertThatThrownBy(() -> Ranges.run(pool(parallel), 1000, 10, (from, to) -> {
            for (int i = from; i < to; ++i) {
                if (i == 123) throw first;
                if (i == 900) throw later;
            }
        })).isSameAs(first);
    }
}
