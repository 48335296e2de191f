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
    /** Index of the next step to report; a worker that claims it by CAS prints it. */
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
        // Claiming a step and printing it under one lock keeps the lines in order: without it a
        // worker that claimed step k could print after another that claimed step k + 1.
        synchronized (this) {
            while (true) {
                int k = nextStep.get();
                double mark = Math.min(100, k * step);
                if (percent < mark || !nextStep.compareAndSet(k, k + 1)) {
                    if (percent < mark) return;
                    continue;
                }
                double elapsed = (System.nanoTime() - start) / 1e9;
                double eta = now == 0 ? 0 : elapsed * (total - now) / now;
                out.println(String.format(Locale.ROOT, "%s: %5.1f%%  %d/%d px  elapsed %.1f s  ETA %.1f s",
                        label, percent, now, total, elapsed, eta));
                if (mark >= 100) return;
            }
        }
    }

    double elapsedSeconds() {
        return (System.nanoTime() - start) / 1e9;
    }
}
