package bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * The benchmark's Markdown: a table per group, the scaling table, and the table that sets our
 * figures beside the student reports', the course's and the targets (ratios measured in
 * this same run).
 */
final class Report {
    private Report() {
    }

    static String markdown(Options o, String commandLine, Machine machine, double loadAtEnd, List<Measurement> results) {
        StringBuilder s = new StringBuilder();
        s.append("## Render benchmark").append(o.quick() ? " (quick smoke run: tiny images, not for comparison)" : "")
                .append("\n\n");
        s.append("- Command: `bench.RenderBenchmark ").append(commandLine).append("`\n");
        s.append("- Date: ").append(machine.date()).append("\n");
        s.append("- Machine: ").append(machine.summary())
                .append(String.format(Locale.ROOT, ", %.2f at the end", loadAtEnd)).append("\n");
        s.append(String.format(Locale.ROOT, "- Each configuration: warm-up renders until they took %.1f s (at least one), then ",
                o.warmupSeconds())).append(o.runs())
                .append(" timed run(s); render times are medians of RenderStats.seconds() (the render loop: no BVH build, "
                        + "no JVM start, no PNG); the BVH build is the median of RenderStats.prepareSeconds().\n\n");

        for (String group : Options.GROUPS) {
            List<Measurement> rows = results.stream().filter(m -> m.config().group().equals(group)).toList();
            if (rows.isEmpty()) continue;
            s.append("### ").append(group).append("\n\n").append(mainTable(rows)).append("\n");
            if (group.equals("scaling")) s.append(scalingTable(rows)).append("\n");
        }
        if (o.quick()) s.append("_Quick mode: no comparison with the reports (the images are too small)._\n");
        else s.append(barTable(results));
        return s.toString();
    }

