package geometries;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveAction;

/**
 * Runs a body over the index range [0, n) in chunks, as fork/join tasks when a pool is given and
 * one after the other on the calling thread otherwise: the BVH build's loops over millions of
 * independent primitives. The chunks are the same either way, so a body may keep a result per
 * chunk ({@code from / grain}).
 *
 * <p>Why chunks on one thread too: the JIT compiles a method called hundreds of times with its
 * whole profile, loop exits included, and a later build starts in that code. One call over the
 * whole range got only an on-stack-replacement compile, made before the loop ever ended: it trapped
 * at the loop's end, and the next build in the JVM ran the loop interpreted until it was compiled
 * again (on JDK 25, 0.08-0.12 s of a 1.1 s build of 10<sup>6</sup> triangles).
 *
 * <p>Failures read as in a sequential loop: a chunk stops at its first exception, and the one
 * rethrown on the calling thread, unwrapped, is that of the lowest failing chunk, which is the
 * exception the loop over [0, n) in order would have met first.
 */
final class Ranges {
    /** The work on indices [from, to). */
    @FunctionalInterface
    interface Body {
        void run(int from, int to);
    }

    private Ranges() {
    }

    /**
     * @param pool  the pool to run the chunks in, or null to run them in order on this thread
     * @param n     the size of the range
     * @param grain the chunk size, ≥ 1: enough indices to be worth a task
     * @param body  what to do with each chunk [k·grain, min(n, (k + 1)·grain)); chunks run
     *              concurrently and must not share writes
     */
    static void run(ForkJoinPool pool, int n, int grain, Body body) {
        if (pool == null || n <= grain) {
            for (int from = 0; from < n;) {
                int to = n - from > grain ? from + grain : n; // never past n, whatever n and grain
                body.run(from, to);
                from = to;
            }
            return;
        }
        RuntimeException[] failures = new RuntimeException[(n + grain - 1) / grain];
        pool.invoke(new Chunks(0, failures.length, n, grain, body, failures));
        for (RuntimeException failure : failures)
            if (failure != null) throw failure;
    }

    /** Chunks [first, last) of the range, split in halves until one is left. */
    private static final class Chunks extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final int first;
        private final int last;
        private final int n;
        private final int grain;
        private final transient Body body;
        private final RuntimeException[] failures;

        Chunks(int first, int last, int n, int grain, Body body, RuntimeException[] failures) {
            this.first = first;
            this.last = last;
            this.n = n;
            this.grain = grain;
            this.body = body;
            this.failures = failures;
        }

        @Override
        protected void compute() {
            if (last - first > 1) {
                int mid = (first + last) >>> 1;
                invokeAll(new Chunks(first, mid, n, grain, body, failures), new Chunks(mid, last, n, grain, body, failures));
                return;
            }
            try {
                body.run(first * grain, Math.min(n, (first + 1) * grain));
            } catch (RuntimeException e) {
                failures[first] = e;
            }
        }
    }
}
