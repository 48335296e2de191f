package bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.time.temporal.ChronoUnit;
import java.util.Locale;
import java.util.Optional;

/**
 * Where the benchmark ran: date, CPU, JVM, heap and the load average at the start (a load near
 * or above the core count means other work competed for the cores and the times are inflated).
 */
record Machine(String date, String cpu, int cores, String java, long maxHeapBytes, double loadAtStart) {

    static Machine describe() {
        Runtime rt = Runtime.getRuntime();
        String java = System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version")
                + " (" + System.getProperty("java.vm.vendor") + "), " + System.getProperty("os.name") + " "
                + System.getProperty("os.arch");
        return new Machine(ZonedDateTime.now().truncatedTo(ChronoUnit.SECONDS).format(DateTimeFormatter.ISO_OFFSET_DATE_TIME), cpuModel().orElse("unknown CPU"),
                rt.availableProcessors(), java, rt.maxMemory(), loadAverage());
    }

    /** @return the one-minute system load average, or NaN where the OS does not tell */
    static double loadAverage() {
        double l = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        return l < 0 ? Double.NaN : l;
    }

    /** The CPU's model name on Linux; empty elsewhere (or when /proc cannot be read). */
    private static Optional<String> cpuModel() {
        Path info = Path.of("/proc/cpuinfo");
        if (!Files.isReadable(info)) return Optional.empty();
        try (var lines = Files.lines(info)) {
            return lines.filter(l -> l.startsWith("model name")).findFirst()
                    .map(l -> l.substring(l.indexOf(':') + 1).trim());
        } catch (IOException | java.io.UncheckedIOException e) {
            // The description is informative only: an unreadable /proc is reported as unknown.
            return Optional.empty();
        }
    }

    String summary() {
        return String.format(Locale.ROOT, "%s; %d cores available to the JVM; %s; max heap %.1f GB; load average %.2f at start",
                cpu, cores, java, maxHeapBytes / 1e9, loadAtStart);
    }
}
