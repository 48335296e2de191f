package app.spark;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/**
 * The watch that ends a job a lost cluster would leave waiting, against a fake cluster and a fake
 * clock: it says when it starts waiting, forgives executors that come back, and cancels the job
 * with one line once none has been there for the timeout.
 */
class ExecutorWatchTest {
    private long now;
    private int executors = 2;
    private final List<String> said = new ArrayList<>();
    private final List<String> cancelled = new ArrayList<>();
    private final ExecutorWatch watch = new ExecutorWatch(new ExecutorWatch.Cluster() {
        @Override
        public int executors() {
            return executors;
        }

        @Override
        public void cancel(String reason) {
            cancelled.add(reason);
        }
    }, 30, () -> now, said::add);

    private boolean at(double seconds) {
        now = (long) (seconds * 1e9);
        return watch.check();
    }

    @Test
    @DisplayName("executors present: nothing said, nothing cancelled")
    void healthy() {
        assertThat(at(0)).isFalse();
        assertThat(at(1000)).isFalse();
        assertThat(said).isEmpty();
        assertThat(cancelled).isEmpty();
    }

    @Test
    @DisplayName("every executor lost: a waiting line, then after the timeout the job is cancelled with the reason")
    void lost() {
        at(0);
        executors = 0;
        assertThat(at(1)).isFalse();
        assertThat(said).containsExactly("waiting for executors: none is available (the job ends if none comes within 30 s)");
        assertThat(at(30.9)).isFalse();
        assertThat(at(31)).isTrue();
        assertThat(cancelled).containsExactly("every executor was lost and none came back for 30 s: the cluster lost its"
                + " workers (the limit is spark.raytracer.executorTimeout)");
        assertThat(watch.reason()).isEqualTo(cancelled.get(0));
        assertThat(at(100)).as("cancelled once").isTrue();
        assertThat(cancelled).hasSize(1);
    }

    @Test
    @DisplayName("no executor yet when the job starts, then the first ones: they joined, they are not back")
    void joined() {
        executors = 0;
        at(0);
        executors = 1;
        assertThat(at(2)).isFalse();
        assertThat(said).containsExactly("waiting for executors: none is available (the job ends if none comes within 30 s)",
                "executors joined; the job goes on");
    }

    @Test
    @DisplayName("executors back within the timeout: the wait starts afresh")
    void back() {
        at(0); // seen
        executors = 0;
        at(0);
        executors = 1;
        assertThat(at(29)).isFalse();
        executors = 0;
        assertThat(at(40)).isFalse();
        assertThat(at(69)).isFalse();
        assertThat(at(70)).isTrue();
        assertThat(said).hasSize(3).element(1).isEqualTo("executors are back; the job goes on");
    }

    @Test
    @DisplayName("a timeout under a second is said to the millisecond, not as 0 s")
    void shortTimeout() {
        List<String> lines = new ArrayList<>();
        ExecutorWatch w = new ExecutorWatch(new ExecutorWatch.Cluster() {
            @Override
            public int executors() {
                return 0;
            }

            @Override
            public void cancel(String reason) {
                lines.add(reason);
            }
        }, 0.001, () -> now, lines::add);
        now = 0;
        w.check();
        now = 2_000_000;
        assertThat(w.check()).isTrue();
        assertThat(lines).containsExactly(
                "waiting for executors: none is available (the job ends if none comes within 0.001 s)",
                "no executor joined in the 0.001 s since the job asked for them: the cluster has no worker free for this"
                        + " job, or its executors take longer to start (raise spark.raytracer.executorTimeout)");
    }
}
