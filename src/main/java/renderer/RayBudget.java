package renderer;

import java.util.Locale;

/**
 * The ray budget of one pixel, defined once for the Java API and the scene files: the most camera
 * rays the sampling may trace for a pixel, times the tracer's rays per camera ray (beam size ×
 * shadow samples), at most {@link #MAX_RAYS_PER_PIXEL}. {@link Camera.Builder#build()} holds a
 * camera to it; {@code scene.io.RenderSettings} holds a scene file to it, with the same words.
 */
public final class RayBudget {
    /**
     * The most rays one pixel may take: 2^24, 16,777,216, so that no setting, alone or multiplied
     * by the others, makes a render that never ends. The defaults use 256; the showcase's adaptive
     * depth 3, 81 × 256 = 20,736.
     */
    public static final long MAX_RAYS_PER_PIXEL = 1L << 24;

    private RayBudget() {
    }

    /**
     * The most camera rays one pixel may take, by the rule of the sampler that spends them (the
     * camera's own figure, {@code Sampling.maxSamplesPerPixel}): RANDOM's grid (columns × rows),
     * ADAPTIVE's whole lattice of (2^depth + 1)² points (the worst case: every square split down
     * to the deepest level; the lattice of pixel x spans points x·2^depth … (x+1)·2^depth on each
     * axis), or with depth of field its 4^depth samples (a pixel whose noise never settles),
     * CORNERS' five points, or without anti-aliasing the lens samples with depth of field and 1
     * without.
     *
     * @param mode          the anti-aliasing mode
     * @param columns       RANDOM: grid columns
     * @param rows          RANDOM: grid rows
     * @param adaptiveDepth ADAPTIVE: the deepest subdivision (negative counts as 0, above 30 as 30)
     * @param depthOfField  whether the camera has a lens (aperture above 0): NONE's lens samples,
     *                      ADAPTIVE's per-pixel sampling
     * @param lensSamples   NONE with depth of field: lens samples per pixel
     * @return camera rays per pixel, as a long (a grid of two ints may overflow an int)
     */
    public static long cameraRaysPerPixel(AntiAliasing mode, int columns, int rows, int adaptiveDepth,
                                          boolean depthOfField, int lensSamples) {
        return switch (mode) {
            case RANDOM -> GridSampler.samplesPerPixel(columns, rows);
            case ADAPTIVE -> {
                int depth = Math.min(Math.max(adaptiveDepth, 0), 30);
                yield depthOfField ? NoiseAdaptiveSampler.maxSamplesPerPixel(depth) : LatticeSampler.maxSamplesPerPixel(true, depth);
            }
            case CORNERS -> LatticeSampler.maxSamplesPerPixel(false, 0);
            case NONE -> CenterSampler.samplesPerPixel(depthOfField, lensSamples);
        };
    }

    /**
     * Checks a pixel's budget.
     *
     * @param mode          the anti-aliasing mode, for the message
     * @param cameraRays    camera rays per pixel ({@link #cameraRaysPerPixel})
     * @param beamSize      rays per glossy or diffuse-glass beam
     * @param shadowSamples shadow rays toward a light with a radius
     * @throws IllegalArgumentException when cameraRays × beamSize × shadowSamples is more than
     *                                  {@link #MAX_RAYS_PER_PIXEL}, naming the factors, the
     *                                  product and the limit
     */
    public static void require(AntiAliasing mode, long cameraRays, int beamSize, int shadowSamples) {
        double rays = (double) cameraRays * beamSize * shadowSamples; // a double: the product may overflow a long
        if (rays > MAX_RAYS_PER_PIXEL)
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "%s sampling with %d samples per pixel × beam size %d × %d shadow samples is %.0f rays per pixel,"
                            + " more than the limit of %d",
                    mode, cameraRays, beamSize, shadowSamples, rays, MAX_RAYS_PER_PIXEL));
    }
}
