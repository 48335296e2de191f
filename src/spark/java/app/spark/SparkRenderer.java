package app.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.io.Serializable;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.UUID;
import java.util.regex.Pattern;

import org.apache.spark.TaskContext;
import org.apache.spark.api.java.JavaRDD;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;

import renderer.ImageWriter;
import renderer.ImageWriters;
import renderer.Progress;
import scene.io.RenderSettings;
import scene.io.SceneFormatException;
import scala.Function2;
import scala.collection.Iterator;
import scala.jdk.javaapi.CollectionConverters;
import scala.reflect.ClassTag$;
import scala.runtime.BoxedUnit;

/**
 * Renders scene files on a Spark cluster, byte for byte as the local renderer does. The driver
 * has read and validated every scene ({@link SparkFrame#read(Path)}) before anything starts; it
 * broadcasts the scenes' files and settings, cuts each image into square tiles and runs one Spark
 * job whose tasks render groups of tiles with the library's own render loop ({@link
 * renderer.RegionRenderer}); each executor parses a scene once. The driver assembles every image
 * and writes its PNG atomically. Every random number of a render derives from (seed, pixel,
 * sample), so neither the tiling, nor the number of executors, nor a retried or speculative task
 * changes a pixel.
 *
 * <p>Many images (an animation's frames) are one job: their tiles are the tasks, so small frames
 * are one tile each and large frames are split. Each task's tiles go into the images as they
 * arrive, so the driver needs memory for the images of one call (4 bytes a pixel), allocated
 * before the job starts (a driver without it refuses at once), and the job's pixels must pass
 * {@code spark.driver.maxResultSize} (default 1 GiB; checked before the job too).
 */
public final class SparkRenderer {
    /**
     * The default tile side, in pixels: the render loop's own largest tile, so that an executor
     * re-traces no more lattice points on tile borders (CORNERS, ADAPTIVE) than the local render.
     */
    public static final int DEFAULT_TILE = 64;

    /**
     * The Spark setting of how long a job may go without any executor before the driver cancels
     * it (a time, as {@code 120s} or {@code 5m}; default 120 s): see {@link #setExecutorTimeout}.
     */
    public static final String EXECUTOR_TIMEOUT = "spark.raytracer.executorTimeout";

    private final JavaSparkContext spark;
    private double executorTimeout;
    private int tile = DEFAULT_TILE;
    private int partitions;
    private double progressStep;
    private PrintStream out = System.out;
    private boolean summary = true;
    private TileProbe probe = TileProbe.NONE;

    /**
     * @param spark the context whose cluster renders
     * @throws UnsupportedOperationException on a JDK Spark does not run on (see
     *                                       {@link #requireSupportedJava()})
     */
    public SparkRenderer(JavaSparkContext spark) {
        requireSupportedJava();
        this.spark = Objects.requireNonNull(spark, "spark context");
        this.executorTimeout = executorTimeout(spark.sc().getConf());
    }

    /**
     * The context's {@value #EXECUTOR_TIMEOUT}, checked as {@link #setExecutorTimeout} checks its
     * argument: a time Spark reads ({@code 120s}, {@code 5m}, {@code 500ms}) that is positive.
     * The command line asks it before Spark starts, so a bad value costs no context.
     *
     * @param conf the configuration (spark-submit's {@code --conf}, or {@code -Dspark.…})
     * @return the timeout in seconds, &gt; 0; 120 when it is not set
     * @throws IllegalArgumentException naming the setting and the value, for one that is not a
     *                                  time or not positive
     */
    static double executorTimeout(SparkConf conf) {
        String given = conf.get(EXECUTOR_TIMEOUT, "120s");
        long millis;
        try {
            // A bare number is seconds, as Spark's getTimeAsSeconds reads it (getTimeAsMs would take milliseconds).
            millis = given.trim().matches("-?\\d+") ? Math.multiplyExact(Long.parseLong(given.trim()), 1000L)
                    : conf.getTimeAsMs(EXECUTOR_TIMEOUT, "120s");
        } catch (NumberFormatException | ArithmeticException e) {
            throw new IllegalArgumentException(EXECUTOR_TIMEOUT + " '" + given + "' is not a time (expected a positive"
                    + " time such as 120s, 5m or 500ms)", e);
        }
        if (millis <= 0)
            throw new IllegalArgumentException(EXECUTOR_TIMEOUT + " '" + given + "' is not positive (expected a positive"
                    + " time such as 120s, 5m or 500ms)");
        return millis / 1000.0;
    }

