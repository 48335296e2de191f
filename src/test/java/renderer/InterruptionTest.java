package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Interrupting the thread that renders cancels the render: {@code renderImage()} throws
 * CancellationException, so {@code renderImage().writeToImage()} writes nothing, and the
 * interrupt flag stays set for the caller.
 */
class InterruptionTest {
    private final String name = "rtests-interrupted-" + UUID.randomUUID();
    private final Path file = ImageWriter.IMAGES.resolve(name + ".png");

    @AfterEach
    void cleanUp() throws Exception {
        Files.deleteIfExists(file);
    }

    /** An output stream that opens a latch on the first progress line: the render is under way. */
    private static PrintStream signalOnFirstLine(CountDownLatch started) {
        return new PrintStream(new OutputStream() {
            @Override
            public void write(int b) {
                started.countDown();
            }
        }, true);
    }

    @ParameterizedTest(name = "{0} threads")
    @ValueSource(ints = {0, 2})
    void interruptCancelsTheRender(int threads) throws Exception {
        CountDownLatch started = new CountDownLatch(1);
        // RANDOM 8x8 at 200x200 with glossy reflections and soft shadows: far more work than the
        // test waits for, so the interrupt always lands mid-render.
        ImageWriter image = new ImageWriter(name, 200, 200);
        Camera camera = TestScenes.camera(TestScenes.everyEffect(), image)
                .setAntiAliasing(AntiAliasing.RANDOM, 8, 8)
                .setMultithreading(threads)
                .setDebugPrint(1).setOutput(signalOnFirstLine(started))
                .build();
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        AtomicBoolean interruptFlagKept = new AtomicBoolean();
        Thread renderer = new Thread(() -> {
            try {
                camera.renderImage().writeToImage();
            } catch (Throwable t) {
                thrown.set(t);
                interruptFlagKept.set(Thread.currentThread().isInterrupted());
            }
        }, "interrupted-render");
        renderer.start();
        assertThat(started.await(20, TimeUnit.SECONDS)).as("render started (first progress line)").isTrue();
        renderer.interrupt();
        renderer.join(TimeUnit.SECONDS.toMillis(20)); // a liveness guard, not a timing assertion
        assertThat(renderer.isAlive()).as("the render thread stopped").isFalse();

        assertThat(thrown.get()).isInstanceOf(CancellationException.class).hasMessageContaining(name);
        assertThat(interruptFlagKept).as("interrupt flag kept").isTrue();
        assertThat(file).as("no image written").doesNotExist();
    }
}
