package app.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/** The PNG encoder's set-up that the render command runs beside the scene's reading. */
class EncoderWarmUpTest {
    @Test
    @DisplayName("the JDK's PNG encoder is set up without an error")
    void encodes() throws Exception {
        EncoderWarmUp.start().await();
    }

    @Nested
    @DisplayName("the set-up's work")
    class Work {
        @Test
        @DisplayName("runs once, on a daemon thread of its own; await blocks until it is done")
        void runsOnItsOwnThread() throws Exception {
            AtomicReference<Thread> ranOn = new AtomicReference<>();
            CountDownLatch release = new CountDownLatch(1);
            int[] runs = new int[1];
            EncoderWarmUp warmUp = EncoderWarmUp.start(() -> {
                release.await();
                ranOn.set(Thread.currentThread());
                ++runs[0];
                return null;
            });
            Thread waiter = new Thread(() -> {
                try {
                    warmUp.await();
                } catch (IOException | InterruptedException e) {
                    throw new AssertionError(e);
                }
            });
            waiter.start();
            while (waiter.getState() != Thread.State.WAITING && waiter.getState() != Thread.State.TERMINATED)
                Thread.onSpinWait();
            assertThat(waiter.getState()).as("await blocks while the work has not finished").isEqualTo(Thread.State.WAITING);
            release.countDown();
            waiter.join();
            warmUp.await();
            warmUp.await();
            assertThat(ranOn.get()).isNotSameAs(Thread.currentThread());
            assertThat(ranOn.get().isDaemon()).isTrue();
            assertThat(runs[0]).isEqualTo(1);
        }

        @Test
        @DisplayName("a failure reaches await as an IOException that names it")
        void failureReachesAwait() {
            EncoderWarmUp warmUp = EncoderWarmUp.start(() -> {
                throw new IOException("no space left on device");
            });
            assertThatThrownBy(warmUp::await).isInstanceOf(IOException.class)
                    .hasMessage("cannot encode PNG images in this JVM: java.io.IOException: no space left on device")
                    .hasCauseInstanceOf(IOException.class);
        }

        @Test
        @DisplayName("an error (out of memory, say) is rethrown as it is")
        void errorRethrown() {
            OutOfMemoryError oom = new OutOfMemoryError("Java heap space");
            EncoderWarmUp warmUp = EncoderWarmUp.start(() -> {
                throw oom;
            });
            assertThatThrownBy(warmUp::await).isSameAs(oom);
        }
    }
}
