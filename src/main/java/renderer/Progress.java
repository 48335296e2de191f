package renderer;

import java.io.PrintStream;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Progress lines of one render: a full line (no carriage-return tricks, so IDE consoles show it)
 * each time another {@code step} percent of the work is done, with elapsed time and an ETA:
 * {@code LABEL:  45.0%  450/1000 px  elapsed 3.1 s  ETA 3.8 s}. The render loop counts pixels;
 * a distributed render counts its tiles ({@code tiles}) in the same format. Shared by the
 * workers of that render only; lock-free except when a line is due.
 *
 * @hidden internal: public only for the command line's progress bar
 */
public final class Progress {
    private final String label;
    private final long total;
    /** What is counted, in the lines: "px" for pixels. */
    private final String unit;
    private final double step;
    private final PrintStream out;
    private final long start = System.nanoTime();
    private final AtomicLong done = new AtomicLong();
    /** Index of the next step to report; updated under the lock by the worker that prints. */
    private final AtomicInteger nextStep = new AtomicInteger(1);
    /**
     * Where the trusted pace starts ({@link #remainingSecondsAfter}): {nanoTime, units done},
     * set once by the first caller after the warm-up; null before.
     */
    private final AtomicReference<long[]> paceFrom = new AtomicReference<>();

    /** @param step percent between lines; 0 reports nothing */
    Progress(String label, long total, double step, PrintStream out) {
        this(label, total, "px", step, out);
    }

    /**
     * Starts the clock.
     *
     * @param label what is done, at the start of each line ("render showcase")
     * @param total how many units make 100 %, at least 1
     * @param unit  the unit's short name in the lines ("px", "tiles")
     * @param step  percent between lines, in [0, 100]; 0 reports nothing
     * @param out   where the lines go
     * @throws IllegalArgumentException for a total below 1 or a step outside [0, 100]
     */
    public Progress(String label, long total, String unit, double step, PrintStream out) {
        if (total < 1) throw new IllegalArgumentException("progress total must be at least 1, got " + total);
        requireStep(step);
        this.label = Objects.requireNonNull(label, "label");
        this.total = total;
        this.unit = Objects.requireNonNull(unit, "unit");
        this.step = step;
        this.out = Objects.requireNonNull(out, "out");
    }

    /**
     * @param step percent between progress lines
     * @return {@code step}
     * @throws IllegalArgumentException when it is outside [0, 100] (or NaN), naming it
     */
    static double requireStep(double step) {
        if (!(step >= 0 && step <= 100))
            throw new IllegalArgumentException("progress step must be in [0, 100] percent, got " + step);
        return step;
    }

    /**
     * Counts {@code units} more as done (from any thread) and prints a line when another step is
     * complete.
     *
     * @param units how many more units are done
     */
    public void advance(long units) {
        long now = done.addAndGet(units);
        if (step <= 0) return;
        double percent = 100.0 * now / total;
        if (percent < Math.min(100, nextStep.get() * step)) return; // most calls: no line is due
        // One line per call however many steps it crosses, claimed and printed under one lock so
        // that lines come out in order (a worker that claimed step k cannot print after k + 1).
        synchronized (this) {
            int k = nextStep.get();
            if (percent < Math.min(100, k * step)) return;
            // The next line is due at the first step beyond what is done now.
            nextStep.set(percent >= 100 ? Integer.MAX_VALUE : (int) Math.floor(percent / step) + 1);
            double elapsed = (System.nanoTime() - start) / 1e9;
            double eta = now == 0 ? 0 : elapsed * (total - now) / now;
            out.println(String.format(Locale.ROOT, "%s: %5.1f%%  %d/%d %s  elapsed %.1f s  ETA %.1f s",
                    label, percent, now, total, unit, elapsed, eta));
        }
    }

    /**
     * The seconds the work still needs at its pace after a warm-up: the first call from
     * {@code warmUpSeconds} into the work marks where the pace starts, and the pace is measured
     * from there once {@code warmUpSeconds} more have passed. The pace so far would count the first
     * tiles, which run while the code is still being compiled: on a 6 s render of a 10⁵-triangle
     * mesh (2 threads, a slow 2-core host) it promised 8.9 s more at its first second, when 3.1 s
     * were left (BENCHMARKS.md, issue 50, the closing session).
     *
     * @param warmUpSeconds seconds not trusted at the start, and then the shortest span of pace
     *                      trusted; at least 0
     * @return the seconds left at the pace since the mark; NaN while that pace is not known yet
     *         (before the mark and for {@code warmUpSeconds} after it, or nothing done since)
     */
    double remainingSecondsAfter(double warmUpSeconds) {
        long nanos = System.nanoTime(), now = done.get();
        long[] from = paceFrom.get();
        if (from == null) {
            if (nanos - start >= warmUpSeconds * 1e9) paceFrom.compareAndSet(null, new long[] { nanos, now });
            return Double.NaN;
        }
        double seconds = (nanos - from[0]) / 1e9;
        long since = now - from[1];
        if (seconds < warmUpSeconds || since <= 0) return Double.NaN;
        return seconds * (total - now) / since;
    }

    /** @return seconds since this progress was made */
    public double elapsedSeconds() {
        return (System.nanoTime() - start) / 1e9;
    }
}
