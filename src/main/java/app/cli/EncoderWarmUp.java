package app.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;

import javax.imageio.ImageIO;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * The PNG encoder's one-time set-up, done on a thread of its own while the scene is read: an
 * 8x8 image encoded to nowhere. The first PNG a JVM writes first loads the JDK's AWT library and
 * fills the image I/O registry ({@code java.awt.Rectangle}'s and {@code ImageIO}'s initialisers
 * the largest parts). That ran on the main thread after the render, where nothing else runs. In a
 * 1-sample render of the 137-primitive Sunflow scene (JDK 17, 16 launches each, with progress
 * lines) the write took 95 ms before and 60 ms after, while the time before the render grew by
 * 36 ms: the second core is not always idle while the scene is read. With {@code --quiet} the launch
 * took 0.975 of the time (30 rotated pairs); on JDK 25, whose start-up cache holds these classes
 * linked, nothing beyond the noise (BENCHMARKS.md, issue 50, thirteenth session).
 *
 * <p>The render waits for it ({@link #await}) before it starts, so that the set-up never takes a
 * core from the render's threads, and so that an encoder that cannot work in this JVM fails the
 * command before the render rather than after it.
 */
final class EncoderWarmUp {
    private final FutureTask<Void> task;

    private EncoderWarmUp(FutureTask<Void> task) {
        this.task = task;
    }

    /** @return the PNG encoder's set-up, started */
    static EncoderWarmUp start() {
        return start(EncoderWarmUp::encodeTinyImage);
    }

    /**
     * @param work the set-up, run once on a daemon thread (a daemon: a command that ends before
     *             it, a usage error say, does not wait for it)
     * @return the set-up, started
     */
    static EncoderWarmUp start(Callable<Void> work) {
        FutureTask<Void> task = new FutureTask<>(work);
        Thread thread = new Thread(task, "raytracer-png-set-up");
        thread.setDaemon(true);
        thread.start();
        return new EncoderWarmUp(task);
    }

    /**
     * Waits until the set-up is done.
     *
     * @throws IOException          naming why the PNG encoder cannot work, when the set-up failed
     * @throws InterruptedException when the calling thread is interrupted while it waits
     */
    void await() throws IOException, InterruptedException {
        try {
            task.get();
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof Error error) throw error;
            throw new IOException("cannot encode PNG images in this JVM: " + cause, cause);
        }
    }

    /** Through the classes a real write uses, except the file: a memory stream that discards what it is given. */
    private static Void encodeTinyImage() throws IOException {
        BufferedImage image = new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB);
        try (MemoryCacheImageOutputStream out = new MemoryCacheImageOutputStream(OutputStream.nullOutputStream())) {
            if (!ImageIO.write(image, "png", out)) throw new IOException("no PNG writer available");
        }
        return null;
    }
}
