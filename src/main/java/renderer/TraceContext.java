package renderer;

import java.util.concurrent.CancellationException;

import geometries.Hit;

/**
 * One worker's scratch state: the random stream of the current sample, reusable hit records (one
 * per recursion level, so that a reflection's query does not overwrite its caller's), the
 * doubles the shading keeps instead of objects, and ray counters. Owned by exactly one thread;
 * never shared.
 */
final class TraceContext {
    final SampleStream random = new SampleStream();
    final Transmittance transmittance;
    final ShadowCache shadowCache = new ShadowCache();
    /** Scratch for one point of a disk (soft-shadow light disks, glossy aim disks). */
    final double[] disk = new double[2];
    /** Scratch for a vector: a cross product. */
    final double[] vector = new double[3];
    /** Scratch for the pinhole direction of the camera ray being made ({@link View.CameraRays}). */
    final double[] cameraDirection = new double[3];
    /** Scratch for a light's direction at a shaded point. */
    final double[] light = new double[3];
    /** Scratch for a light's intensity at a shaded point. */
    final double[] intensity = new double[3];
    /** The colour of the local effects of the point being shaded. */
    final double[] local = new double[3];
    /** The transparency (product of kT) toward the light being shaded. */
    final double[] transparency = new double[3];
    /**
     * Per recursion level: the colour the last calcColor, global-effects, beam or secondary step
     * of that level produced (each is read at once by its caller).
     */
    final double[] red;
    final double[] green;
    final double[] blue;
    /** The colour of the last camera sample (a camera trace), then of the pixel (a sampler). */
    double r;
    double g;
    double b;
    private final Hit[] hits;
    /** The query record of shadow rays: only its ray is used (an any-hit walk records no hit). */
    final Hit shadow = new Hit();
    long cameraRays;
    long shadowRays;
    long secondaryRays;
    /**
     * Whether the tracer stops when the thread is interrupted (a render's worker): a pixel may
     * take up to {@link RayBudget#MAX_RAYS_PER_PIXEL} rays, far longer than a render should go on
     * after an interrupt, so the tracer asks between the rays of a beam or a soft shadow.
     */
    boolean interruptible;

    TraceContext(int levels, double threshold) {
        transmittance = new Transmittance(threshold);
        hits = new Hit[levels + 1];
        for (int i = 0; i < hits.length; ++i) hits[i] = new Hit();
        red = new double[levels + 1];
        green = new double[levels + 1];
        blue = new double[levels + 1];
    }

    /** The hit record for recursion level {@code level}, reset to the bound {@code tMax} (its ray stays). */
    Hit hit(int level, double tMax) {
        return hits[level].reset(tMax);
    }

    /** The record a camera ray is written into: the top level's. */
    Hit cameraRay() {
        return hits[hits.length - 1];
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

    void addTo(RenderStats.Counter counter) {
        counter.add(cameraRays, shadowRays, secondaryRays);
    }
}
