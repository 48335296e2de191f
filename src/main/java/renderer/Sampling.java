package renderer;

import java.util.Objects;

import primitives.Checks;

/**
 * Internal: how a render samples its pixels. Public only so that the scene reader and the
 * command line check a sampling setting by this rule before any camera exists; a scene test
 * sets these through {@link Camera.Builder}.
 *
 * <p>The anti-aliasing mode with the parameters of each mode (a builder keeps all of them, so that
 * switching modes keeps what was set), the lens samples of depth of field without anti-aliasing,
 * and the seed every random number derives from. A value, checked when it is made; its
 * {@link #plan(boolean)} is what its mode needs for a render (the samplers, the camera rays a
 * pixel may take, the tile size). The limits and
 * defaults of sampling are defined here; {@link Camera} names them for the course.
 *
 * @param antiAliasing the mode
 * @param grid         RANDOM's grid of jittered samples
 * @param adaptive     ADAPTIVE's depth and threshold
 * @param lensSamples  rays per pixel with depth of field and no anti-aliasing, 1 to
 *                     {@link #MAX_SAMPLES_PER_PIXEL}
 * @param seed         the render's seed: the same seed gives the same image on any number of threads
 * @hidden
 */
public record Sampling(AntiAliasing antiAliasing, Grid grid, Adaptive adaptive, int lensSamples, long seed) {
    /**
     * The most primary samples of one pixel from the RANDOM grid (columns × rows) or the depth of
     * field's lens samples: 65,536 (a 256×256 grid), so that the count fits an int and a pixel
     * ends (ADAPTIVE's depth 6 stays below it, at most 65² lattice points).
     */
    public static final int MAX_SAMPLES_PER_PIXEL = 1 << 16;
    /** ADAPTIVE's deepest subdivision when none is set: sub-pixels down to 1/8 of the side. */
    public static final int DEFAULT_ADAPTIVE_DEPTH = 3;
    /** ADAPTIVE's pixel-level corner spread that subdivides when none is set, 0..255 scale. */
    public static final double DEFAULT_ADAPTIVE_THRESHOLD = 8;
    /** RANDOM's grid side when none is set: a 4×4 grid. */
    static final int DEFAULT_GRID_SIDE = 4;
    /** Lens samples per pixel when none are set: as many as the default grid. */
    static final int DEFAULT_LENS_SAMPLES = 16;

    /** The defaults: no anti-aliasing, a 4×4 grid, adaptive depth 3 and threshold 8, 16 lens samples, seed 0. */
    public static final Sampling DEFAULT = new Sampling(AntiAliasing.NONE, new Grid(DEFAULT_GRID_SIDE, DEFAULT_GRID_SIDE),
            new Adaptive(DEFAULT_ADAPTIVE_DEPTH, DEFAULT_ADAPTIVE_THRESHOLD), DEFAULT_LENS_SAMPLES, 0);

    /**
     * @param antiAliasing the mode
     * @param grid         RANDOM's grid
     * @param adaptive     ADAPTIVE's settings
     * @param lensSamples  lens samples per pixel
     * @param seed         the render's seed
     * @throws NullPointerException     naming a missing part
     * @throws IllegalArgumentException for lens samples out of range, naming them
     */
    public Sampling {
        Objects.requireNonNull(antiAliasing, "anti-aliasing mode");
        Objects.requireNonNull(grid, "anti-aliasing grid");
        Objects.requireNonNull(adaptive, "adaptive settings");
        requireLensSamples(lensSamples);
    }

    /**
     * @param mode how pixels are sampled
     * @return this sampling with that mode (each mode's parameters kept)
     * @throws NullPointerException when it is null
     */
    public Sampling withAntiAliasing(AntiAliasing mode) {
        return new Sampling(mode, grid, adaptive, lensSamples, seed);
    }

    /**
     * @param columns RANDOM: cells across a pixel
     * @param rows    RANDOM: cells down a pixel
     * @return this sampling with that grid
     * @throws IllegalArgumentException as {@link Grid#Grid(int, int)}
     */
    public Sampling withGrid(int columns, int rows) {
        return new Sampling(antiAliasing, new Grid(columns, rows), adaptive, lensSamples, seed);
    }

    /**
     * The rule of the course's {@code setAntiAliasing(mode, columns, rows)}: RANDOM with that grid,
     * the mode checked first.
     *
     * @throws IllegalArgumentException for a mode other than RANDOM (naming the grid, and for
     *                                  ADAPTIVE its own setter), then as {@link Grid#Grid(int, int)}
     */
    Sampling withRandomGrid(AntiAliasing mode, int columns, int rows) {
        if (mode != AntiAliasing.RANDOM)
            throw new IllegalArgumentException("a " + columns + "x" + rows + " grid applies to RANDOM anti-aliasing only, got "
                    + mode + (mode == AntiAliasing.ADAPTIVE ? " (use setAdaptive(depth, threshold))" : ""));
        return withGrid(columns, rows).withAntiAliasing(mode);
    }

    /**
     * @param depth     ADAPTIVE: the deepest subdivision
     * @param threshold ADAPTIVE: the corner spread that subdivides
     * @return this sampling with those settings
     * @throws IllegalArgumentException as {@link Adaptive#Adaptive(int, double)}
     */
    public Sampling withAdaptive(int depth, double threshold) {
        return new Sampling(antiAliasing, grid, new Adaptive(depth, threshold), lensSamples, seed);
    }

