package bench;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Old code against new, in one JVM: two class paths (each a tree's bench classes, main classes
 * and dependencies) loaded by two isolated class loaders, and {@link RenderBenchmark} of each run
 * in turn, A then B then B then A…, with the same arguments. For each row: the median over the
 * pairs of B's median / A's median (each pair measured seconds apart), the same of the fastest
 * renders, and B's fastest render of all / A's.
 *
 * <p>Why not two processes: on a shared two-core machine the speed drifts by tens of per cent
 * over minutes, so the medians of two processes run one after the other differ by more than the
 * few per cent being asked about; a pair measured back to back in one process sees the same
 * drift. The fastest renders matter as much: the slow spells last seconds and slow a render by up
 * to 1.6×, so the fastest of many renders is the code's speed with the least interference. Each loader has its own classes, so each side keeps its own compiled code and profile.
 *
 * <pre>
 * java -cp target/bench/classes bench.InterleavedAB --a OLD_CP --b NEW_CP --pairs 12 \
 *      -- --only glossy --match "beam 10, 1 thread" --runs 3 --warmup 2
 * java -cp target/bench/classes bench.InterleavedAB --a OLD_CP --b NEW_CP --processes 30 --pairs 2 -- …
 * </pre>
 * Everything after {@code --} goes to both sides' {@code RenderBenchmark}; with {@code --only build}
 * the rows are the BVH builds on 1 and on 2 threads (that group reports medians only, so its
 * "fastest" columns repeat them). With
 * {@code --processes N}, N fresh JVMs one after the other, each of {@code --pairs} pairs, and the
 * figures are medians over the processes: the compiled code itself varies between processes
 * (and between the two loaders of one), by as much as the few per cent asked about, so one
 * process's pairs compare one compilation of each side; an A/A run (the same class path twice)
 * shows the spread the method can resolve.
 */
public final class InterleavedAB {
    private InterleavedAB() {
    }

