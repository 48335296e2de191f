package renderer;

import java.util.concurrent.CancellationException;

import geometries.Hit;
import primitives.Rgb;

/**
 * One worker's scratch state: the random stream of the current sample, the shader's per-level
 * records ({@link Level}: hit, colours, bounces) and per-light scratch, all allocated once and
 * reused for every ray, and ray counters. Owned by exactly one thread; never shared.
 */
final class TraceContext {
    final SampleStream random = new SampleStream();
    /** The any-hit walk's product of kT along the current shadow ray. */
    final Transmittance transmittance;
    final ShadowCache shadowCache = new ShadowCache();
    /** Scratch for one point of a disk (soft-shadow light disks, glossy aim disks). */
    final double[] disk = new double[2];
    /** Scratch for a vector: a cross product. */
    final double[] vector = new double[3];
    /** Scratch for the pinhole direction of the camera ray being made ({@link View.CameraRays}). */
    final double[] cameraDirection = new double[3];
    /** A light's unit direction toward the shaded point, as {@code LightSource.getL} writes it. */
    final double[] light = new double[3];
    /** A light's intensity at the shaded point, as {@code LightSource.getIntensity} writes it. */
    final double[] lightIntensity = new double[3];
    /** The same intensity, as the shader multiplies it (0..255 scale). */
    final Rgb intensity = new Rgb();
    /** The Phong factor of the light being shaded: kD·|n·l| + kS·max(0, −r·v)^shininess, per channel. */
    final Rgb phong = new Rgb();
    /** The light arriving directly at the point being shaded (emission aside), summed over the lights. */
    final Rgb local = new Rgb();
    /** The mean transparency (product of kT) over a soft shadow's rays toward one light. */
    final Rgb transparency = new Rgb();
    /** Indexed by recursion level: the camera ray's at {@code levels.length - 1}, one less per bounce. */
    private final Level[] levels;
    /** The query record of shadow rays: only its ray is used (an any-hit walk records no hit). */
    final RayHit shadow = new RayHit();
    long cameraRays;
    long shadowRays;
    long secondaryRays;
    /**
     * Whether the tracer stops when the thread is interrupted (a render's worker): a pixel may
     * take up to {@link RayBudget#MAX_RAYS_PER_PIXEL} rays, far longer than a render should go on
     * after an interrupt, so the tracer asks between the rays of a beam or a soft shadow.
     */
    boolean interruptible;
    /**
     * The most rays the current pixel may trace: {@link RayBudget#MAX_RAYS_PER_PIXEL} (a test's
     * tracer may make contexts with less). The up-front budget counts one bounce; this bounds
     * every bounce below it.
     */
    private final long rayLimit;
    /** cameraRays + shadowRays + secondaryRays when the current pixel began. */
    private long pixelStart;
    /** The current pixel, for the message of one that goes over the budget; -1: a direct traceRay call. */
    private int pixelX = -1, pixelY = -1;

    /** A context with the library's limit of rays per pixel: {@link RayBudget#MAX_RAYS_PER_PIXEL}. */
    TraceContext(int levels, double threshold) {
        this(levels, threshold, RayBudget.MAX_RAYS_PER_PIXEL);
    }

    /**
     * @param levels    the tracer's recursion depth: levels below the camera ray's
     * @param threshold the smallest product of kT a shadow ray carries on through
     * @param rayLimit  the most rays a pixel may trace
     */
    TraceContext(int levels, double threshold, long rayLimit) {
        this.rayLimit = rayLimit;
        transmittance = new Transmittance(threshold);
        this.levels = new Level[levels + 1];
        for (int i = 0; i < this.levels.length; ++i) this.levels[i] = new Level(i, i == 0 ? null : this.levels[i - 1]);
    }

    /** The camera ray's level, the highest: the levels below it are reached through {@link Level#below}. */
    Level top() {
        return levels[levels.length - 1];
    }

    /** The record a camera ray is written into: the top level's. */
    RayHit cameraRay() {
        return top().hit;
    }

    /** Where the colour seen along the camera ray is left: the top level's colour. */
    Rgb cameraColour() {
        return top().colour;
    }

