package bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.regex.PatternSyntaxException;

/** The command line of {@link RenderBenchmark}; see {@link #USAGE}. */
record Options(boolean quick, int runs, Set<String> groups, Path out, int flatMax, int scalingMax,
               double budgetSeconds, double warmupSeconds, Pattern match, boolean images, boolean help) {

    static final List<String> GROUPS = List.of("teapot", "glossy", "showcase", "aa", "scaling", "build");

    static final String USAGE = """
            bench.RenderBenchmark: renders the benchmark scenes and prints a Markdown table.
              --quick            tiny images, 1 timed run: a smoke test of every configuration
              --runs N           timed runs per configuration after the warm-up (default 5)
              --warmup S         warm-up renders per configuration until they took S seconds (default 2;
                                 at least one, at most 20): one render is too few for C2 to finish
                                 compiling a short render's code, and a 2-thread render, whose
                                 compiler threads take a core from it, would be measured cold
              --only G1,G2       groups to run, of teapot, glossy, showcase, aa, scaling, build (default all)
              --match REGEX      only configurations whose "group settings, N threads" line contains a
                                 match, e.g. "teapot BVH" or "beam 50" (handy under a profiler)
              --out FILE         also write the tables to FILE
              --flat-max N       scaling: the largest N also rendered without the BVH (default 1000)
              --scaling-max N    scaling: the largest N rendered (default 1000000)
              --budget S         stop repeating a configuration once its timed runs took S seconds
                                 (default 0: no limit; at least one run is always made)
              --images           write each configuration's last render to images/bench/
              --help             this text
            """;

    /** @throws IllegalArgumentException naming the bad argument */
    static Options parse(String... args) {
        boolean quick = false, help = false, images = false;
        int runs = -1, flatMax = 1000, scalingMax = 1_000_000;
        double budget = 0, warmup = -1;
        Set<String> groups = new LinkedHashSet<>(GROUPS);
        Path out = null;
        Pattern match = null;
        List<String> list = new ArrayList<>();
        for (String a : args)
            if (!a.isBlank()) list.add(a.trim()); // Maven passes an empty property as an empty argument
        for (int i = 0; i < list.size(); ++i) {
            String a = list.get(i);
            switch (a) {
                case "--quick" -> quick = true;
                case "--help", "-h" -> help = true;
                case "--images" -> images = true;
                case "--runs" -> runs = positiveInt(a, value(list, ++i, a));
                case "--flat-max" -> flatMax = positiveInt(a, value(list, ++i, a));
                case "--scaling-max" -> scalingMax = positiveInt(a, value(list, ++i, a));
                case "--out" -> out = Path.of(value(list, ++i, a));
                case "--match" -> {
                    String v = value(list, ++i, a);
                    try {
                        match = Pattern.compile(v);
                    } catch (PatternSyntaxException e) {
                        throw new IllegalArgumentException("--match needs a regular expression, got '" + v + "'", e);
                    }
                }
                case "--budget" -> budget = seconds(a, value(list, ++i, a));
                case "--warmup" -> warmup = seconds(a, value(list, ++i, a));
                case "--only" -> {
                    groups = new LinkedHashSet<>();
                    for (String g : value(list, ++i, a).split(",")) {
                        String name = g.trim().toLowerCase(Locale.ROOT);
                        if (!GROUPS.contains(name))
                            throw new IllegalArgumentException("unknown group '" + g + "' in --only; groups: " + GROUPS);
                        groups.add(name);
                    }
                }
                default -> throw new IllegalArgumentException("unknown argument '" + a + "'\n" + USAGE);
            }
        }
        if (runs < 0) runs = quick ? 1 : 5;
        if (warmup < 0) warmup = quick ? 0 : 2;
        return new Options(quick, runs, groups, out, flatMax, scalingMax, budget, warmup, match, images, help);
    }

    private static String value(List<String> args, int i, String option) {
        if (i >= args.size()) throw new IllegalArgumentException(option + " needs a value");
        return args.get(i);
    }

    private static double seconds(String option, String v) {
        double s;
        try {
            s = Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " needs seconds, got '" + v + "'", e);
        }
        if (!(s >= 0) || Double.isInfinite(s)) throw new IllegalArgumentException(option + " must be >= 0 seconds, got " + v);
        return s;
    }

    private static int positiveInt(String option, String v) {
        try {
            int n = Integer.parseInt(v.replace("_", ""));
            if (n < 1) throw new IllegalArgumentException(option + " must be at least 1, got " + v);
            return n;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " needs a whole number, got '" + v + "'", e);
        }
    }
}
