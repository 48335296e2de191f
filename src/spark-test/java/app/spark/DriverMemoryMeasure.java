package app.spark;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;

import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;

/**
 * Measures what the driver holds per task of a {@link SparkRenderer} job (the figure behind
 * {@link SparkRenderer#BYTES_PER_TASK}; BENCHMARKS.md, "The driver's memory per task"): in
 * local[1], for jobs of 2,500 to 22,500 tasks, the heap after full collections while the job's
 * first and then its last task runs (the task held by a probe), less the heap before the job and
 * less the images. Not a test (no *Test name): run from the project folder after
 * {@code mvn -Pspark test-compile}, with Spark's jars and its JVM flags:
 * {@code java -Xmx2g <spark.jvm.args> -cp target/test-classes:target/classes:<Spark's jars>/* app.spark.DriverMemoryMeasure [ui: true|false]}.
 */
final class DriverMemoryMeasure {
    static final AtomicInteger calls = new AtomicInteger();
    static volatile int stopAt;
    static volatile CountDownLatch reached, release;

    static long used() {
        for (int i = 0; i < 3; ++i) System.gc();
        Runtime r = Runtime.getRuntime();
        return r.totalMemory() - r.freeMemory();
    }

    private DriverMemoryMeasure() {
    }

    public static void main(String[] args) throws Exception {
        String ui = args.length > 0 ? args[0] : "true";
        SparkConf conf = new SparkConf().setMaster("local[1]").setAppName("measure").set("spark.ui.enabled", ui)
                .set("spark.log.level", "ERROR");
        try (JavaSparkContext spark = new JavaSparkContext(conf)) {
            SparkFrame base = SparkFrame.read(Path.of("scenes/two-colors.xml"));
            // warm-up job, so that one-time structures exist before measuring
            run(spark, base, 64, 64, 16, -1);
            int[][] cases = { { 800, 800, 16 }, { 1600, 1600, 16 }, { 2400, 2400, 16 }, { 3200, 3200, 64 } };
            for (int[] c : cases) {
                for (String where : List.of("first", "last")) {
                    int tiles = ((c[0] + c[2] - 1) / c[2]) * ((c[1] + c[2] - 1) / c[2]);
                    long before = used();
                    reached = new CountDownLatch(1);
                    release = new CountDownLatch(1);
                    long[] at = new long[1];
                    Thread t = new Thread(() -> {
                        try {
                            run(spark, base, c[0], c[1], c[2], where.equals("first") ? 1 : tiles);
                        } catch (Exception e) {
                            e.printStackTrace();
                        }
                    });
                    t.start();
                    reached.await();
                    at[0] = used();
                    release.countDown();
                    t.join();
                    long image = 4L * c[0] * c[1];
                    long perTask = (at[0] - before - image) / tiles;
                    System.out.flush();
                    System.out.printf("%dx%d tile %d: %d tasks, at %s task: heap +%d KB, image %d KB, rest %d KB = %d bytes/task%n",
                            c[0], c[1], c[2], tiles, where, (at[0] - before) >> 10, image >> 10, (at[0] - before - image) >> 10, perTask);
                }
            }
        }
    }

    /** Where the renders go: a temporary file, deleted at exit. */
    private static final Path out = temporaryPng();

    private static Path temporaryPng() {
        try {
            Path png = java.nio.file.Files.createTempFile("driver-memory", ".png");
            png.toFile().deleteOnExit();
            return png;
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** Renders a {@code w} × {@code h} image of {@code base} in tiles of {@code tile}, holding the {@code stop}th tile. */
    static void run(JavaSparkContext spark, SparkFrame base, int w, int h, int tile, int stop) throws Exception {
        calls.set(0);
        stopAt = stop;
        SparkFrame f = base.withSettings(base.settings().withImage("m", w, h)).withOutput(out);
        new SparkRenderer(spark).setTileSize(tile).setSummary(false).setProbe(x -> {
            if (calls.incrementAndGet() == stopAt) {
                reached.countDown();
                try {
                    release.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }).render(List.of(f));
    }
}
