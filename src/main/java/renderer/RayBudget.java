package renderer;

import java.util.Collection;
import java.util.Locale;

import lighting.LightSource;

/**
 * The ray budget of one pixel, defined once for the Java API and the scene files: the most camera
 * rays the sampling may trace for a pixel, times the tracer's rays per camera ray (its beams, its
 * shadow samples and the scene's lights: {@link #require}), at most {@link #MAX_RAYS_PER_PIXEL};
 * a render also counts the rays each pixel traces and fails a pixel that goes over. {@link Camera.Builder#build()} holds a
 * camera to it; {@code scene.io.RenderSettings} holds a scene file to it, with the same rule and words.
 *
 * <p>Internal: public only for the scene reader and the command line, which check a setting
 * before any camera exists; a scene test meets the budget through {@code build()}.
 *
 * @hidden
 */
public final class RayBudget {
    /**
     * The most rays one pixel may take: 2^24, 16,777,216, so that no setting, alone or multiplied
     * by the others, makes a render that never ends. The defaults use 33 × (1 + the lights' shadow
     * rays); the showcase (adaptive depth 3, three lights without a radius) 81 × 33 × 4 = 10,692.
     */
    public static final long MAX_RAYS_PER_PIXEL = 1L << 24;

    private RayBudget() {
    }

    /**
     * The budget of a render's settings, the rule and message of {@code Camera.Builder.build()}:
     * {@code cameraRays} per pixel times the Whitted tracer's rays per camera ray over
     * {@code lights}, counted as soft (a radius) and other. Public for the settings of a scene
     * file or a command line, before any camera or tracer exists; the beam size and shadow
     * samples are checked first, by the tracer's own rules.
     *
     * @param mode          the anti-aliasing mode, for the message
     * @param cameraRays    the sampling's most camera rays per pixel ({@code Sampling.maxSamplesPerPixel})
     * @param beamSize      rays per glossy or diffuse-glass beam, ≥ 1
     * @param shadowSamples shadow rays toward a light with a radius, ≥ 1
     * @param lights        the scene's lights (read once, a copy)
     * @throws IllegalArgumentException for a beam size or shadow samples below 1, or more than
     *                                  {@link #MAX_RAYS_PER_PIXEL} rays per pixel, naming the
     *                                  factors, the product and the limit
     */
    public static void require(AntiAliasing mode, long cameraRays, int beamSize, int shadowSamples,
                               Collection<? extends LightSource> lights) {
        WhittedShader.requireBeamSize(beamSize);
        WhittedShader.requireShadowSamples(shadowSamples);
        int soft = 0, other = 0;
        for (LightSource light : lights.toArray(new LightSource[0])) { // a copy: read once, whatever its kind
            if (light.getRadius() > 0) ++soft;
            else ++other;
        }
        require(mode, cameraRays, beamSize, shadowSamples, soft, other);
    }

    /**
     * Checks a pixel's budget up front: what one camera sample traces down to its first bounce,
     * times the camera samples. A camera sample shades its hit and, at a material that reflects
     * and transmits with a spread, the hits of a reflection beam and a transmission beam of
     * {@code beamSize} rays each: {@code 1 + 2·beamSize} shaded points. Each shaded point was
     * found by one ray and traces {@code shadowSamples} shadow rays to each light with a radius
     * (a soft light) and one to each other light: {@code 1 + shadowSamples·softLights +
     * otherLights} rays. So a pixel takes
     * <pre>cameraRays × (1 + 2·beamSize) × (1 + shadowSamples·softLights + otherLights)</pre>
     * rays when no path bounces twice. Deeper bounces shade again (up to the tracer's recursion
     * depth), which no up-front figure can bound without refusing ordinary scenes; the render
     * counts those rays as it traces them and stops a pixel that goes over the limit
     * ({@code TraceContext.requireWithinBudget}), so no pixel ever traces more.
     *
     * @param mode          the anti-aliasing mode, for the message
     * @param cameraRays    camera rays per pixel ({@code Sampling.maxSamplesPerPixel})
     * @param beamSize      rays per glossy or diffuse-glass beam
     * @param shadowSamples shadow rays toward a light with a radius
     * @param softLights    lights with a radius in the scene
     * @param otherLights   lights without a radius (one shadow ray each)
     * @throws IllegalArgumentException when the product is more than {@link #MAX_RAYS_PER_PIXEL},
     *                                  naming every factor, the product and the limit
     */
    public static void require(AntiAliasing mode, long cameraRays, int beamSize, int shadowSamples, int softLights,
                               int otherLights) {
        // Doubles: the products may overflow a long; exact while they stay below 2^53.
        double shaded = 1 + 2.0 * beamSize;
        double perPoint = 1 + (double) shadowSamples * softLights + otherLights;
        double rays = cameraRays * shaded * perPoint;
        if (rays > MAX_RAYS_PER_PIXEL)
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "%s sampling with %d samples per pixel × (1 + 2 beams of %d rays: reflection and transmission)"
                            + " × (1 + %d shadow samples × %d soft %s + %d other %s) is %.0f rays per pixel,"
                            + " more than the limit of %d",
                    mode, cameraRays, beamSize, shadowSamples, softLights, softLights == 1 ? "light" : "lights",
                    otherLights, otherLights == 1 ? "light" : "lights", rays, MAX_RAYS_PER_PIXEL));
    }

    /**
     * Checks a tracer that traces one ray per camera sample (a tracer other than the library's
     * Whitted tracer: the budget cannot see into it).
     *
     * @throws IllegalArgumentException when {@code cameraRays} is more than {@link #MAX_RAYS_PER_PIXEL}
     */
    static void requireCameraRays(AntiAliasing mode, long cameraRays) {
        if (cameraRays > MAX_RAYS_PER_PIXEL)
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "%s sampling with %d samples per pixel is %d rays per pixel, more than the limit of %d",
                    mode, cameraRays, cameraRays, MAX_RAYS_PER_PIXEL));
    }
}
