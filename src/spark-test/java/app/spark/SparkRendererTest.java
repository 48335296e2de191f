package app.spark;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.UnaryOperator;

import org.apache.spark.SparkConf;
import org.apache.spark.TaskContext;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerTaskStart;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import app.Project;
import renderer.AntiAliasing;
import renderer.ImageWriter;
import renderer.ImageWriters;
import scene.io.LoadedScene;
import scene.io.RenderSettings;
import scene.io.SceneFormatException;
import scene.io.XmlSceneReader;

/**
 * Spark renders in local mode ({@code local[2, 4]}: two executor threads, a task tried up to four
 * times) against the local renderer, compared as PNG bytes. The images are small (under 100×80)
 * and non-square, so that tiles of 16 pixels cut them unevenly and a swapped row and column would
 * show. One Spark context serves every test of the class.
 */
@EnabledWhereSparkRuns
class SparkRendererTest {
    private static final Path GLOSSY = Project.file("scenes/glossy.xml");
    private static final Path SHOWCASE = Project.file("scenes/showcase.xml");
    private static final Path TEAPOT = Project.file("scenes/teapot.xml");

    private static JavaSparkContext spark;

    @TempDir
    Path dir;

    @BeforeAll
    static void startSpark() {
        spark = new JavaSparkContext(new SparkConf().setMaster("local[2,4]").setAppName("SparkRendererTest")
                .set("spark.ui.enabled", "false").set("spark.log.level", "ERROR"));
    }

    @AfterAll
    static void stopSpark() {
        spark.stop();
    }

    /** The settings of a test: the file's, at a small size, changed by {@code change}. */
    private static RenderSettings small(RenderSettings file, UnaryOperator<RenderSettings> change) {
        return change.apply(file.withImage(file.imageName(), 83, 61));
    }

    /** The local render of {@code scene} with {@code settings}, as the command line does it: its PNG's bytes. */
    private byte[] local(Path scene, RenderSettings settings) throws IOException, SceneFormatException {
        LoadedScene loaded = XmlSceneReader.read(scene);
        ImageWriter image = settings.newImageWriter();
        var camera = settings.applyTo(loaded.requireView(), loaded.scene(), image).setSummary(false).build();
        camera.render();
        settings.drawGrid(camera);
        Path png = dir.resolve("local-" + settings.imageName() + ".png");
        image.writeToImage(png);
        return Files.readAllBytes(png);
    }

    private SparkRenderer renderer() {
        return new SparkRenderer(spark).setTileSize(16).setSummary(false);
    }