    public static void main(String[] args) throws Exception {
        String a = null, b = null;
        int pairs = 10, processes = 1;
        boolean raw = false;
        int split = Arrays.asList(args).indexOf("--");
        if (split < 0) throw new IllegalArgumentException("missing -- before RenderBenchmark's arguments");
        for (int i = 0; i < split; ++i) {
            if (args[i].equals("--raw")) {
                raw = true;
                continue;
            }
            if (i + 1 >= split) throw new IllegalArgumentException(args[i] + " needs a value");
            switch (args[i]) {
                case "--a" -> a = args[++i];
                case "--b" -> b = args[++i];
                case "--pairs" -> pairs = Integer.parseInt(args[++i]);
                case "--processes" -> processes = Integer.parseInt(args[++i]);
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        if (a == null || b == null) throw new IllegalArgumentException("--a and --b are required");
        String[] benchArgs = Arrays.copyOfRange(args, split + 1, args.length);
        // Per row, per unit (a pair, or with --processes a whole process): A's median, B's median,
        // A's fastest, B's fastest.
        Map<String, List<double[]>> rows = new LinkedHashMap<>();
        if (processes > 1) {
            for (int p = 0; p < processes; ++p) {
                for (var e : child(a, b, pairs, benchArgs).entrySet()) {
                    List<double[]> list = e.getValue();
                    double[] unit = {RenderBenchmark.median(column(list, 0)), RenderBenchmark.median(column(list, 1)),
                            RenderBenchmark.median(column(list, 2)), RenderBenchmark.median(column(list, 3))};
                    rows.computeIfAbsent(e.getKey(), k -> new ArrayList<>()).add(unit);
                    System.err.printf(Locale.ROOT, "process %d %s: B/A of medians %.3f, of fastest %.3f%n", p + 1,
                            e.getKey(), unit[1] / unit[0], unit[3] / unit[2]);
                }
            }
        } else {
            Method mainA = benchMain(a), mainB = benchMain(b);
            for (int p = 0; p < pairs; ++p) {
                // A first in even pairs, B first in odd ones: a drift within a pair cancels over two.
                boolean aFirst = p % 2 == 0;
                Map<String, double[]> first = run(aFirst ? mainA : mainB, benchArgs);
                Map<String, double[]> second = run(aFirst ? mainB : mainA, benchArgs);
                Map<String, double[]> ta = aFirst ? first : second, tb = aFirst ? second : first;
                for (var e : ta.entrySet()) {
                    double[] other = tb.get(e.getKey());
                    if (other == null) continue;
                    double[] x = e.getValue();
                    rows.computeIfAbsent(e.getKey(), k -> new ArrayList<>()).add(new double[] {x[0], other[0], x[1], other[1]});
                    if (raw) {
                        System.out.printf(Locale.ROOT, "RAW\t%s\t%s\t%s\t%s\t%s%n", e.getKey(), x[0], other[0], x[1], other[1]);
                    } else {
                        System.err.printf(Locale.ROOT, "pair %d %s: median A %.3f s, B %.3f s, B/A %.3f; fastest A %.3f s, B %.3f s%n",
                                p + 1, e.getKey(), x[0], other[0], other[0] / x[0], x[1], other[1]);
                    }
                }
            }
            if (raw) return;
        }
        String unit = processes > 1 ? "processes" : "pairs";
        System.out.println("| row | " + unit + " | A median s | B median s | B/A of medians (median of " + unit + ") | its quartiles "
                + "| B/A of fastest (median of " + unit + ") | its quartiles | fastest A s | fastest B s |");
        System.out.println("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|");
        for (var e : rows.entrySet()) {
            List<double[]> list = e.getValue();
            double[] ratio = list.stream().mapToDouble(x -> x[1] / x[0]).sorted().toArray();
            double[] fastRatio = list.stream().mapToDouble(x -> x[3] / x[2]).sorted().toArray();
            double fastA = list.stream().mapToDouble(x -> x[2]).min().orElseThrow();
            double fastB = list.stream().mapToDouble(x -> x[3]).min().orElseThrow();
            System.out.printf(Locale.ROOT, "| %s | %d | %.3f | %.3f | %.3f | %.3f–%.3f | %.3f | %.3f–%.3f | %.3f | %.3f |%n",
                    e.getKey(), list.size(), RenderBenchmark.median(column(list, 0)), RenderBenchmark.median(column(list, 1)),
                    RenderBenchmark.median(ratio), quantile(ratio, 0.25), quantile(ratio, 0.75),
                    RenderBenchmark.median(fastRatio), quantile(fastRatio, 0.25), quantile(fastRatio, 0.75), fastA, fastB);
        }
    }

    /**
     * One child JVM of this class with {@code --raw}: its pairs by row (A's median, B's median,
     * A's fastest, B's fastest). Each process compiles both sides afresh, so the spread between
     * processes includes the compiler's own: the same code, compiled in two processes (or by two
     * class loaders of one), can run several per cent apart for as long as the process lives.
     */
    private static Map<String, List<double[]>> child(String a, String b, int pairs, String[] benchArgs)
            throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx8g"));
        // The children read the vector module when this JVM does, and take the walk this JVM was
        // told to (-Draytracer.simd): an A/B with and without the BVH's vector walk is this command
        // run with --add-modules jdk.incubator.vector -Draytracer.simd=true and without.
        if (ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent())
            command.addAll(List.of("--add-modules", "jdk.incubator.vector"));
        String simd = System.getProperty("raytracer.simd");
        if (simd != null) command.add("-Draytracer.simd=" + simd);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), InterleavedAB.class.getName(),
                "--a", a, "--b", b, "--pairs", Integer.toString(pairs), "--raw", "--"));
        command.addAll(Arrays.asList(benchArgs));
        Process process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        Map<String, List<double[]>> rows = new LinkedHashMap<>();
        try (var out = new java.io.BufferedReader(new java.io.InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line; (line = out.readLine()) != null;) {
                String[] f = line.split("\t");
                if (f.length != 6 || !f[0].equals("RAW")) continue;
                rows.computeIfAbsent(f[1], k -> new ArrayList<>()).add(new double[] {Double.parseDouble(f[2]),
                        Double.parseDouble(f[3]), Double.parseDouble(f[4]), Double.parseDouble(f[5])});
            }
        }
        int exit = process.waitFor();
        if (exit != 0 || rows.isEmpty()) throw new IllegalStateException("child run exited with " + exit + ", rows " + rows.keySet());
        return rows;
    }

    private static double[] column(List<double[]> rows, int i) {
        return rows.stream().mapToDouble(x -> x[i]).toArray();
    }

    private static Method benchMain(String classPath) throws ReflectiveOperationException, MalformedURLException {
        String[] parts = classPath.split(File.pathSeparator);
        URL[] urls = new URL[parts.length];
        for (int i = 0; i < parts.length; ++i) urls[i] = new File(parts[i]).toURI().toURL();
        // The platform loader as parent: nothing of either tree comes from this class's own path.
        ClassLoader loader = new URLClassLoader(urls, ClassLoader.getPlatformClassLoader());
        return loader.loadClass("bench.RenderBenchmark").getMethod("main", String[].class);
    }

    /** One RenderBenchmark run; its table's median and fastest render by row (scene, settings, threads). */
    private static Map<String, double[]> run(Method main, String[] args) throws IllegalAccessException {
        PrintStream out = System.out, err = System.err;
        ByteArrayOutputStream report = new ByteArrayOutputStream();
        try (PrintStream capture = new PrintStream(report, true, StandardCharsets.UTF_8);
             PrintStream quiet = new PrintStream(PrintStream.nullOutputStream())) {
            System.setOut(capture);
            System.setErr(quiet);
            main.invoke(null, (Object) args.clone());
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("RenderBenchmark failed", e.getCause());
        } finally {
            System.setOut(out);
            System.setErr(err);
        }
        Map<String, double[]> medians = new LinkedHashMap<>();
        boolean builds = false; // whether the table being read is the build group's
        for (String line : report.toString(StandardCharsets.UTF_8).split("\n")) {
            String[] cells = line.split("\\|");
            if (cells.length > 2 && cells[2].trim().equals("primitives")) builds = true;
            else if (cells.length > 2 && cells[1].trim().equals("scene")) builds = false;
            if (builds) {
                // | scene | primitives | runs | 1 thread s (median) | 2 threads s (median) | …: the
                // group gives medians only, which stand for the fastest too.
                if (cells.length < 6 || !cells[4].trim().matches("[0-9.]+")) continue;
                double one = Double.parseDouble(cells[4].trim()), two = Double.parseDouble(cells[5].trim());
                medians.put(cells[1].trim() + ", build, 1 t", new double[] {one, one});
                medians.put(cells[1].trim() + ", build, 2 t", new double[] {two, two});
                continue;
            }
            // | scene | resolution | settings | threads | runs | median s | …: cells[0] is empty.
            if (cells.length < 8 || !cells[6].trim().matches("[0-9.]+")) continue;
            String key = cells[1].trim() + ", " + cells[3].trim() + ", " + cells[4].trim() + " t";
            medians.put(key, new double[] {Double.parseDouble(cells[6].trim()), Double.parseDouble(cells[7].trim())});
        }
        if (medians.isEmpty()) throw new IllegalStateException("no rows in the report:\n" + report);
        return medians;
    }

    private static double quantile(double[] sorted, double q) {
        double pos = q * (sorted.length - 1);
        int lo = (int) Math.floor(pos), hi = (int) Math.ceil(pos);
        return sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo);
    }
}
