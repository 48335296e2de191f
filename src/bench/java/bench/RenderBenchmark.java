package bench;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import geometries.Bvh;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RenderStats;
import scene.Scene;

/**
 * The render benchmark (see BENCHMARKS.md): renders each configuration of {@link Configurations}
 * once to warm the JIT up, then {@code --runs} times, and prints Markdown tables of the medians
 * with the BVH build time, the rays traced by kind, the ray rates, the bytes allocated per ray and
 * the peak heap.
 * Progress goes to stderr, the tables to stdout (and {@code --out FILE}).
 *
 * <p>Run it in its own JVM (the {@code bench} Maven profile forks one), on an otherwise idle
 * machine: the numbers are wall-clock times.
 */
public final class RenderBenchmark {
    private final Options options;
    private final PrintStream log;

    private RenderBenchmark(Options options, PrintStream log) {
        this.options = options;
        this.log = log;
    }

    public static void main(String[] args) throws IOException {
        Options options;
        try {
            options = Options.parse(args);
        } catch (IllegalArgumentException e) {
            System.err.println("bench.RenderBenchmark: " + e.getMessage());
            System.err.print(Options.USAGE);
            System.exit(2);
            return;
        }
        if (options.help()) {
            System.out.print(Options.USAGE);
            return;
        }
        String report = new RenderBenchmark(options, System.err).run(String.join(" ", args));
        System.out.print(report);
        if (options.out() != null) {
            Path parent = options.out().toAbsolutePath().getParent();
            if (parent != null) Files.createDirectories(parent);
            Files.writeString(options.out(), report);
            System.err.println("wrote " + options.out());
        }
    }

    /** Renders every configuration and returns the report. */
    private String run(String commandLine) {
        Machine machine = Machine.describe();
        List<Configuration> configs = Configurations.of(options);
        if (configs.isEmpty()) log.println("no configuration matches " + options.groups() + " and --match " + options.match());
        log.printf(Locale.ROOT, "%d configurations, %d timed run(s) each%s%n", configs.size(), options.runs(),
                options.quick() ? " (quick)" : "");
        List<Measurement> results = new ArrayList<>();
        Scene scene = null;
        String sceneKey = null;
        for (Configuration c : configs) {
            if (!c.sceneKey().equals(sceneKey)) {
                scene = null; // let the previous scene go before building the next
                System.gc();
                long t0 = System.nanoTime();
                scene = c.scene().get();
                sceneKey = c.sceneKey();
                log.printf(Locale.ROOT, "built scene %s in %.2f s%n", sceneKey, (System.nanoTime() - t0) / 1e9);
            }
            Measurement m = measure(c, scene);
            log.printf(Locale.ROOT, "  %s %s: median %.3f s of %d, %.2f Mrays/s%n", c.describe(), c.resolution(),
                    m.median(), m.runs(), m.mraysPerSecond());
            results.add(m);
        }
        String report = Report.markdown(options, commandLine, machine, Machine.loadAverage(), results);
        // The build group times Bvh.build alone (no render): its own table after the others.
        return options.groups().contains("build") ? report + "\n" + BuildBenchmark.markdown(options, log) : report;
    }

    /** The most warm-up renders of one configuration, whatever --warmup asks. */
    private static final int MAX_WARMUP_RENDERS = 20;

    private Measurement measure(Configuration c, Scene scene) {
        // Warm-up: renders (smaller for costly configurations, see Configuration.warmupScale) until
        // they took --warmup seconds: with a single one, a 0.2 s render's first timed runs still
        // ran code that C2 was compiling, on 2 threads with the compiler taking one of the cores.
        int ww = Math.max(16, (int) Math.round(c.width() * c.warmupScale()));
        int wh = Math.max(16, (int) Math.round(c.height() * c.warmupScale()));
        double warm = 0;
        for (int i = 0; i < MAX_WARMUP_RENDERS && (i == 0 || warm < options.warmupSeconds()); ++i)
            warm += render(c, scene, ww, wh, c.threads(), false).seconds();

        double allocPerRay = allocationPerRay(c, scene);

        HeapMeter.reset();
        double[] times = new double[options.runs()];
        double[] prepare = new double[options.runs()];
        int runs = 0;
        double spent = 0;
        RenderStats last = null;
        while (runs < options.runs()) {
            // Each timed render starts from a collected heap: otherwise the previous render's
            // garbage (at 2×10⁶ primitives, the rebuilt tree's humongous arrays) starts a concurrent
            // G1 cycle whose marking competes with this render for the two cores, and the row
            // spreads by a third between runs.
            System.gc();
            last = render(c, scene, c.width(), c.height(), c.threads(), options.images() && runs == options.runs() - 1);
            prepare[runs] = last.prepareSeconds();
            times[runs++] = last.seconds();
            spent += last.seconds();
            log.printf(Locale.ROOT, "    run %d: %.3f s (+ %.3f s preparing)%n", runs, last.seconds(), last.prepareSeconds());
            if (options.budgetSeconds() > 0 && spent >= options.budgetSeconds() && runs < options.runs()) {
                log.printf(Locale.ROOT, "    budget of %.0f s spent: stopping after %d run(s)%n", options.budgetSeconds(), runs);
                break;
            }
        }
        long peak = HeapMeter.peakBytes();
        double[] done = Arrays.copyOf(times, runs);
        return new Measurement(c, runs, median(done), Arrays.stream(done).min().orElseThrow(), last,
                median(Arrays.copyOf(prepare, runs)), peak, allocPerRay);
    }

    private static RenderStats render(Configuration c, Scene scene, int width, int height, int threads, boolean write) {
        Camera camera = camera(c, scene, width, height, threads);
        RenderStats stats = camera.render();
        if (write) camera.writeToImage();
        return stats;
    }

    private static Camera camera(Configuration c, Scene scene, int width, int height, int threads) {
        String name = "bench/" + c.sceneKey() + "-" + c.settings().replaceAll("[^A-Za-z0-9]+", "_") + "-" + threads + "t";
        return c.camera().builder(scene)
                .setImageWriter(new ImageWriter(name, width, height))
                .setMultithreading(threads)
                .setSummary(false)
                .build();
    }

    /**
     * Bytes allocated per ray, from a render of a tenth of the side on the calling thread (the
     * JVM counts allocations per thread; worker threads are gone when the render returns). The
     * BVH build, done inside the render, is measured apart and subtracted.
     */
    private static double allocationPerRay(Configuration c, Scene scene) {
        Camera camera = camera(c, scene, Math.max(8, c.width() / 10), Math.max(8, c.height() / 10), 0);
        long before = HeapMeter.threadAllocatedBytes();
        RenderStats stats = camera.render();
        long after = HeapMeter.threadAllocatedBytes();
        long build = 0;
        if (c.bvh()) {
            long b0 = HeapMeter.threadAllocatedBytes();
            Bvh.build(scene.geometries);
            build = HeapMeter.threadAllocatedBytes() - b0;
        }
        if (before < 0 || stats.totalRays() == 0) return Double.NaN;
        return Math.max(0, after - before - build) / (double) stats.totalRays();
    }

    static double median(double[] values) {
        double[] v = values.clone();
        Arrays.sort(v);
        int n = v.length;
        return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
    }
}