    static List<Arguments> modes() {
        return List.of(
                Arguments.of("NONE", SHOWCASE, (UnaryOperator<RenderSettings>) s -> s.withAntiAliasing(AntiAliasing.NONE)),
                Arguments.of("RANDOM 3x2", SHOWCASE, (UnaryOperator<RenderSettings>) s -> s
                        .withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(3, 2).withAdaptiveDepth(3)
                        .withAdaptiveThreshold(8)),
                Arguments.of("CORNERS", SHOWCASE, (UnaryOperator<RenderSettings>) s -> s.withAntiAliasing(AntiAliasing.CORNERS)),
                Arguments.of("ADAPTIVE depth 4", SHOWCASE, (UnaryOperator<RenderSettings>) s -> s
                        .withAntiAliasing(AntiAliasing.ADAPTIVE).withAntiAliasingGrid(4, 4).withAdaptiveDepth(4)
                        .withAdaptiveThreshold(4)),
                Arguments.of("depth of field", SHOWCASE, (UnaryOperator<RenderSettings>) s -> s
                        .withAntiAliasing(AntiAliasing.NONE).withDepthOfField(900, 8).withDepthOfFieldSamples(3)),
                Arguments.of("ADAPTIVE + depth of field", SHOWCASE, (UnaryOperator<RenderSettings>) s -> s
                        .withAntiAliasing(AntiAliasing.ADAPTIVE).withAntiAliasingGrid(4, 4).withAdaptiveDepth(2)
                        .withAdaptiveThreshold(4)
                        .withDepthOfField(900, 8)),
                Arguments.of("glossy wall, RANDOM 2x2, seed 7", GLOSSY, (UnaryOperator<RenderSettings>) s -> s
                        .withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(2, 2).withAdaptiveDepth(3)
                        .withAdaptiveThreshold(8).withSeed(7)),
                Arguments.of("OBJ mesh (teapot), grid", TEAPOT, (UnaryOperator<RenderSettings>) s -> s
                        .withGrid(10, RenderSettings.DEFAULT_GRID_COLOR)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("modes")
    @DisplayName("a Spark render is byte-identical to the local render")
    void sameBytesAsLocal(String name, Path scene, UnaryOperator<RenderSettings> change) throws Exception {
        SparkFrame frame = SparkFrame.read(scene);
        frame = frame.withSettings(small(frame.settings(), change)).withOutput(dir.resolve("spark.png"));
        renderer().render(List.of(frame));
        assertThat(Files.readAllBytes(dir.resolve("spark.png"))).isEqualTo(local(scene, frame.settings()));
    }

    @ParameterizedTest(name = "{0} partitions")
    @ValueSource(ints = { 1, 3, 7, 1000 })
    @DisplayName("the number of partitions changes no byte")
    void anyPartitionCount(int partitions) throws Exception {
        SparkFrame frame = SparkFrame.read(SHOWCASE);
        frame = frame.withSettings(small(frame.settings(), s -> s.withAntiAliasing(AntiAliasing.ADAPTIVE)))
                .withOutput(dir.resolve("spark.png"));
        SparkRenderStats stats = renderer().setPartitions(partitions).render(List.of(frame));
        assertThat(Files.readAllBytes(dir.resolve("spark.png"))).isEqualTo(local(SHOWCASE, frame.settings()));
        assertThat(stats.tiles()).isEqualTo(6 * 4); // 83x61 in tiles of 16
        assertThat(stats.tasks()).isEqualTo(Math.min(partitions, stats.tiles()));
    }

    @Test
    @DisplayName("frames: several scenes in one job, one PNG each, each equal to its local render")
    void frames() throws Exception {
        List<Path> scenes = List.of(SHOWCASE, GLOSSY, SHOWCASE);
        List<SparkFrame> frames = new java.util.ArrayList<>();
        for (int i = 0; i < scenes.size(); ++i) {
            SparkFrame f = SparkFrame.read(scenes.get(i));
            int seed = i;
            // The third frame is large enough to be split into several tiles, the others are one tile each.
            RenderSettings s = i == 2 ? f.settings().withImage("frame2", 40, 36)
                    : f.settings().withImage("frame" + i, 16, 12);
            frames.add(f.withSettings(s.withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(2, 2).withAdaptiveDepth(3)
                    .withAdaptiveThreshold(8).withSeed(seed)).withOutput(dir.resolve("frame" + i + ".png")));
        }
        SparkRenderStats stats = renderer().render(frames);
        assertThat(stats.frames()).isEqualTo(3);
        assertThat(stats.tiles()).isEqualTo(1 + 1 + 3 * 3);
        for (int i = 0; i < scenes.size(); ++i)
            assertThat(Files.readAllBytes(dir.resolve("frame" + i + ".png"))).as("frame %d", i)
                    .isEqualTo(local(scenes.get(i), frames.get(i).settings()));
    }

    @Nested
    @DisplayName("faults")
    class Faults {
        @Test
        @DisplayName("a task whose first attempt fails is retried, and the image is byte-identical")
        void retriedTask() throws Exception {
            SparkFrame frame = SparkFrame.read(SHOWCASE);
            frame = frame.withSettings(small(frame.settings(), s -> s.withAntiAliasing(AntiAliasing.CORNERS)))
                    .withOutput(dir.resolve("spark.png"));
            SparkRenderStats stats = renderer().setProbe(tile -> {
                TaskContext task = TaskContext.get();
                if (task.partitionId() == 5 && task.attemptNumber() == 0)
                    throw new IllegalStateException("injected failure of partition 5, attempt 0");
            }).render(List.of(frame));
            assertThat(Files.readAllBytes(dir.resolve("spark.png"))).isEqualTo(local(SHOWCASE, frame.settings()));
            assertThat(stats.retries()).isEqualTo(1);
            assertThat(stats.tasks()).isEqualTo(stats.tiles() + 1);
        }

        @Test
        @DisplayName("a task that fails every attempt ends the job with one line and no image")
        void exhaustedRetries() throws Exception {
            SparkFrame frame = SparkFrame.read(SHOWCASE);
            frame = frame.withSettings(small(frame.settings(), UnaryOperator.identity())).withOutput(dir.resolve("spark.png"));
            SparkRenderer failing = renderer().setProbe(tile -> {
                if (TaskContext.get().partitionId() == 2) throw new IllegalStateException("injected failure of partition 2");
            });
            List<SparkFrame> frames = List.of(frame);
            assertThatThrownBy(() -> failing.render(frames)).isInstanceOf(SparkRenderException.class)
                    .hasMessageContaining("failed 4 times").hasMessageContaining("injected failure of partition 2")
                    .hasMessageNotContaining("\n");
            assertThat(dir.resolve("spark.png")).doesNotExist();
        }
    }

    @Test
    @DisplayName("a bad scene fails on the driver with the local renderer's message, before any task")
    void badScene() throws IOException {
        Path bad = dir.resolve("bad.xml");
        Files.writeString(bad, "<scene>\n  <geometries>\n    <sphere center=\"0 0\" radius=\"1\"/>\n  </geometries>\n</scene>\n");
        AtomicInteger tasks = new AtomicInteger();
        SparkListener counter = new SparkListener() {
            @Override
            public void onTaskStart(SparkListenerTaskStart taskStart) {
                tasks.incrementAndGet();
            }
        };
        spark.sc().addSparkListener(counter);
        try {
            String expected = "";
            try {
                XmlSceneReader.read(bad);
            } catch (SceneFormatException e) {
                expected = e.getMessage();
            }
            assertThat(expected).startsWith(bad + ":3:");
            SparkRenderer renderer = renderer();
            Path png = dir.resolve("bad.png");
            assertThatThrownBy(() -> renderer.render(bad, png)).isInstanceOf(SceneFormatException.class)
                    .hasMessage(expected);
            assertThat(png).doesNotExist();
        } finally {
            spark.sc().removeSparkListener(counter);
        }
        assertThat(tasks).hasValue(0);
    }

    @Test
    @DisplayName("progress lines count tiles, in the local render's format, and the summary names executors, tasks and retries")
    void progressAndSummary() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        SparkFrame frame = SparkFrame.read(SHOWCASE);
        frame = frame.withSettings(small(frame.settings(), UnaryOperator.identity())).withOutput(dir.resolve("spark.png"));
        new SparkRenderer(spark).setTileSize(16).setProgress(25).setOutput(out).render(List.of(frame));
        List<String> lines = bytes.toString(StandardCharsets.UTF_8).lines().toList();
        assertThat(lines).hasSize(5);
        assertThat(lines.subList(0, 4)).allMatch(l -> l.matches(
                "spark render showcase: +\\d+\\.\\d%  \\d+/24 tiles  elapsed \\d+\\.\\d s  ETA \\d+\\.\\d s"), "progress lines");
        assertThat(lines.get(3)).contains("100.0%  24/24 tiles");
        assertThat(lines.get(4)).matches("spark render showcase: \\d+\\.\\d+ s, 83x61 \\[ADAPTIVE depth 3 threshold 8\\.0, .*")
                .contains(" 24 tiles ", "1 executor, 24 tasks, 0 retries");
    }

    @Nested
    @DisplayName("the driver's memory: the images allocated, and the results' size checked, before the job")
    class DriverMemory {
        @Test
        @DisplayName("an image larger than the driver's heap: refused, naming the MB and --driver-memory")
        void imageTooLarge() throws Exception {
            assumeTrue(ImageWriters.bytesNeeded(40_000, 40_000) > Runtime.getRuntime().maxMemory(), "the heap is above 6.4 GB");
            SparkFrame frame = SparkFrame.read(GLOSSY);
            frame = frame.withSettings(frame.settings().withImage("huge", 40_000, 40_000)).withOutput(dir.resolve("huge.png"));
            List<SparkFrame> frames = List.of(frame);
            // (With the default spark.driver.maxResultSize this job is refused for its results first.)
            assertThatThrownBy(() -> SparkRenderer.allocate("spark render huge", frames)).isInstanceOf(SparkRenderException.class)
                    .hasMessage("spark render huge: the driver cannot hold the image: image 40000x40000 needs 6104 MB; Java"
                            + " may use at most " + (Runtime.getRuntime().maxMemory() >> 20) + " MB here (give the driver"
                            + " more memory with spark-submit --driver-memory, or -Xmx for a local master; or render it"
                            + " smaller)");
        }

        @Test
        @DisplayName("the job's images are allocated before it starts: one per frame, of its size")
        void allocated() throws Exception {
            SparkFrame frame = SparkFrame.read(GLOSSY);
            List<ImageWriter> images = SparkRenderer.allocate("x", List.of(frame.withSettings(frame.settings().withImage("a", 30, 20)),
                    frame.withSettings(frame.settings().withImage("b", 10, 40))));
            assertThat(images).extracting(ImageWriter::getNx, ImageWriter::getNy)
                    .containsExactly(org.assertj.core.groups.Tuple.tuple(30, 20), org.assertj.core.groups.Tuple.tuple(10, 40));
        }

        @Test
        @DisplayName("pixels beyond spark.driver.maxResultSize (1 GiB by default): refused before any task, naming the setting")
        void resultsTooLarge() throws Exception {
            SparkFrame frame = SparkFrame.read(GLOSSY);
            frame = frame.withSettings(frame.settings().withImage("large", 17_000, 17_000)).withOutput(dir.resolve("large.png"));
            List<SparkFrame> frames = List.of(frame);
            SparkRenderer counting = renderer().setProbe(t -> {
                throw new IllegalStateException("a task started");
            });
            assertThatThrownBy(() -> counting.render(frames)).isInstanceOf(SparkRenderException.class)
                    .hasMessage("spark render large: the job's results are 1103 MB of pixels, more than"
                            + " spark.driver.maxResultSize (1024 MB) lets the driver receive: raise it (spark-submit --conf"
                            + " spark.driver.maxResultSize=3g, or 0 for no limit) or render it smaller");
            assertThat(dir.resolve("large.png")).doesNotExist();
            SparkRenderer.requireResultSize("x", frames, 0); // 0: no limit
            SparkRenderer.requireResultSize("x", frames, 2L << 30);
        }
    }
}