    /**
     * How long a job may go without any executor (every worker lost, or none granted) before the
     * driver cancels it with {@link SparkRenderException}; the progress says when it starts
     * waiting. Spark itself would wait without end. A local master always has its executor.
     *
     * @param seconds the limit, &gt; 0 (default: {@value #EXECUTOR_TIMEOUT} of the context's
     *                configuration, else 120)
     * @return this renderer
     * @throws IllegalArgumentException for a limit that is not positive
     */
    public SparkRenderer setExecutorTimeout(double seconds) {
        if (!(seconds > 0)) throw new IllegalArgumentException("executor timeout must be positive seconds, got " + seconds);
        this.executorTimeout = seconds;
        return this;
    }

    /**
     * Checks that Spark runs on this JDK. Call it before making the {@code JavaSparkContext}: on a
     * JDK Spark 4.0 does not support (after Java 21), the context itself fails while starting, with
     * an error from Hadoop's security code that names neither the JDK nor a remedy.
     *
     * @throws UnsupportedOperationException naming this JDK, the JDKs Spark runs on and what to do
     */
    public static void requireSupportedJava() {
        SparkJdk.unsupported().ifPresent(why -> {
            throw new UnsupportedOperationException(why);
        });
    }

    /**
     * @param pixels the tile side, a positive multiple of 16; no pixel depends on it, only the
     *               balance of the work (smaller tiles: more, shorter tasks) and the lattice points
     *               re-traced on tile borders
     * @return this renderer
     * @throws IllegalArgumentException for another value
     */
    public SparkRenderer setTileSize(int pixels) {
        if (pixels < 16 || pixels % 16 != 0)
            throw new IllegalArgumentException("tile size must be a positive multiple of 16 pixels, got " + pixels);
        this.tile = pixels;
        return this;
    }

    /**
     * @param count the number of tasks of a job, each rendering a run of consecutive tiles; 0 (the
     *              default): one task per tile. More partitions than tiles make one per tile.
     * @return this renderer
     * @throws IllegalArgumentException for a negative count
     */
    public SparkRenderer setPartitions(int count) {
        if (count < 0) throw new IllegalArgumentException("partition count must be 0 (one per tile) or positive, got " + count);
        this.partitions = count;
        return this;
    }

    /**
     * @param percentStep print a progress line (tiles done of all, elapsed time, ETA) each time
     *                    this much more is done, in (0, 100]; 0 (the default): none
     * @return this renderer
     * @throws IllegalArgumentException for a step outside [0, 100]
     */
    public SparkRenderer setProgress(double percentStep) {
        if (!(percentStep >= 0 && percentStep <= 100))
            throw new IllegalArgumentException("progress step must be in [0, 100] percent, got " + percentStep);
        this.progressStep = percentStep;
        return this;
    }

    /**
     * @param output where progress lines and the summary go (default System.out)
     * @return this renderer
     */
    public SparkRenderer setOutput(PrintStream output) {
        this.out = Objects.requireNonNull(output, "output stream");
        return this;
    }

    /**
     * @param on whether to print the summary line of each job (default true)
     * @return this renderer
     */
    public SparkRenderer setSummary(boolean on) {
        this.summary = on;
        return this;
    }

    /** The test seam of the fault-injection tests. */
    SparkRenderer setProbe(TileProbe probe) {
        this.probe = Objects.requireNonNull(probe, "probe");
        return this;
    }

    /**
     * Renders a scene file with its own settings into {@code png}.
     *
     * @param scene the scene file
     * @param png   the image to write
     * @return what the job did
     * @throws IOException           when the scene file cannot be read (nothing started)
     * @throws SceneFormatException  when it is not a valid scene (nothing started)
     * @throws SparkRenderException  when a task failed more often than Spark retries it (no image)
     */
    public SparkRenderStats render(Path scene, Path png) throws IOException, SceneFormatException {
        return render(List.of(SparkFrame.read(scene).withOutput(png)));
    }

