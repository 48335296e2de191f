package renderer;

import java.io.PrintStream;
import java.util.Objects;

/**
 * Internal: how a render runs. Public only so that the scene reader and the command line check a
 * thread count by this rule ({@link #requireThreads}) before any camera exists; a scene test sets
 * these through {@link Camera.Builder}.
 *
 * <p>On how many threads, in tiles of what side, with what progress lines and where they go. A
 * value, checked when it is made; none of it changes a pixel.
 *
 * @param threads      worker threads; 0: the calling thread (a builder's -1 and -2, all cores,
 *                     are resolved to the core count before this is made)
 * @param tileSize     the side of the square tiles workers claim, in pixels, ≥ 1
 * @param progressStep percent of the pixels between progress lines, in [0, 100]; 0: none
 * @param output       where progress lines go (and, for the camera, its summary and write lines)
 * @hidden
 */
public record Execution(int threads, int tileSize, double progressStep, PrintStream output) {
    /**
     * Render threads per available core at most: rendering is bound by the processor, so more
     * threads than cores gain nothing, and a few times more stay harmless; a count such as 100,000
     * would exhaust the native threads of the machine.
     */
    public static final int MAX_THREADS_PER_CORE = 8;

    /**
     * @param threads      worker threads
     * @param tileSize     the tile side in pixels
     * @param progressStep percent of the pixels between progress lines
     * @param output       where progress lines go
     * @throws IllegalArgumentException for a negative thread count, a tile below 1 pixel or a
     *                                  progress step outside [0, 100], naming it
     * @throws NullPointerException     when the output is missing
     */
    public Execution {
        if (threads < 0) throw new IllegalArgumentException("thread count must be 0 (the calling thread) or more, got " + threads);
        if (tileSize < 1) throw new IllegalArgumentException("tile size must be at least 1 pixel, got " + tileSize);
        Progress.requireStep(progressStep);
        Objects.requireNonNull(output, "output stream");
    }

    /**
     * @return the most render threads this machine allows: {@link #MAX_THREADS_PER_CORE} per
     *         available core
     */
    public static int maxThreads() {
        return MAX_THREADS_PER_CORE * Runtime.getRuntime().availableProcessors();
    }

    /**
     * The thread rule of {@link Camera.Builder#setMultithreading(int)}.
     *
     * @param threads 0: the calling thread; n &gt; 0: n workers, at most {@link #maxThreads()};
     *                -1 or -2: all cores
     * @return {@code threads}
     * @throws IllegalArgumentException for another value, naming it and the limit
     */
    public static int requireThreads(int threads) {
        if (threads < -2)
            throw new IllegalArgumentException("thread count must be 0 (calling thread), a positive number, or -1 or -2 (all cores), got " + threads);
        if (threads > maxThreads())
            throw new IllegalArgumentException("thread count " + threads + " is more than the limit of " + maxThreads()
                    + " (" + MAX_THREADS_PER_CORE + " per core, " + Runtime.getRuntime().availableProcessors() + " cores)");
        return threads;
    }

    /**
     * @param threads a count {@link #requireThreads} accepts
     * @return the worker threads it means: the core count for -1 and -2
     */
    static int resolveThreads(int threads) {
        return threads < 0 ? Runtime.getRuntime().availableProcessors() : threads;
    }
}
