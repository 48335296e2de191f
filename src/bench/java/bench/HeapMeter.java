package bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.util.List;

/**
 * Peak heap use over a window and the bytes one thread allocates. The peak is the sum of the
 * heap pools' peaks (eden, survivor, old): an upper bound of the true peak, since the pools need
 * not peak at the same moment, and it includes the scene, which stays alive while it renders.
 */
final class HeapMeter {
    private static final List<MemoryPoolMXBean> HEAP = ManagementFactory.getMemoryPoolMXBeans().stream()
            .filter(p -> p.getType() == MemoryType.HEAP && p.isValid()).toList();
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    private HeapMeter() {
    }

    /** Collects the garbage of earlier work, then starts a new peak window. */
    static void reset() {
        System.gc();
        for (MemoryPoolMXBean pool : HEAP) pool.resetPeakUsage();
    }

    /** @return the heap's peak use since {@link #reset()}, in bytes */
    static long peakBytes() {
        long sum = 0;
        for (MemoryPoolMXBean pool : HEAP) sum += pool.getPeakUsage().getUsed();
        return sum;
    }

    /** @return the bytes the calling thread has allocated so far, or -1 when the JVM cannot tell */
    static long threadAllocatedBytes() {
        return THREADS.isThreadAllocatedMemorySupported() && THREADS.isThreadAllocatedMemoryEnabled()
                ? THREADS.getCurrentThreadAllocatedBytes() : -1;
    }
}