    /**
     * Renders frames read and validated before (see {@link SparkFrame#read(Path)}) in one job
     * and writes each one's PNG.
     *
     * @param frames the images to render, at least one
     * @return what the job did
     * @throws SparkRenderException  when a task failed more often than Spark retries it; no PNG
     *                               was written. Before anything starts: when the images' pixels
     *                               are more than {@code spark.driver.maxResultSize}, or the images
     *                               do not fit the driver's heap (one line naming the MB and the
     *                               setting to raise)
     * @throws java.io.UncheckedIOException when a PNG cannot be written
     * @throws IllegalArgumentException for an empty list
     */
    public SparkRenderStats render(List<SparkFrame> frames) {
        if (frames.isEmpty()) throw new IllegalArgumentException("no frame to render");
        long start = System.nanoTime();
        List<Frame> sent = new ArrayList<>(frames.size());
        List<Tile> tiles = new ArrayList<>();
        long broadcastBytes = 0;
        for (SparkFrame f : frames) {
            RenderSettings s = f.settings();
            tiles.addAll(Tile.cut(sent.size(), s.width(), s.height(), tile));
            sent.add(f.frame());
            broadcastBytes += f.frame().files().size();
        }
        String label = "spark render " + (frames.size() == 1 ? frames.get(0).settings().imageName() : frames.size() + " frames");
        List<List<Tile>> groups = groups(tiles, partitions == 0 ? tiles.size() : Math.min(partitions, tiles.size()));
        // Before anything starts: the results must pass Spark's limit, and the images and the
        // job's tasks fit the driver.
        requireResultSize(label, frames, spark.sc().getConf().getSizeAsBytes(MAX_RESULT_SIZE, "1g"));
        requireDriverMemory(label, frames, groups.size(), Runtime.getRuntime().maxMemory(), live(frames, groups.size()));
        Assembly assembly = new Assembly(allocate(label, frames), tiles.size());
        Progress progress = new Progress(label, tiles.size(), "tiles", progressStep, out);
        JobMonitor monitor = new JobMonitor("raytracer-" + UUID.randomUUID(),
                groups.stream().mapToInt(List::size).toArray(), progress);

        run(new FrameSet(sent), groups, monitor, label, assembly, imageSizes(frames));
        double renderSeconds = (System.nanoTime() - start) / 1e9;
        long pixels = write(frames, assembly.images);

        double[] tileSeconds = assembly.tileSeconds();
        SparkRenderStats stats = new SparkRenderStats(renderSeconds, frames.size(), pixels, tiles.size(), assembly.rays,
                broadcastBytes, monitor.executors(), monitor.attempts(), monitor.retries(), tileSeconds);
        if (summary) {
            RenderSettings s = frames.get(0).settings();
            out.println(label + ": " + stats.summary(frames.size() == 1 ? s.width() + "x" + s.height() + " ["
                    + frames.get(0).describe() + "]" : null));
        }
        return stats;
    }

    /** Spark's limit of the results of one job, on the driver (default 1g; 0: none). */
    static final String MAX_RESULT_SIZE = "spark.driver.maxResultSize";

    /**
     * Refuses a job whose pixels alone are more than {@code limit} bytes ({@value #MAX_RESULT_SIZE};
     * 0: no limit): Spark would abort it when the results passed the limit, after rendering that
     * much on the cluster.
     *
     * @throws SparkRenderException naming the bytes, the limit and how to raise it
     */
    static void requireResultSize(String label, List<SparkFrame> frames, long limit) {
        long bytes = 0;
        for (SparkFrame f : frames) bytes += ImageWriters.bytesNeeded(f.settings().width(), f.settings().height());
        if (limit <= 0 || bytes <= limit) return;
        long mb = 1 << 20, gb = 1 << 30;
        throw new SparkRenderException(label + ": the job's results are " + (bytes + mb - 1) / mb + " MB of pixels, more than "
                + MAX_RESULT_SIZE + " (" + limit / mb + " MB) lets the driver receive: raise it (spark-submit --conf "
                + MAX_RESULT_SIZE + "=" + ((bytes + gb - 1) / gb + 1) + "g, or 0 for no limit) or render it smaller", null);
    }

