package bench;

import renderer.RenderStats;

/**
 * What the harness measured for one configuration.
 *
 * @param config        what was rendered
 * @param runs          timed runs made (fewer than asked when the time budget ran out)
 * @param median        the median render time of the timed runs, seconds (RenderStats.seconds():
 *                      the render loop, without the BVH build, JVM start or PNG writing)
 * @param min           the fastest timed run, seconds
 * @param stats         the last timed run's counters (the ray counts are the same in every run:
 *                      renders are deterministic)
 * @param buildSeconds  the median preparation time of the timed runs (RenderStats.prepareSeconds():
 *                      the BVH build; about 0 without the BVH)
 * @param peakHeapBytes the heap's peak over the timed runs ({@link HeapMeter})
 * @param allocPerRay   bytes allocated per traced ray (of every kind) by a small render of the same
 *                      configuration on the calling thread, BVH build excluded; NaN when unknown
 */
record Measurement(Configuration config, int runs, double median, double min, RenderStats stats,
                   double buildSeconds, long peakHeapBytes, double allocPerRay) {

    double mraysPerSecond() {
        return stats.totalRays() / median / 1e6;
    }

    double cameraMraysPerSecond() {
        return stats.cameraRays() / median / 1e6;
    }

    /** Render time (build excluded) per camera ray, each with its shadow and secondary rays, in ns. */
    double nsPerCameraRay() {
        return median / stats.cameraRays() * 1e9;
    }
}
