package app.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.UUID;

import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;

import renderer.ImageWriter;
import renderer.Progress;
import scene.io.RenderSettings;
import scene.io.SceneFormatException;

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
 * are one tile each and large frames are split. The results come back to the driver at the end
 * of the job, so the driver needs memory for all the images of one call (4 bytes a pixel).
 */
public final class SparkRenderer {
    /**
     * The default tile side, in pixels: the render loop's own largest tile, so that an executor
     * re-traces no more lattice points on tile borders (CORNERS, ADAPTIVE) than the local render.
     */
    public static final int DEFAULT_TILE = 64;

    private final JavaSparkContext spark;
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
     *                               was written
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
        Progress progress = new Progress(label, tiles.size(), "tiles", progressStep, out);
        List<List<Tile>> groups = groups(tiles, partitions == 0 ? tiles.size() : Math.min(partitions, tiles.size()));
        JobMonitor monitor = new JobMonitor("raytracer-" + UUID.randomUUID(),
                groups.stream().mapToInt(List::size).toArray(), progress);

        List<TilePixels> results = run(new FrameSet(sent), groups, monitor, label);
        double renderSeconds = (System.nanoTime() - start) / 1e9;
        long pixels = write(frames, results);

        double[] tileSeconds = new double[results.size()];
        long rays = 0;
        for (int i = 0; i < results.size(); ++i) {
            tileSeconds[i] = results.get(i).seconds();
            rays += results.get(i).rays();
        }
        Arrays.sort(tileSeconds);
        SparkRenderStats stats = new SparkRenderStats(renderSeconds, frames.size(), pixels, tiles.size(), rays,
                broadcastBytes, monitor.executors(), monitor.attempts(), monitor.retries(), tileSeconds);
        if (summary) {
            RenderSettings s = frames.get(0).settings();
            out.println(label + (frames.size() == 1 ? " " + s.width() + "x" + s.height() + " [" + frames.get(0).describe() + "]" : "")
                    + ": " + stats);
        }
        return stats;
    }

    /**
     * The Spark job: broadcasts the frames, renders every group of tiles in a task of its own and
     * brings the pixels back.
     *
     * @throws SparkRenderException when the job fails (a task failed every attempt)
     */
    private List<TilePixels> run(FrameSet frames, List<List<Tile>> groups, JobMonitor monitor, String label) {
        Broadcast<FrameSet> scenes = spark.broadcast(frames);
        spark.sc().addSparkListener(monitor);
        spark.setJobGroup(monitor.jobGroup(), label, false);
        TileProbe p = probe; // the task's closure captures locals only, not this renderer
        try {
            List<TilePixels> results = spark.parallelize(groups, groups.size()).flatMap(g -> {
                List<TilePixels> done = new ArrayList<>(g.size());
                for (Tile t : g) {
                    p.beforeTile(t);
                    done.add(scenes.value().render(t));
                }
                return done.iterator();
            }).collect();
            monitor.awaitAll(10_000);
            return results;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SparkRenderException(label + ": interrupted", e);
        } catch (Exception e) { // SparkException is checked in Java's eyes but undeclared
            throw new SparkRenderException(label + ": " + firstLine(e), e);
        } finally {
            spark.clearJobGroup();
            spark.sc().removeSparkListener(monitor);
            scenes.destroy();
        }
    }

    /**
     * Assembles each frame from its tiles, draws the grid its settings may ask for and writes its
     * PNG atomically.
     *
     * @return the pixels of all frames
     */
    private static long write(List<SparkFrame> frames, List<TilePixels> results) {
        List<ImageWriter> images = new ArrayList<>(frames.size());
        for (SparkFrame f : frames) images.add(f.settings().newImageWriter());
        for (TilePixels r : results) {
            Tile t = r.tile();
            images.get(t.frame()).writeTile(t.x0(), t.y0(), t.x1() - t.x0(), t.y1() - t.y0(), r.rgb());
        }
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

    /** The first line of an exception's message (Spark's carry a stack trace), or its class. */
    private static String firstLine(Throwable e) {
        String m = e.getMessage();
        if (m == null || m.isBlank()) return e.getClass().getSimpleName();
        return m.lines().findFirst().orElse(m).trim();
    }
}