    /**
     * What the driver holds for each task of a job, measured: the task, its partition and tiles,
     * its serialized form while it is sent, and what Spark keeps of it once done (its TaskInfo,
     * the status store's record). Measured in local[1] with the UI on (as spark-submit has it),
     * the heap after full collections while the job's last task ran, less the images: 4,886 KB at
     * 2,500 tasks, 16,872 KB at 10,000, 36,907 KB at 22,500, that is 1,641 to 1,675 bytes a task
     * and about 0.8 MB besides; the pixels add nothing beyond the images' 4 bytes (2,500 tasks of
     * 64² pixels held 267 KB more than 2,500 of 16², 0.03 bytes a pixel). At the first task it is
     * about 530 bytes a task: what Spark keeps of a finished task is most of it. BENCHMARKS.md,
     * "Spark: the driver's memory per task", has the figures and how they were taken.
     */
    static final long BYTES_PER_TASK = 1700;
    /** What a job holds on the driver besides its images and tasks (measured 0.8 MB, above), rounded up. */
    static final long HEADROOM_BYTES = 1L << 20;

    /** @return the bytes a job of {@code frames} in {@code tasks} tasks needs on the driver: its images, its tasks and the headroom */
    static long driverBytesNeeded(List<SparkFrame> frames, int tasks) {
        long bytes = HEADROOM_BYTES + tasks * BYTES_PER_TASK;
        for (SparkFrame f : frames) bytes += ImageWriters.bytesNeeded(f.settings().width(), f.settings().height());
        return bytes;
    }

    /**
     * Refuses, before the images are allocated and any task exists, a job the driver cannot hold
     * (a 462 MB image on a 512 MB driver: Spark's "Task serialization failed:
     * java.lang.OutOfMemoryError" after the image was allocated, before).
     *
     * @param max  the driver's heap limit ({@link Runtime#maxMemory()}; {@link Long#MAX_VALUE}: none)
     * @param live the bytes the driver holds already (Spark's own included)
     * @throws SparkRenderException naming the images, the tasks, the memory needed, the limit, what
     *                              was free and --driver-memory
     */
    static void requireDriverMemory(String label, List<SparkFrame> frames, int tasks, long max, long live) {
        long needed = driverBytesNeeded(frames, tasks);
        if (max == Long.MAX_VALUE || needed <= max - live) return;
        long mb = 1 << 20;
        throw new SparkRenderException(label + ": the driver cannot hold the job: its images (" + imageSizes(frames)
                + ") and " + tasks + " task" + (tasks == 1 ? "" : "s") + " (about " + (tasks * BYTES_PER_TASK + mb - 1) / mb
                + " MB) need about " + (needed + mb - 1) / mb + " MB; Java may use at most "
                + max / mb + " MB here, of which about " + Math.max(0, max - live) / mb + " MB were free (give the driver"
                + " more memory with spark-submit --driver-memory, or -Xmx for a local master; or render it smaller)", null);
    }

    /**
     * The bytes the driver holds now, as far as a job needing {@link #driverBytesNeeded} must
     * know: what is in use, and when that leaves too little, what is in use after one full
     * collection (garbage counts as in use until then; a collection costs a fraction of a second,
     * against a job that fails after the cluster rendered).
     */
    private static long live(List<SparkFrame> frames, int tasks) {
        Runtime runtime = Runtime.getRuntime();
        long used = runtime.totalMemory() - runtime.freeMemory();
        if (runtime.maxMemory() == Long.MAX_VALUE || driverBytesNeeded(frames, tasks) <= runtime.maxMemory() - used) return used;
        System.gc(); // only before refusing a job for lack of memory
        return runtime.totalMemory() - runtime.freeMemory();
    }

    /**
     * The images of the job, allocated before it starts, so that a driver without the memory for
     * them refuses at once instead of after the cluster rendered every tile.
     *
     * @throws SparkRenderException naming the image, the memory it needs and how to give it
     */
    static List<ImageWriter> allocate(String label, List<SparkFrame> frames) {
        List<ImageWriter> images = new ArrayList<>(frames.size());
        for (SparkFrame f : frames) {
            try {
                images.add(f.settings().newImageWriter());
            } catch (OutOfMemoryError e) {
                images.clear(); // the memory of the frames before goes back
                RenderSettings s = f.settings();
                throw new SparkRenderException(label + ": the driver cannot hold the image: "
                        + ImageWriters.memoryNeeded(s.width(), s.height()) + (frames.size() > 1 ? " for this frame alone"
                        : "") + " (give the driver more memory with spark-submit --driver-memory, or -Xmx for a local"
                        + " master; or render it smaller)", e);
            }
        }
        return images;
    }

