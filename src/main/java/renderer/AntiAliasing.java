package renderer;

/**
 * How each pixel is sampled. Chosen with {@link Camera.Builder#setAntiAliasing(AntiAliasing)}.
 */
public enum AntiAliasing {
    /** One ray through the pixel centre: the plain course render. */
    NONE,
    /** An m×n grid of cells, one ray through a random point of each (jittered supersampling). */
    RANDOM,
    /** The centre and the four corners, averaged; corners are shared with the neighbouring pixels. */
    CORNERS,
    /**
     * The four corners, shared with the neighbouring pixels (one ray per pixel where the image is
     * smooth); where they disagree, the four quadrants are sampled the same way, down to the
     * maximum depth ({@link Camera.Builder#setAdaptive}: 1..6, default 3, sub-pixels down to 1/8
     * of the side). Corners disagree when they spread over more than the threshold divided by the
     * square's share of the pixel in some channel (0..255 scale, values clamped to 255; default 8):
     * 8 for the pixel, 32 for a quarter, 128 for a sixteenth, so a square adds at most about the
     * threshold to its pixel's error and deep levels split only at strong edges. Samples are
     * reused; each lattice point is jittered within its cell so that edges aligned with the pixel
     * grid do not alias. The defaults trace about 2 camera rays per pixel on the showcase at
     * 600×600 (BENCHMARKS.md, image quality per ray).
     * <p>With depth of field the corners would each see one random lens point and could agree by
     * chance where the blur is noisy, so each pixel takes its own stratified samples (film and
     * lens points) instead: 8, then 8 more at a time while the standard error of their mean (from
     * their spread) is above the threshold in some channel, up to 4^depth (64 at depth 3): about
     * 10 camera rays per pixel on the showcase with a lens, 40.7 dB against 256 (BENCHMARKS.md,
     * depth of field).
     */
    ADAPTIVE
}
