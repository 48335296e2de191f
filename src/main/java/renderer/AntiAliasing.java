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
     * smooth); where they disagree by more than the threshold, the four quadrants are sampled the
     * same way, down to the maximum depth. Samples are reused; each lattice point is jittered
     * within its cell so that edges aligned with the pixel grid do not alias. With depth of
     * field, each pixel instead takes its own stratified samples (film and lens points), 8 and
     * then 8 more at a time while their spread says the pixel's mean is off by more than the
     * threshold, up to 4^depth: the rays go where the blur is noisy.
     */
    ADAPTIVE
}
