package app.spark;

import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * Ends a job that a lost cluster would leave waiting without end. Spark waits for executors as
 * long as it takes: with every worker gone, a job neither fails nor progresses, and the driver
 * says nothing. The watch looks at the cluster's executors now and then ({@link #check()}); when
 * none has been there for the timeout, it cancels the job with a reason the driver prints in one
 * line (exit 1). It says when it starts waiting, and when executors join (the first) or are back.
 */
final class ExecutorWatch {
    /** The cluster as the watch sees it: a seam for the tests' fake clusters. */
    interface Cluster {
        /** @return the executors registered now (the driver not counted) */
        int executors();

        /**
         * Cancels the job.
         *
         * @param reason why, one line
         */
        void cancel(String reason);
    }

    private final Cluster cluster;
    private final long timeoutNanos;
    private final LongSupplier clock;
    private final Consumer<String> say;
    /** When the cluster was last seen without an executor; -1 while it has some. */
    private long noneSince = -1;
    /** Whether the watch has seen an executor: the first ones to come are not "back". */
    private boolean seen;
    private volatile String reason;

    /**
     * @param cluster        what is watched
     * @param timeoutSeconds how long the job may go without any executor, &gt; 0
     * @param clock          nanoseconds, as {@link System#nanoTime()}
     * @param say            where the lines about waiting go (the progress)
     */
    ExecutorWatch(Cluster cluster, double timeoutSeconds, LongSupplier clock, Consumer<String> say) {
        this.cluster = cluster;
        this.timeoutNanos = (long) (timeoutSeconds * 1e9);
        this.clock = clock;
        this.say = say;
    }

    /**
     * Looks once: notes when the executors went, and cancels the job when they have been gone for
     * the timeout.
     *
     * @return whether the job was cancelled (now or before)
     */
    synchronized boolean check() {
        if (reason != null) return true;
        long now = clock.getAsLong();
        if (cluster.executors() > 0) {
            if (noneSince >= 0) say.accept(seen ? "executors are back; the job goes on" : "executors joined; the job goes on");
            noneSince = -1;
            seen = true;
            return false;
        }
        if (noneSince < 0) {
            noneSince = now;
            say.accept("waiting for executors: none is available (the job ends if none comes within " + seconds() + ")");
            return false;
        }
        if (now - noneSince < timeoutNanos) return false;
        // What was measured, in its own words: a cluster that had executors and lost them is not
        // one whose first executors have not joined yet (none free, or slower to start than the limit).
        reason = seen ? "every executor was lost and none came back for " + seconds() + ": the cluster lost its workers"
                + " (the limit is spark.raytracer.executorTimeout)"
                : "no executor joined in the " + seconds() + " since the job asked for them: the cluster has no worker free for"
                        + " this job, or its executors take longer to start (raise spark.raytracer.executorTimeout)";
        cluster.cancel(reason);
        return true;
    }

    /** The timeout in words: whole seconds as {@code 120 s}, shorter or finer ones to the millisecond ({@code 0.001 s}). */
    private String seconds() {
        double s = timeoutNanos / 1e9;
        return (s == Math.rint(s) ? String.format(Locale.ROOT, "%.0f", s)
                : String.format(Locale.ROOT, "%.3f", s).replaceAll("0+$", "")) + " s";
    }

    /** @return why the watch cancelled the job, or null when it did not */
    String reason() {
        return reason;
    }
}