    /**
     * Puts each partition's tiles into the images as its result arrives (on Spark's scheduler
     * thread), so that the driver holds the images and the results in flight, not every tile of
     * the job besides; keeps what the summary needs of them.
     */
    private static final class Assembly {
        final List<ImageWriter> images;
        private final double[] seconds;
        private int tiles;
        long rays;

        Assembly(List<ImageWriter> images, int tileCount) {
            this.images = images;
            this.seconds = new double[tileCount];
        }

        synchronized void add(List<TilePixels> results) {
            for (TilePixels r : results) {
                Tile t = r.tile();
                ImageWriters.writeTile(images.get(t.frame()), t.x0(), t.y0(), t.x1() - t.x0(), t.y1() - t.y0(), r.rgb());
                seconds[tiles++] = r.seconds();
                rays += r.rays();
            }
        }

        synchronized double[] tileSeconds() {
            double[] sorted = Arrays.copyOf(seconds, tiles);
            Arrays.sort(sorted);
            return sorted;
        }
    }

    /**
     * The Spark job: broadcasts the frames, renders every group of tiles in a task of its own and
     * hands each group's pixels to {@code assembly} as they arrive.
     *
     * @throws SparkRenderException when the job fails (a task failed every attempt)
     */
    private void run(FrameSet frames, List<List<Tile>> groups, JobMonitor monitor, String label, Assembly assembly,
                     String images) {
        Broadcast<FrameSet> scenes = spark.broadcast(frames);
        spark.sc().addSparkListener(monitor);
        spark.setJobGroup(monitor.jobGroup(), label, false);
        TileProbe p = probe; // the task's closure captures locals only, not this renderer
        ExecutorWatch watch = new ExecutorWatch(cluster(monitor.jobGroup()), executorTimeout, System::nanoTime,
                line -> {
                    if (progressStep > 0) out.println(label + ": " + line);
                });
        Thread watching = watching(watch, monitor, label);
        try {
            JavaRDD<List<TilePixels>> rendered = spark.parallelize(groups, groups.size()).map(g -> {
                List<TilePixels> done = new ArrayList<>(g.size());
                for (Tile t : g) {
                    p.beforeTile(t);
                    done.add(scenes.value().render(t));
                }
                return done;
            });
            List<Object> all = new ArrayList<>(groups.size());
            for (int i = 0; i < groups.size(); ++i) all.add(i);
            spark.sc().runJob(rendered.rdd(), (Function2<TaskContext, Iterator<List<TilePixels>>, List<TilePixels>> & Serializable)
                            (context, partition) -> partition.next(),
                    CollectionConverters.asScala(all).toSeq(),
                    (Function2<Object, List<TilePixels>, BoxedUnit> & Serializable) (index, result) -> {
                        assembly.add(result);
                        return BoxedUnit.UNIT;
                    },
                    ClassTag$.MODULE$.apply(List.class));
            monitor.awaitAll(10_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SparkRenderException(label + ": interrupted", e);
        } catch (Exception e) { // SparkException is checked in Java's eyes but undeclared
            String reason = watch.reason();
            if (reason == null) reason = driverOutOfMemory(e, images, Runtime.getRuntime().maxMemory());
            throw new SparkRenderException(label + ": " + (reason != null ? reason : firstLine(e)), e);
        } finally {
            watching.interrupt();
            spark.clearJobGroup();
            spark.sc().removeSparkListener(monitor);
            scenes.destroy();
        }
    }

    /** The context's executors, the driver not counted (a local master counts as one), and its job group's cancel. */
    private ExecutorWatch.Cluster cluster(String jobGroup) {
        return new ExecutorWatch.Cluster() {
            @Override
            public int executors() {
                return spark.sc().isLocal() ? 1 : spark.sc().statusTracker().getExecutorInfos().length - 1;
            }

            @Override
            public void cancel(String reason) {
                spark.sc().cancelJobGroup(jobGroup, reason);
            }
        };
    }

    /**
     * A daemon thread that waits until Spark has the job (a watch started before would count the
     * time before the submission, and a timeout shorter than that would let the job run on), then
     * checks {@code watch} every half second until it is interrupted or cancels the job.
     */
    private static Thread watching(ExecutorWatch watch, JobMonitor monitor, String label) {
        Thread t = new Thread(() -> {
            try {
                monitor.awaitJobStart();
                while (!watch.check()) Thread.sleep(500);
            } catch (InterruptedException e) {
                // the job ended
            }
        }, "executor watch of " + label);
        t.setDaemon(true);
        t.start();
        return t;
    }

    /**
     * Draws the grid each frame's settings may ask for over its assembled image and writes its
     * PNG atomically.
     *
     * @return the pixels of all frames
     */
    private static long write(List<SparkFrame> frames, List<ImageWriter> images) {
        long pixels = 0;
        for (int i = 0; i < frames.size(); ++i) {
            SparkFrame f = frames.get(i);
            f.settings().drawGrid(f.camera(images.get(i)));
            images.get(i).writeToImage(f.output());
            images.set(i, null); // written: its memory can go
            pixels += (long) f.settings().width() * f.settings().height();
        }
        return pixels;
    }

    /** Consecutive runs of tiles, {@code count} of them, as even as can be. */
    private static List<List<Tile>> groups(List<Tile> tiles, int count) {
        List<List<Tile>> groups = new ArrayList<>(count);
        for (int i = 0; i < count; ++i)
            groups.add(new ArrayList<>(tiles.subList((int) ((long) i * tiles.size() / count),
                    (int) ((long) (i + 1) * tiles.size() / count))));
        return groups;
    }

    /** @return the job's images and the memory they hold on the driver, as "11000x11000, 462 MB" */
    static String imageSizes(List<SparkFrame> frames) {
        long bytes = 0;
        StringBuilder sizes = new StringBuilder();
        for (SparkFrame f : frames) {
            RenderSettings s = f.settings();
            bytes += ImageWriters.bytesNeeded(s.width(), s.height());
            if (sizes.length() > 0) sizes.append(" + ");
            sizes.append(s.width()).append('x').append(s.height());
        }
        long mb = 1 << 20;
        return sizes + ", " + (bytes + mb - 1) / mb + " MB";
    }

    /** How Spark's job failure names a task that failed on an executor. */
    private static final Pattern TASK_FAILED = Pattern.compile("Lost task|failed \\d+ times?, most recent failure");

    /**
     * The one line for a job that failed because the driver ran out of memory (Spark reports it
     * as the job's failure, with the error's trace in its message: a task that could not be
     * serialized beside the job's images, say), or an executor did (a task that failed on it with
     * the error), or null for another failure.
     *
     * @param e      the job's failure
     * @param images {@link #imageSizes}
     * @param max    the driver's heap limit ({@link Runtime#maxMemory()})
     * @return the reason, naming the images, the limit and --driver-memory (an executor's:
     *         --executor-memory); null when the failure was not a lack of memory
     */
    static String driverOutOfMemory(Throwable e, String images, long max) {
        boolean oom = false;
        for (Throwable t = e; t != null && !oom; t = t.getCause())
            oom = t instanceof OutOfMemoryError || (t.getMessage() != null && t.getMessage().contains("java.lang.OutOfMemoryError"));
        if (!oom) return null;
        String message = e.getMessage() == null ? "" : e.getMessage();
        // A task that failed on an executor carries the executor's error in the job's message
        // too: that lack of memory was the executor's, and the driver's memory would not help.
        if (!message.contains("Task serialization failed") && TASK_FAILED.matcher(message).find())
            return "an executor ran out of memory rendering the job's tiles (give the executors more memory with"
                    + " spark-submit --executor-memory, or -Xmx for a local master; or render it smaller)";
        return "the driver ran out of memory " + (message.contains("Task serialization failed") ? "serializing the job's tasks"
                : "during the job") + " beside the job's images (" + images + ")"
                + (max == Long.MAX_VALUE ? "" : "; Java may use at most " + (max >> 20) + " MB there")
                + " (give the driver more memory with spark-submit --driver-memory, or -Xmx for a local master; or render"
                + " it smaller)";
    }

    /** The first line of an exception's message (Spark's carry a stack trace), or its class. */
    static String firstLine(Throwable e) {
        String m = e.getMessage();
        if (m == null || m.isBlank()) return e.getClass().getSimpleName();
        return m.lines().findFirst().orElse(m).trim();
    }
}
