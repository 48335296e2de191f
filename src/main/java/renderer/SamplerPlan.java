package renderer;

import java.util.function.Supplier;

/**
 * What one anti-aliasing mode needs for a render, decided once ({@link Sampling#plan(boolean)}):
 * the most camera rays a pixel may take (the ray budget's factor), the render loop's tile side,
 * each worker's sampler, and the mode's words for the summary line. Each sampler class defines
 * its own plan beside it, so adding a mode is one sampler class with its plan, one
 * {@link AntiAliasing} constant and the arm of {@code Sampling.plan} the compiler then asks for.
 * Not sealed: nothing switches over plans, and a {@code permits} list would tie this interface
 * back to every sampler that implements it.
 */
interface SamplerPlan {
    /** @return the mode, for messages */
    AntiAliasing mode();

    /**
     * @return the most camera rays one pixel may take: the worst case, which a test holds equal
     *         to the rays a worst-case pixel traces; a long (a grid of two ints may overflow an int)
     */
    long maxSamplesPerPixel();

    /**
     * @return the fewest camera rays a pixel takes, as far as a render's size is estimated before it
     *         starts ({@link PreparedTracer#expectCameraRays}): {@link #maxSamplesPerPixel()}, but
     *         for modes whose pixels take fewer where the image is smooth
     */
    default long leastSamplesPerPixel() {
        return maxSamplesPerPixel();
    }

    /** @return the side, in pixels, of the render loop's square tiles that suits this sampler */
    int tileSize();

    /**
     * The samplers of one pass over the pixels [x0, x1) × [y0, y1), in tiles from (x0, y0): each
     * call of the supplier gives one worker a new sampler, whose scratch state is its own. What the
     * pass's workers share is made here, once per pass ({@link LatticeSeams}).
     *
     * @param estimator the colour of a camera sample, from the render loop
     * @param tileSize  the render loop's tile side, in pixels, at most {@link #tileSize()} (a
     *                  lattice sampler's cache covers one tile)
     */
    Supplier<PixelSampler> samplers(Estimator estimator, int tileSize, int x0, int y0, int x1, int y1);

    /** @return the mode and its parameters in words, as the summary line shows them ("RANDOM 4x4") */
    String describe();

    /** @return what the summary line adds after the lens's words: the lens samples where this mode takes them; "" by default */
    default String lensSamples() {
        return "";
    }
}
