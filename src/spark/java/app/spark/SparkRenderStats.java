package app.spark;

import java.util.Locale;

/**
 * What a Spark render job did, printed as its summary line.
 *
 * @param seconds        wall time on the driver from the job's start to the last tile's return
 *                       (broadcast, scheduling and rendering; without assembling and writing)
 * @param frames         images rendered
 * @param pixels         pixels of all images
 * @param tiles          tiles rendered
 * @param rays           rays traced on the executors, of every kind
 * @param broadcastBytes bytes of scene and mesh files broadcast
 * @param executors      executors that ran a task attempt
 * @param tasks          task attempts, retries included
 * @param retries        attempts that repeated a failed (or slow) task
 * @param tileSeconds    each tile's render time on its executor, in ascending order
 */
public record SparkRenderStats(double seconds, int frames, long pixels, int tiles, long rays, long broadcastBytes,
                               int executors, int tasks, int retries, double[] tileSeconds) {
    /**
     * Keeps its own copy of the tile times.
     *
     * @param seconds        the job's wall time on the driver
     * @param frames         images rendered
     * @param pixels         pixels of all images
     * @param tiles          tiles rendered
     * @param rays           rays traced
     * @param broadcastBytes bytes of files broadcast
     * @param executors      executors that ran an attempt
     * @param tasks          task attempts
     * @param retries        repeated attempts
     * @param tileSeconds    each tile's render time, ascending
     */
    public SparkRenderStats {
        tileSeconds = tileSeconds.clone();
    }

    /** @return a copy of the tile times, in ascending order */
    @Override
    public double[] tileSeconds() {
        return tileSeconds.clone();
    }

    /**
     * @param q a quantile in [0, 1]
     * @return the tile time at quantile {@code q} (nearest rank), 0 without tiles
     */
    public double tileQuantile(double q) {
        if (tileSeconds.length == 0) return 0;
        int i = (int) Math.ceil(q * tileSeconds.length) - 1;
        return tileSeconds[Math.max(0, Math.min(tileSeconds.length - 1, i))];
    }

    /** @return the tiles' render times added up: the work, in seconds of one executor core */
    public double tileSum() {
        double sum = 0;
        for (double t : tileSeconds) sum += t;
        return sum;
    }

    /** @return the figures: {@code 25.400 s, 360000 px, 100 tiles (…), 3.10 Mrays/s, 1 executor, 100 tasks, 0 retries} */
    @Override
    public String toString() {
        return summary(null);
    }

    /**
     * The figures with {@code frame} after the time, as the camera's summary line has them
     * ({@code render NAME: TIME, WxH [settings] …}).
     *
     * @param frame the one frame's size and settings in words; null for a job of several frames
     * @return the time, the frame, then the other figures
     */
    String summary(String frame) {
        return String.format(Locale.ROOT,
                "%.3f s%s, %d px, %d tiles (tile time median %.3f s, p90 %.3f s, max %.3f s, sum %.3f s), %.2f Mrays/s,"
                        + " %d executor%s, %d task%s, %d retr%s",
                seconds, frame == null ? "" : ", " + frame, pixels, tiles, tileQuantile(0.5), tileQuantile(0.9),
                tileQuantile(1), tileSum(), seconds > 0 ? rays / seconds / 1e6 : 0,
                executors, executors == 1 ? "" : "s", tasks, tasks == 1 ? "" : "s", retries, retries == 1 ? "y" : "ies");
    }
}
