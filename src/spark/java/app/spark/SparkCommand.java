package app.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;

import app.cli.SparkRequest;
import app.cli.SparkRunner;
import scene.io.Messages;
import scene.io.SceneFormatException;

/**
 * The command line's Spark render (see {@link SparkEntry}): the driver validates, then starts
 * Spark, renders and writes. Spark's own log is off unless {@code spark.log.level} is set (with
 * {@code --conf} of spark-submit or {@code -Dspark.log.level=WARN}; see {@link QuietLog}), so that
 * a failure is the one line the command line promises; the cause is in the executors' logs.
 */
final class SparkCommand {
    private SparkCommand() {
    }

    /** @return whether {@code master} runs its executors in the driver's JVM (local, local[N], local[N,M], local[*]) */
    static boolean runsInThisJvm(String master) {
        return master.equals("local") || master.startsWith("local[");
    }

    /**
     * The jar this program's classes come from, for {@code spark.jars}; null when they come from
     * a class folder (a build's target/classes) or from where no file is.
     */
    static Path applicationJar() {
        try {
            java.security.CodeSource source = SparkCommand.class.getProtectionDomain().getCodeSource();
            if (source == null || source.getLocation() == null) return null;
            Path path = Path.of(source.getLocation().toURI());
            return java.nio.file.Files.isRegularFile(path) && path.toString().endsWith(".jar") ? path : null;
        } catch (java.net.URISyntaxException | IllegalArgumentException | java.nio.file.FileSystemNotFoundException e) {
            return null; // not a file on this machine: nothing to ship
        }
    }

    static int run(SparkRequest request, PrintStream progress, PrintStream out, PrintStream err) {
        return run(request, TileProbe.NONE, progress, out, err);
    }

    /** As {@link #run(SparkRequest, PrintStream, PrintStream, PrintStream)}, with the tests' fault injection. */
    static int run(SparkRequest request, TileProbe probe, PrintStream progress, PrintStream out, PrintStream err) {
        long start = System.nanoTime();
        boolean quiet = QuietLog.unlessAsked(); // first: a bad input's exit must not be followed by Spark's shutdown lines
        List<SparkFrame> frames = new ArrayList<>();
        Map<Path, String> outputs = new HashMap<>();
        for (Path scene : request.scenes()) {
            SparkFrame frame;
            try {
                frame = SparkFrame.read(scene, request.meshRoot());
            } catch (SceneFormatException e) {
                err.println(e.getMessage());
                return SparkEntry.BAD_INPUT;
            } catch (IOException e) {
                err.println(Messages.visible(Messages.cannotReadScene(scene, e)));
                return SparkEntry.BAD_INPUT;
            } catch (OutOfMemoryError e) { // a mesh that does not fit the driver's heap: the reader named it
                String named = e.getMessage();
                long max = Runtime.getRuntime().maxMemory();
                err.println("raytracer: " + (named != null && named.startsWith("the OBJ file ") ? Messages.visible(named)
                        : "not enough memory to read " + Messages.visible(scene.toString()) + " on the driver"
                        + (max == Long.MAX_VALUE ? "" : "; Java may use at most " + (max >> 20) + " MB there")
                        + " (give the driver more memory with spark-submit --driver-memory, or -Xmx for a local master)"));
                return 1;
            }
            try {
                frame = frame.withSettings(request.settings().apply(frame.settings(), frame.loadedScene()));
            } catch (IllegalArgumentException e) {
                err.println(Messages.visible(scene + ": " + e.getMessage()));
                return SparkEntry.BAD_INPUT;
            }
            if (request.output() != null) frame = frame.withOutput(request.output());
            String other = outputs.putIfAbsent(frame.output().toAbsolutePath().normalize(), scene.toString());
            if (other != null) {
                err.println("raytracer: " + other + " and " + scene + " would both write " + frame.output()
                        + " (give the scenes different image names)");
                return SparkEntry.BAD_INPUT;
            }
            frames.add(frame);
        }

        SparkConf conf = new SparkConf().setAppName("raytracer " + frames.get(0).scene()
                + (frames.size() > 1 ? " and " + (frames.size() - 1) + " more" : ""));
        if (!request.master().equals(SparkRequest.SUBMIT)) conf.setMaster(request.master());
        else if (!conf.contains("spark.master")) {
            err.println("raytracer: --spark " + SparkRequest.SUBMIT + " takes the master of spark-submit, and there is none: "
                    + "give a master URL such as --spark local[2], or " + SparkRunner.HOW_TO_RUN);
            return SparkEntry.BAD_INPUT;
        }
        QuietLog.onExecutors(conf, quiet);
        ExecutorWalk.fromTheFirstRay(conf);
        String master = conf.get("spark.master");
        if (!runsInThisJvm(master) && !conf.contains("spark.jars")) {
            // Outside spark-submit nothing ships this program's classes to a cluster's executors,
            // whose every task then failed with ClassNotFoundException after a minute: ship the
            // jar this class came from, or, run from class folders (the Maven profile), refuse.
            Path jar = applicationJar();
            if (jar == null) {
                err.println("raytracer: --spark " + master + ": a cluster's executors need this program's jar, and it runs"
                        + " from class folders here, which Spark cannot ship: build it (mvn -Pspark package) and run"
                        + " spark-submit --master " + master + " --class app.cli.Main target/raytracer.jar --spark submit ...,"
                        + " or render on this machine with --spark local[N]");
                return SparkEntry.BAD_INPUT;
            }
            conf.set("spark.jars", jar.toUri().toString());
        }
        try {
            SparkRenderer.executorTimeout(conf); // before Spark starts: a bad value costs no context
        } catch (IllegalArgumentException e) {
            err.println("raytracer: " + Messages.visible(e.getMessage()));
            return SparkEntry.BAD_INPUT;
        }
        JavaSparkContext started;
        try {
            started = new JavaSparkContext(conf);
        } catch (RuntimeException e) { // a driver Spark refuses (too little memory), a master it cannot reach
            err.println("raytracer: cannot start Spark: " + SparkRenderer.firstLine(e));
            return 1;
        }
        try (JavaSparkContext spark = started) {
            new SparkRenderer(spark).setProbe(probe).setProgress(request.progressStep()).setOutput(progress)
                    .setSummary(request.summary()).render(frames);
        } catch (SparkRenderException e) {
            err.println("raytracer: failed on Spark: " + Messages.visible(e.getMessage()));
            return 1;
        } catch (UncheckedIOException e) {
            err.println("raytracer: " + Messages.visible(e.getMessage()));
            return 1;
        } catch (OutOfMemoryError e) { // on the driver, outside the job: assembling, or the PNG's encoding
            long max = Runtime.getRuntime().maxMemory();
            err.println("raytracer: failed on Spark: the driver ran out of memory beside the job's images ("
                    + SparkRenderer.imageSizes(frames) + ")" + (max == Long.MAX_VALUE ? "" : "; Java may use at most "
                    + (max >> 20) + " MB there") + " (give the driver more memory with spark-submit --driver-memory, or -Xmx"
                    + " for a local master; or render it smaller)");
            return 1;
        }
        if (request.summary())
            for (SparkFrame f : frames)
                out.println(String.format(Locale.ROOT, "wrote %s (%dx%d) in %.2f s", f.output(), f.settings().width(),
                        f.settings().height(), (System.nanoTime() - start) / 1e9));
        return 0;
    }
}
