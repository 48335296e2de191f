package renderer;

import java.util.Locale;

/**
 * What a render did: its wall time and the rays it traced by kind. Returned by
 * {@link Camera#render()} and printed as the render's one-line summary.
 *
 * @param seconds       wall-clock time of the render loop: tracing every pixel (without the
 *                      preparation and without writing the PNG)
 * @param pixels        pixels rendered
 * @param cameraRays    rays from the camera (one per pixel sample)
 * @param shadowRays    rays from a hit point toward a light
 * @param secondaryRays reflected and refracted rays
 * @param threads       worker threads used (0: the calling thread)
 * @param prepareSeconds wall-clock time spent preparing the scene before the loop (building the BVH)
 */
public record RenderStats(double seconds, long pixels, long cameraRays, long shadowRays, long secondaryRays,
                          int threads, double prepareSeconds) {

    /** @return camera, shadow and secondary rays together: what the Mrays/s rate counts */
    public long totalRays() {
        return cameraRays + shadowRays + secondaryRays;
    }

    /** @return millions of rays of every kind per second of wall time */
    public double mraysPerSecond() {
        return seconds > 0 ? totalRays() / seconds / 1e6 : 0;
    }

    /** @return camera rays per pixel (the anti-aliasing and depth-of-field sample count) */
    public double samplesPerPixel() {
        return pixels > 0 ? (double) cameraRays / pixels : 0;
    }

    /**
     * The figures of a render (not the record's usual {@code RenderStats[seconds=…]} form):
     * {@code 0.122 s, 250000 px, rays: camera 296535, shadow 194284, secondary 192235, 1.19 camera
     * rays per px, 5.89 Mrays/s (all rays), 2 threads, prepared in 0.000 s}. The summary line
     * {@link Camera#render()} prints has the same figures, the time first after the image's name.
     *
     * @return the figures in words, in {@link Locale#ROOT} number format
     */
    @Override
    public String toString() {
        return time() + ", " + figures();
    }

    /** The wall time, as the summary line starts with it: {@code 0.122 s}. */
    String time() {
        return String.format(Locale.ROOT, "%.3f s", seconds);
    }

    /** Every figure but the time, as the summary line ends with them. */
    String figures() {
        return String.format(Locale.ROOT,
                "%d px, rays: camera %d, shadow %d, secondary %d, %.2f camera rays per px, %.2f Mrays/s (all rays), %s, prepared in %.3f s",
                pixels, cameraRays, shadowRays, secondaryRays, samplesPerPixel(), mraysPerSecond(),
                threads == 0 ? "calling thread" : threads == 1 ? "1 thread" : threads + " threads", prepareSeconds);
    }

    /** Thread-safe accumulation of the workers' counters. */
    static final class Counter {
        private long camera;
        private long shadow;
        private long secondary;

        synchronized void add(long cameraRays, long shadowRays, long secondaryRays) {
            camera += cameraRays;
            shadow += shadowRays;
            secondary += secondaryRays;
        }

        synchronized RenderStats stats(double seconds, long pixels, int threads, double prepareSeconds) {
            return new RenderStats(seconds, pixels, camera, shadow, secondary, threads, prepareSeconds);
        }
    }
}
