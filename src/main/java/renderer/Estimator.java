package renderer;

import primitives.Rgb;

/**
 * The colour of one camera sample, what a {@link PixelSampler} averages: the render loop makes it
 * from the view's camera rays and the shading the render prepared, so that a sampler knows neither
 * the camera nor the tracer, only where on the film and the lens it samples.
 */
@FunctionalInterface
interface Estimator {
    /**
     * Traces the camera sample through film point (px, py) (pixels from the image's top-left
     * corner: pixel (x, y)'s centre is (x + 0.5, y + 0.5)) and lens point (u, v) of the unit
     * square (ignored by a pinhole). The tracer draws its own numbers from {@code ctx.random} as
     * the caller positioned it.
     *
     * @param px  film x, in pixels
     * @param py  film y, in pixels
     * @param u   lens u, in [0, 1)
     * @param v   lens v, in [0, 1)
     * @param ctx the worker's scratch state
     * @return the colour seen, on the 0..255 scale: the context's, valid until its next trace
     */
    Rgb estimate(double px, double py, double u, double v, TraceContext ctx);
}