    /**
     * Stops the pixel when this context belongs to a render and its thread was interrupted (the
     * flag stays set for the render loop to see): a field read, no allocation while it goes on.
     *
     * @throws CancellationException when it stops
     */
    void stopIfInterrupted() {
        if (interruptible && Thread.currentThread().isInterrupted())
            throw new CancellationException("render was interrupted");
    }

    /** Starts counting the rays of pixel (x, y) against {@link #rayLimit}: (-1, -1) for a direct call. */
    void beginPixel(int x, int y) {
        pixelStart = cameraRays + shadowRays + secondaryRays;
        pixelX = x;
        pixelY = y;
    }

    /**
     * Holds the current pixel to {@link #rayLimit}, before {@code more} rays not yet counted are
     * traced: asked where rays multiply (each camera sample, each secondary ray, each shadow ray),
     * so a pixel never traces more than the limit. Two additions and a comparison: no allocation.
     *
     * @param more the rays about to be traced and not yet counted (0: the camera ray, counted by
     *             the sampler before it is traced)
     * @throws IllegalStateException naming the pixel, the limit and what multiplies the rays
     */
    void requireWithinBudget(int more) {
        if (cameraRays + shadowRays + secondaryRays - pixelStart + more > rayLimit) throw overBudget();
    }

    private IllegalStateException overBudget() {
        String where = pixelX < 0 ? "a traceRay call" : "pixel (" + pixelX + ", " + pixelY + ")";
        return new IllegalStateException(where + " needs more than " + rayLimit + " rays"
                + (rayLimit == RayBudget.MAX_RAYS_PER_PIXEL ? " (RayBudget.MAX_RAYS_PER_PIXEL)" : "")
                + ": each reflection and refraction below the first bounce shades again, with its own shadow rays,"
                + " beyond the budget checked up front (samples per pixel × (1 + 2 beams) × (1 + shadow samples × soft"
                + " lights + other lights)); lower the samples per pixel, the beam size, the shadow samples or the soft"
                + " lights, or let fewer materials both reflect and transmit");
    }

    void addTo(RenderStats.Counter counter) {
        counter.add(cameraRays, shadowRays, secondaryRays);
    }

    /**
     * One recursion level of the shader: the hit being shaded there and what the shader keeps at
     * that level while the levels below it are traced (a reflection's hit is shaded one level
     * down, so it never overwrites these). Colours are on the 0..255 scale.
     */
    static final class Level {
        /** The recursion level: the camera ray's is the highest; level 1 traces no bounce. */
        final int level;
        /** The level one bounce down, or null for level 0. */
        final Level below;
        final RayHit hit = new RayHit();
        /** The product of kR and kT of the bounces from the camera down to this level's hit, per channel. */
        final Rgb weight = new Rgb();
        /** The colour seen along this level's ray: emission, local and indirect light, or the background. */
        final Rgb colour = new Rgb();
        /** The light reflected and transmitted at the hit: the sum of the two bounces'. */
        final Rgb indirect = new Rgb();
        /** The light one bounce brings back, times its k: one ray's, or a beam's running sum, then mean. */
        final Rgb beam = new Rgb();
        final Bounce reflection = new Bounce();
        final Bounce transmission = new Bounce();

        Level(int level, Level below) {
            this.level = level;
            this.below = below;
        }

        /**
         * This level's record, reset, holding the secondary ray {@code new Ray(p, d, n)} from the
         * hit point p (normal n) of {@code from}: d normalized, the head moved off the surface.
         */
        Hit secondaryRay(Hit from, double dx, double dy, double dz) {
            hit.reset(Double.POSITIVE_INFINITY);
            return hit.secondary(from.pointX(), from.pointY(), from.pointZ(), dx, dy, dz,
                    from.normalX(), from.normalY(), from.normalZ());
        }
    }

    /**
     * A reflection or a transmission at a hit: its coefficient k (kR or kT, after the Fresnel
     * split of a refracting material), the direction it leaves in (not unit length: the mirror
     * image or refraction of a unit vector) and the radius of its aim disk at unit distance (0 for
     * one ray).
     */
    static final class Bounce {
        final Rgb k = new Rgb();
        double dirX;
        double dirY;
        double dirZ;
        double spread;

        void aim(double x, double y, double z, double spread) {
            this.dirX = x;
            this.dirY = y;
            this.dirZ = z;
            this.spread = spread;
        }
    }
}
