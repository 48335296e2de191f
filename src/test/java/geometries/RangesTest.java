package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.atomic.AtomicIntegerArray;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
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
    @CsvSource({ "0, 4, true", "1, 4, true", "4, 4, true", "5, 4, true", "1000, 7, true", "1000, 1, true", "0, 4, false",
            "5, 4, false", "1000, 7, false" })
    @DisplayName("every index of [0, n) is visited exactly once, in the chunks [k·grain, min(n, (k + 1)·grain)) with or"
            + " without a pool, and in order without one")
    void everyIndexOnce(int n, int grain, boolean parallel) {
        AtomicIntegerArray visits = new AtomicIntegerArray(n);
        List<int[]> chunks = Collections.synchronizedList(new ArrayList<>());
        Ranges.run(pool(parallel), n, grain, (from, to) -> {
            chunks.add(new int[] { from, to });
            for (int i = from; i < to; ++i) visits.incrementAndGet(i);
        });
        for (int i = 0; i < n; ++i) assertThat(visits.get(i)).as("visits of %d", i).isEqualTo(1);
        List<int[]> expected = new ArrayList<>();
        for (int from = 0; from < n; from += grain) expected.add(new int[] { from, Math.min(n, from + grain) });
        List<int[]> seen = new ArrayList<>(chunks);
        if (parallel) seen.sort(Comparator.comparingInt(c -> c[0]));
        assertThat(seen).as("the chunks%s", parallel ? ", sorted" : ", in the order run").containsExactlyElementsOf(expected);
    }

    @Test
    @DisplayName("on one thread, a range near the int limit ends in two chunks (a chunk's end never overflows)")
    void noOverflowNearTheLimit() {
        List<int[]> chunks = new ArrayList<>();
        Ranges.run(null, Integer.MAX_VALUE, Integer.MAX_VALUE - 100, (from, to) -> {
            // An end that overflowed would be below its start (and the loop would never end): fail at once.
            assertThat(to).as("the end of the chunk from %d", from).isGreaterThan(from);
            chunks.add(new int[] { from, to });
        });
        assertThat(chunks).containsExactly(new int[] { 0, Integer.MAX_VALUE - 100 },
                new int[] { Integer.MAX_VALUE - 100, Integer.MAX_VALUE });
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
