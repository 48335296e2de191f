package renderer;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * The temporary file of one image write, and what becomes of it when the JVM exits during the
 * write (SIGINT, SIGTERM, {@code System.exit}): registered as a shutdown hook, it marks the write
 * abandoned, waits (a bounded time) until the writer has let go of the file, and deletes it, so
 * that neither a half-written file nor a finished one that was never moved into place is left.
 * The writer asks {@link #mayComplete()} before moving the file into place.
 */
final class InFlightFile {
    /** How long the exiting JVM waits for the writer to let go of the file. */
    private static final long WAIT_MS = 10_000;
    /** Names tried before {@link #createBeside} gives up (each try takes a new one). */
    private static final int NAME_TRIES = 64;

    private Path file;
    private boolean abandoned;
    private boolean released;

    /**
     * Creates an empty hidden file beside {@code target}, named after it, for the image to be
     * written into before it is moved into place. Not {@code Files.createTempFile}: its first call
     * in a JVM seeds a {@code SecureRandom}, about 20 ms of a fresh JVM's first image write
     * (BENCHMARKS.md, "One call per box, a static archive"). The name here comes from the thread
     * and the clock; its uniqueness comes from the file system, which refuses to create a name
     * that exists, and a refused try takes the clock again.
     *
     * @return the new file: {@code .<target's name>.<thread>-<clock>.tmp} in target's folder
     * @throws IOException when the folder cannot take the file, or {@value #NAME_TRIES} names in a
     *                     row were taken
     */
    static Path createBeside(Path target) throws IOException {
        String stem = "." + target.getFileName() + "." + Long.toHexString(Thread.currentThread().getId()) + "-";
        FileAlreadyExistsException taken = null;
        for (int i = 0; i < NAME_TRIES; ++i) {
            try {
                return Files.createFile(target.resolveSibling(stem + Long.toHexString(System.nanoTime()) + ".tmp"));
            } catch (FileAlreadyExistsException e) {
                taken = e;
            }
        }
        throw new IOException(NAME_TRIES + " temporary names beside " + target + " were taken, the last "
                + taken.getFile(), taken);
    }

    /** @param file the temporary file, once it exists */
    synchronized void created(Path file) {
        this.file = file;
    }

    /**
     * @return true if the write may complete (the JVM is not exiting); from then on an exit waits
     *         for {@link #release()} and the completed image stays
     */
    synchronized boolean mayComplete() {
        return !abandoned;
    }

    /** The writer is done with the file: moved, deleted, or failed. */
    synchronized void release() {
        released = true;
        notifyAll();
    }

    /** The shutdown hook's work: abandon the write, wait for the writer, delete what is left. */
    void abandon() {
        Path leftOver;
        synchronized (this) {
            abandoned = true;
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
            for (long left = WAIT_MS; !released && left > 0; left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())) {
                try {
                    wait(left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
            }
            leftOver = file;
        }
        if (leftOver == null) return;
        try {
            Files.deleteIfExists(leftOver);
        } catch (IOException e) {
            System.err.println("cannot delete the unfinished image " + leftOver + ": " + e.getMessage());
        }
    }
}
