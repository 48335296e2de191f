package renderer;

import java.util.Objects;

import primitives.Util;

/**
 * How a render samples its pixels: the anti-aliasing mode with the parameters of each mode (a
 * builder keeps all of them, so that switching modes keeps what was set), the lens samples of
 * depth of field without anti-aliasing, and the seed every random number derives from. A value,
 * checked when it is made; it makes each worker's {@link PixelSampler} and knows how many camera
 * rays a pixel may take.
 *
 * @param antiAliasing the mode
 * @param grid         RANDOM's grid of jittered samples
 * @param adaptive     ADAPTIVE's depth and threshold
 * @param lensSamples  rays per pixel with depth of field and no anti-aliasing, 1 to
 *                     {@link Camera#MAX_SAMPLES_PER_PIXEL}
 * @param seed         the render's seed: the same seed gives the same image on any number of threads
 */
record Sampling(AntiAliasing antiAliasing, Grid grid, Adaptive adaptive, int lensSamples, long seed) {
    /** The defaults: no anti-aliasing, a 4×4 grid, adaptive depth 3 and threshold 8, 16 lens samples, seed 0. */
    static final Sampling DEFAULT = new Sampling(AntiAliasing.NONE, new Grid(4, 4),
            new Adaptive(Camera.DEFAULT_ADAPTIVE_DEPTH, Camera.DEFAULT_ADAPTIVE_THRESHOLD), 16, 0);

    /**
     * @throws NullPointerException     naming a missing part
     * @throws IllegalArgumentException for lens samples out of range, naming them
     */
    Sampling {
        Objects.requireNonNull(antiAliasing, "anti-aliasing mode");
        Objects.requireNonNull(grid, "anti-aliasing grid");
        Objects.requireNonNull(adaptive, "adaptive settings");
        requireLensSamples(lensSamples);
    }

    /**
     * RANDOM's grid: columns × rows cells per pixel, one jittered sample in each.
     *
     * @param columns cells across a pixel, ≥ 1
     * @param rows    cells down a pixel, ≥ 1
     */
    record Grid(int columns, int rows) {
        /** @throws IllegalArgumentException for a grid below 1×1 or of more than {@link Camera#MAX_SAMPLES_PER_PIXEL} cells, naming it */
        Grid {
            if (columns < 1 || rows < 1)
                throw new IllegalArgumentException("anti-aliasing grid must be at least 1x1, got " + columns + "x" + rows);
            if (GridSampler.samplesPerPixel(columns, rows) > Camera.MAX_SAMPLES_PER_PIXEL)
                throw new IllegalArgumentException("anti-aliasing grid " + columns + "x" + rows + " has "
                        + GridSampler.samplesPerPixel(columns, rows) + " samples per pixel, more than the limit of "
                        + Camera.MAX_SAMPLES_PER_PIXEL);
        }
    }

    /**
     * ADAPTIVE's settings (see {@link LatticeSampler}, and with a lens {@link NoiseAdaptiveSampler}).
     *
     * @param depth     the deepest subdivision, 1..6: sub-pixels down to 1/2^depth of the pixel
     *                  side; with a lens, at most 4^depth samples a pixel
     * @param threshold the pixel-level corner spread that subdivides, on the 0..255 scale, finite
     *                  and ≥ 0 (the test is "more than": at 0 any difference subdivides, corners
     *                  that agree exactly never do); with a lens, the estimated standard error of
     *                  its mean at which a pixel stops
     */
    record Adaptive(int depth, double threshold) {
        /** @throws IllegalArgumentException when either is out of range, naming it */
        Adaptive {
            if (depth < 1 || depth > 6) throw new IllegalArgumentException("adaptive depth must be in 1..6, got " + depth);
            Util.requireNonNegative(threshold, "adaptive threshold");
        }
    }

    /**
     * @param samples lens samples per pixel
     * @throws IllegalArgumentException when it is below 1 or above {@link Camera#MAX_SAMPLES_PER_PIXEL}
     */
    static void requireLensSamples(int samples) {
        if (samples < 1 || samples > Camera.MAX_SAMPLES_PER_PIXEL)
            throw new IllegalArgumentException("depth-of-field samples must be from 1 to " + Camera.MAX_SAMPLES_PER_PIXEL
                    + ", got " + samples);
    }

    /**
     * The most camera rays one pixel may take, by the rule of the sampler that spends them: the
     * worst case, which a test holds equal to the rays a worst-case pixel traces.
     *
     * @param depthOfField whether the view has a lens (NONE then takes the lens samples, and
     *                     ADAPTIVE samples each pixel on its own, {@link NoiseAdaptiveSampler})
     * @return camera rays per pixel, as a long (a grid of two ints may overflow an int)
     */
    long maxSamplesPerPixel(boolean depthOfField) {
        return switch (antiAliasing) {
            case NONE -> CenterSampler.samplesPerPixel(depthOfField, lensSamples);
            case RANDOM -> GridSampler.samplesPerPixel(grid.columns, grid.rows);
            case CORNERS -> LatticeSampler.maxSamplesPerPixel(false, 0);
            case ADAPTIVE -> depthOfField ? NoiseAdaptiveSampler.maxSamplesPerPixel(adaptive.depth)
                    : LatticeSampler.maxSamplesPerPixel(true, adaptive.depth);
        };
    }

    /**
     * Holds these settings with the view's lens and the tracer's rays per camera ray to
     * {@link RayBudget#MAX_RAYS_PER_PIXEL}.
     *
     * @throws IllegalArgumentException naming the factors and their product when it is over
     */
    void requireRayBudget(View.Lens lens, RayTracerBase tracer) {
        tracer.requireRayBudget(antiAliasing, maxSamplesPerPixel(!lens.isPinhole()));
    }

    /** @return the side, in pixels, of the render loop's square tiles that suits this sampling */
    int tileSize() {
        return switch (antiAliasing) {
            case NONE, RANDOM -> 16;
            case CORNERS -> LatticeSampler.tileSize(false, 0);
            case ADAPTIVE -> LatticeSampler.tileSize(true, adaptive.depth);
        };
    }

    /**
     * A new sampler, for one worker: its scratch state is its own.
     *
     * @param rays     the view's camera rays
     * @param tracer   what colours each camera ray
     * @param tileSize the render loop's tile side, in pixels (at most {@link #tileSize()} for the
     *                 lattice samplers, whose cache covers one tile)
     */
    PixelSampler newSampler(View.CameraRays rays, RayTracerBase tracer, int tileSize) {
        return switch (antiAliasing) {
            case NONE -> new CenterSampler(this, rays, tracer);
            case RANDOM -> new GridSampler(this, rays, tracer);
            case CORNERS -> new LatticeSampler(this, rays, tracer, tileSize);
            case ADAPTIVE -> rays.hasLens() ? new NoiseAdaptiveSampler(this, rays, tracer)
                    : new LatticeSampler(this, rays, tracer, tileSize);
        };
    }

    /**
     * @param lens the view's lens
     * @return the mode and its parameters in words, then the depth of field's when there is a lens
     */
    String describe(View.Lens lens) {
        String aa = switch (antiAliasing) {
            case NONE -> "NONE";
            case RANDOM -> "RANDOM " + grid.columns + "x" + grid.rows;
            case CORNERS -> "CORNERS";
            case ADAPTIVE -> "ADAPTIVE depth " + adaptive.depth + " threshold " + adaptive.threshold;
        };
        return lens.isPinhole() ? aa : aa + ", DOF focal " + lens.focalDistance() + " aperture " + lens.aperture()
                + (antiAliasing == AntiAliasing.NONE ? " x" + lensSamples : "");
    }
}
