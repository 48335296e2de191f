package renderer;

import geometries.Hit;

/**
 * One worker's scratch state: the random stream of the current sample, reusable hit records (one
 * per recursion level, so that a reflection's query does not overwrite its caller's) and ray
 * counters. Owned by exactly one thread; never shared.
 */
final class TraceContext {
    final SampleStream random = new SampleStream();
    final Transmittance transmittance;
    /** Scratch for one point of a disk (soft-shadow light disks, glossy aim disks). */
    final double[] disk = new double[2];
    private final Hit[] hits;
    /** The query record of shadow rays: only its ray is used (an any-hit walk records no hit). */
    final Hit shadow = new Hit();
    long cameraRays;
    long shadowRays;
    long secondaryRays;

    TraceContext(int levels, double threshold) {
        transmittance = new Transmittance(threshold);
        hits = new Hit[levels + 1];
        for (int i = 0; i < hits.length; ++i) hits[i] = new Hit();
    }

    /** The hit record for recursion level {@code level}, reset to the bound {@code tMax}. */
    Hit hit(int level, double tMax) {
        return hits[level].reset(tMax);
    }

    void addTo(RenderStats.Counter counter) {
        counter.add(cameraRays, shadowRays, secondaryRays);
    }
}