    private static String mainTable(List<Measurement> rows) {
        StringBuilder s = new StringBuilder();
        s.append("| scene | resolution | settings | threads | runs | median s | min s | BVH build s | camera rays "
                + "| shadow rays | secondary rays | Mrays/s (all) | camera Mrays/s | alloc B/ray | peak heap MB |\n");
        s.append("|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
        for (Measurement m : rows) {
            Configuration c = m.config();
            s.append(String.format(Locale.ROOT, "| %s | %s | %s | %d | %d | %.3f | %.3f | %s | %,d | %,d | %,d | %.2f | %.2f | %s | %,.0f |%n",
                    c.sceneLabel(), c.resolution(), c.settings(), c.threads(), m.runs(), m.median(), m.min(),
                    c.bvh() ? String.format(Locale.ROOT, "%.3f", m.buildSeconds()) : "–",
                    m.stats().cameraRays(), m.stats().shadowRays(), m.stats().secondaryRays(), m.mraysPerSecond(),
                    m.cameraMraysPerSecond(), Double.isNaN(m.allocPerRay()) ? "?" : String.format(Locale.ROOT, "%.1f", m.allocPerRay()),
                    m.peakHeapBytes() / 1e6));
        }
        return s.toString();
    }

    /** Time per camera ray against the primitive count, relative to 10³ with the same method. */
    private static String scalingTable(List<Measurement> rows) {
        StringBuilder s = new StringBuilder();
        s.append("Time per camera ray (its shadow ray included), BVH build excluded:\n\n");
        s.append("| primitives | method | BVH build s | render s (median) | ns per camera ray | × the 2×10³ time |\n");
        s.append("|--:|---|--:|--:|--:|--:|\n");
        for (Measurement m : rows) {
            Configuration c = m.config();
            Optional<Measurement> base = rows.stream()
                    .filter(b -> b.config().primitives() == 2000 && b.config().bvh() == c.bvh()).findFirst();
            s.append(String.format(Locale.ROOT, "| %s | %s | %s | %.3f | %.1f | %s |%n",
                    "2×" + Configurations.power(c.primitives() / 2), c.settings(),
                    c.bvh() ? String.format(Locale.ROOT, "%.3f", m.buildSeconds()) : "–", m.median(),
                    m.nsPerCameraRay(),
                    base.map(b -> String.format(Locale.ROOT, "%.2f", m.nsPerCameraRay() / b.nsPerCameraRay())).orElse("–")));
        }
        return s.toString();
    }

    /** A published figure, the configuration of ours that answers it, and the target. */
    private record Bar(String figure, double theirs, String theirsText, Predicate<Configuration> ours, double scale,
                       String target, double targetSeconds) {
    }

    private static String barTable(List<Measurement> results) {
        List<Bar> bars = new ArrayList<>();
        Predicate<Configuration> primary = c -> c.settings().startsWith("primary rays");
        Predicate<Configuration> teapot = c -> c.group().equals("teapot") && c.width() == 1000 && !primary.test(c);
        bars.add(new Bar("course teapot 1000×1000, no acceleration, 1 thread", 25, "25 s",
                teapot.and(c -> !c.bvh() && c.threads() == 1), 1, "", Double.NaN));
        bars.add(new Bar("course teapot 1000×1000, no acceleration, all cores", 9.3, "9.3 s",
                teapot.and(c -> !c.bvh() && c.threads() == 2), 1, "", Double.NaN));
        bars.add(new Bar("best public course implementations, teapot with BVH, 2 threads (warm)", 0.70, "0.70 s",
                teapot.and(c -> c.bvh() && c.threads() == 2), 1, "≤ 0.15 s", 0.15));
        Predicate<Configuration> glossy = c -> c.group().equals("glossy") && c.width() == 1000;
        bars.add(new Bar("glossy 1000×1000, 1 ray per pixel with bounding boxes (our beam 1)", 10.3, "10.3 s",
                glossy.and(c -> c.settings().equals("beam 1")), 1, "", Double.NaN));
        bars.add(new Bar("glossy 1000×1000, 50-ray beams", 45 * 60 + 42, "45 min 42 s",
                glossy.and(c -> c.settings().equals("beam 50")), 1, "≤ 60 s", 60));
        Predicate<Configuration> showcase = c -> c.group().equals("showcase") && c.width() == 600;
        bars.add(new Bar("showcase 600×600, RANDOM 17×17", 69 * 60, "1 h 9 min",
                showcase.and(c -> c.settings().equals("RANDOM 17×17")), 1, "≤ 60 s", 60));
        bars.add(new Bar("showcase 600×600, ADAPTIVE", 32 * 60, "32 min",
                showcase.and(c -> c.settings().startsWith("ADAPTIVE")), 1, "≤ 10 s", 10));
        bars.add(new Bar("showcase 1400×1400, RANDOM 33×33 (ours: 600×600 × 1400²/600², extrapolated)",
                5 * 3600 + 13 * 60, "5 h 13 min", showcase.and(c -> c.settings().equals("RANDOM 33×33")),
                1400.0 * 1400 / (600.0 * 600), "", Double.NaN));

        StringBuilder s = new StringBuilder("### Against the bar\n\n");
        s.append("Their figures were measured on the students' laptops (3–4 threads) or by the course; ours on "
                + "this machine in this run. Speed-up = their time / ours.\n\n");
        s.append("| figure | theirs | ours | speed-up | issue target | met? |\n|---|--:|--:|--:|--:|---|\n");
        for (Bar b : bars) {
            Optional<Measurement> m = results.stream().filter(r -> b.ours().test(r.config())).findFirst();
            if (m.isEmpty()) continue;
            double ours = m.get().median() * b.scale();
            s.append(String.format(Locale.ROOT, "| %s | %s | %s | %s | %s | %s |%n", b.figure(), b.theirsText(),
                    seconds(ours), ratio(b.theirs() / ours), b.target().isEmpty() ? "–" : b.target(),
                    Double.isNaN(b.targetSeconds()) ? "–" : ours <= b.targetSeconds() ? "yes" : "**no**"));
        }

        // Rate and ratio targets of the issue, measured in this run.
        Optional<Measurement> bvh1 = find(results, teapot.and(c -> c.bvh() && c.threads() == 1));
        Optional<Measurement> bvh2 = find(results, teapot.and(c -> c.bvh() && c.threads() == 2));
        Optional<Measurement> flat1 = find(results, teapot.and(c -> !c.bvh() && c.threads() == 1));
        Optional<Measurement> flat2 = find(results, teapot.and(c -> !c.bvh() && c.threads() == 2));
        s.append("\n| measure | ours | target | met? |\n|---|--:|--:|---|\n");
        bvh2.ifPresent(m -> {
            double rate = m.cameraMraysPerSecond();
            s.append(String.format(Locale.ROOT, "| teapot camera rays in the full render (shaded, shadows), BVH, 2 threads (Mrays/s) | %.2f | ≥ 12 | %s |%n",
                    rate, rate >= 12 ? "yes" : "**no**"));
        });
        find(results, c -> c.group().equals("teapot") && c.width() == 1000 && primary.test(c) && c.threads() == 2).ifPresent(m -> {
            double rate = m.cameraMraysPerSecond();
            s.append(String.format(Locale.ROOT, "| teapot primary rays, tracing core only (closest hit, no shading), 2 threads (Mrays/s) | %.2f | ≥ 18.5 | %s |%n",
                    rate, rate >= 18.5 ? "yes" : "**no**"));
            s.append(String.format(Locale.ROOT, "| … as a fraction of Embree's ~37 Mrays/s primary rays (within 2× = ≥ 0.50) | %.2f | ≥ 0.50 | %s |%n",
                    rate / 37, rate / 37 >= 0.5 ? "yes" : "**no**"));
        });
        if (bvh1.isPresent() && bvh2.isPresent()) {
            double speedup = bvh1.get().median() / bvh2.get().median();
            s.append(String.format(Locale.ROOT, "| teapot BVH: 2 threads vs 1 (speed-up) | %.2f | ≥ 1.8 | %s |%n",
                    speedup, speedup >= 1.8 ? "yes" : "**no**"));
        }
        if (flat1.isPresent() && flat2.isPresent()) {
            double speedup = flat1.get().median() / flat2.get().median();
            s.append(String.format(Locale.ROOT, "| teapot flat: 2 threads vs 1 (speed-up) | %.2f | ≥ 1.8 | %s |%n",
                    speedup, speedup >= 1.8 ? "yes" : "**no**"));
        }
        if (flat2.isPresent() && bvh2.isPresent())
            s.append(String.format(Locale.ROOT, "| teapot 2 threads: BVH vs flat (speed-up) | %.1f | – | – |%n",
                    flat2.get().median() / bvh2.get().median()));
        // Every other configuration rendered on 1 and on 2 threads: the second thread's speed-up.
        for (Measurement two : results) {
            Configuration c2 = two.config();
            if (c2.threads() != 2 || c2.group().equals("teapot")) continue;
            find(results, c -> c.threads() == 1 && c.group().equals(c2.group()) && c.sceneKey().equals(c2.sceneKey())
                    && c.settings().equals(c2.settings()) && c.width() == c2.width() && c.height() == c2.height()
                    && c.bvh() == c2.bvh()).ifPresent(one -> {
                        double speedup = one.median() / two.median();
                        s.append(String.format(Locale.ROOT, "| %s %s %s: 2 threads vs 1 (speed-up) | %.2f | ≥ 1.8 | %s |%n",
                                c2.group(), c2.resolution(), c2.settings(), speedup, speedup >= 1.8 ? "yes" : "**no**"));
                    });
        }
        Optional<Measurement> k3 = find(results, c -> c.group().equals("scaling") && c.bvh() && c.primitives() == 2000);
        Optional<Measurement> m6 = find(results, c -> c.group().equals("scaling") && c.bvh() && c.primitives() == 2_000_000);
        if (k3.isPresent() && m6.isPresent()) {
            double r = m6.get().nsPerCameraRay() / k3.get().nsPerCameraRay();
            s.append(String.format(Locale.ROOT, "| scaling, BVH: time per camera ray at 2×10⁶ / at 2×10³ | %.2f | ≤ 3 | %s |%n",
                    r, r <= 3 ? "yes" : "**no**"));
        }
        s.append("\nThe whole-process teapot time (JVM start to PNG) is measured apart: see BENCHMARKS.md.\n");
        return s.toString();
    }

    private static Optional<Measurement> find(List<Measurement> results, Predicate<Configuration> p) {
        return results.stream().filter(r -> p.test(r.config())).findFirst();
    }

    private static String seconds(double s) {
        return s >= 100 ? String.format(Locale.ROOT, "%.0f s", s) : String.format(Locale.ROOT, "%.3g s", s);
    }

    private static String ratio(double r) {
        return r >= 100 ? String.format(Locale.ROOT, "%.0f×", r) : String.format(Locale.ROOT, "%.1f×", r);
    }
}