    /**
     * @param samples lens samples per pixel
     * @return this sampling with that many
     * @throws IllegalArgumentException as {@link #requireLensSamples(int)}
     */
    public Sampling withLensSamples(int samples) {
        return new Sampling(antiAliasing, grid, adaptive, samples, seed);
    }

    /**
     * @param seed the render's seed
     * @return this sampling with that seed
     */
    public Sampling withSeed(long seed) {
        return new Sampling(antiAliasing, grid, adaptive, lensSamples, seed);
    }

    /**
     * RANDOM's grid: columns × rows cells per pixel, one jittered sample in each.
     *
     * @param columns cells across a pixel, ≥ 1
     * @param rows    cells down a pixel, ≥ 1
     *
     * @hidden internal: part of the sampling value
     */
    public record Grid(int columns, int rows) {
        /**
         * @param columns cells across a pixel
         * @param rows    cells down a pixel
         * @throws IllegalArgumentException for a grid below 1×1 or of more than
         *                                  {@link #MAX_SAMPLES_PER_PIXEL} cells, naming it
         */
        public Grid {
            if (columns < 1 || rows < 1)
                throw new IllegalArgumentException("anti-aliasing grid must be at least 1x1, got " + columns + "x" + rows);
            if (GridSampler.samplesPerPixel(columns, rows) > MAX_SAMPLES_PER_PIXEL)
                throw new IllegalArgumentException("anti-aliasing grid " + columns + "x" + rows + " has "
                        + GridSampler.samplesPerPixel(columns, rows) + " samples per pixel, more than the limit of "
                        + MAX_SAMPLES_PER_PIXEL);
        }
    }

    /**
     * ADAPTIVE's settings, as {@link AntiAliasing#ADAPTIVE} uses them.
     *
     * @param depth     the deepest subdivision, 1..6
     * @param threshold the pixel-level corner spread that subdivides (with a lens, the standard
     *                  error at which a pixel stops), 0..255 scale, finite and ≥ 0
     *
     * @hidden internal: part of the sampling value
     */
    public record Adaptive(int depth, double threshold) {
        /**
         * @param depth     the deepest subdivision
         * @param threshold the corner spread that subdivides
         * @throws IllegalArgumentException when either is out of range, naming it
         */
        public Adaptive {
            requireDepth(depth);
            Checks.requireNonNegative(threshold, "adaptive threshold");
        }

        /**
         * @param depth ADAPTIVE's deepest subdivision
         * @return {@code depth}
         * @throws IllegalArgumentException when it is outside 1..6, naming it
         */
        public static int requireDepth(int depth) {
            if (depth < 1 || depth > 6) throw new IllegalArgumentException("adaptive depth must be in 1..6, got " + depth);
            return depth;
        }
    }

    /**
     * @param samples lens samples per pixel
     * @return {@code samples}
     * @throws IllegalArgumentException when it is below 1 or above {@link #MAX_SAMPLES_PER_PIXEL}
     */
    public static int requireLensSamples(int samples) {
        if (samples < 1 || samples > MAX_SAMPLES_PER_PIXEL)
            throw new IllegalArgumentException("depth-of-field samples must be from 1 to " + MAX_SAMPLES_PER_PIXEL
                    + ", got " + samples);
        return samples;
    }

    /**
     * What this sampling's mode needs for a render, decided here and nowhere else: each mode's
     * sampler with only the values it reads. ADAPTIVE samples each pixel on its own under a lens
     * ({@link NoiseAdaptiveSampler}): the lattice's shared corners are each one random lens point.
     *
     * @param lens whether the view has a lens (an aperture above 0)
     * @return the plan of the mode
     */
    SamplerPlan plan(boolean lens) {
        return switch (antiAliasing) {
            case NONE -> CenterSampler.Plan.of(seed, lens, lensSamples);
            case RANDOM -> new GridSampler.Plan(seed, lens, grid.columns, grid.rows);
            case CORNERS -> LatticeSampler.Plan.corners(seed, lens);
            case ADAPTIVE -> lens ? new NoiseAdaptiveSampler.Plan(seed, adaptive.depth, adaptive.threshold)
                    : LatticeSampler.Plan.adaptive(seed, adaptive.depth, adaptive.threshold);
        };
    }

    /**
     * The most camera rays one pixel may take, by the rule of the sampler that spends them: the
     * worst case, which a test holds equal to the rays a worst-case pixel traces.
     *
     * @param depthOfField whether the view has a lens
     * @return camera rays per pixel, as a long (a grid of two ints may overflow an int)
     */
    public long maxSamplesPerPixel(boolean depthOfField) {
        return plan(depthOfField).maxSamplesPerPixel();
    }

    /**
     * @param lens the view's lens
     * @return the mode and its parameters in words, then the depth of field's when there is a lens
     */
    String describe(View.Lens lens) {
        SamplerPlan plan = plan(!lens.isPinhole());
        return lens.isPinhole() ? plan.describe() : plan.describe() + ", DOF focal " + lens.focalDistance() + " aperture "
                + lens.aperture() + plan.lensSamples();
    }
}
