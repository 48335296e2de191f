package renderer;

import java.io.PrintStream;
import java.util.Objects;

/**
 * How a render runs: on how many threads, in tiles of what side, with what progress lines and
 * where they go. A value, checked when it is made; none of it changes a pixel.
 *
 * @param threads      worker threads; 0: the calling thread (a builder's -1 and -2, all cores,
 *                     are resolved to the core count before this is made)
 * @param tileSize     the side of the square tiles workers claim, in pixels, ≥ 1
 * @param progressStep percent of the pixels between progress lines, in [0, 100]; 0: none
 * @param output       where progress lines go (and, for the camera, its summary and write lines)
 */
record Execution(int threads, int tileSize, double progressStep, PrintStream output) {
    /**
     * @throws IllegalArgumentException for a negative thread count, a tile below 1 pixel or a
     *                                  progress step outside [0, 100], naming it
     * @throws NullPointerException     when the output is missing
     */
    Execution {
        if (threads < 0) throw new IllegalArgumentException("thread count must be 0 (the calling thread) or more, got " + threads);
        if (tileSize < 1) throw new IllegalArgumentException("tile size must be at least 1 pixel, got " + tileSize);
        Progress.requireStep(progressStep);
        Objects.requireNonNull(output, "output stream");
    }
}
