package renderer;

import java.io.PrintStream;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Progress lines of one render: a full line (no carriage-return tricks, so IDE consoles show it)
 * each time another {@code step} percent of the pixels is done, with elapsed time and an ETA.
 * Shared by the workers of that render only; lock-free except when a line is due.
 */
final class Progress {
    private final String label;
    private final long total;
    private final double step;
    private final PrintStream out;
    private final long start = System.nanoTime();
    private final AtomicLong done = new AtomicLong();
    /** Index of the next step to report; updated under the lock by the worker that prints. */
    private final AtomicInteger nextStep = new AtomicInteger(1);

    /** @param step percent between lines; 0 reports nothing */
    Progress(String label, long total, double step, PrintStream out) {
        this.label = label;
        this.total = total;
        this.step = step;
        this.out = out;
    }

    void advance(long pixels) {
        long now = done.addAndGet(pixels);
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
            out.println(String.format(Locale.ROOT, "%s: %5.1f%%  %d/%d px  elapsed %.1f s  ETA %.1f s",
                    label, percent, now, total, elapsed, eta));
        }
    }

    double elapsedSeconds() {
        return (System.nanoTime() - start) / 1e9;
    }
}
