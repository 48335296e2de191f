package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * What a camera prints when it renders and writes: a summary line naming the image (whichever
 * course year's flow named it) with the render's figures, then a line with the written file and
 * the time the write took.
 */
class SummaryLineTest {
    /** A course-style camera over an empty scene, printing into {@code out}; no writer yet. */
    private static Camera.Builder camera(PrintStream out) {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(4, 4).setVpDistance(1).setRayTracer(new RayTracerBasic(new Scene("summary")))
                .setOutput(out);
    }

    /** Runs {@code use} with a camera builder and returns the lines it printed. */
    private static List<String> printed(Consumer<Camera.Builder> use) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        use.accept(camera(out));
        return bytes.toString(StandardCharsets.UTF_8).lines().toList();
    }

    @Nested
    @DisplayName("the image's name")
    class Naming {
        @Test
        @DisplayName("2023–24: the name given to the ImageWriter")
        void writerName() {
            assertThat(printed(b -> b.setImageWriter(new ImageWriter("named", 4, 4)).build().render()))
                    .singleElement().asString().matches("render named: \\d+\\.\\d{3} s, 4x4 \\[NONE, .*");
        }

        @Test
        @DisplayName("2024–25 (setResolution, named only when written): the calling test method")
        void testName() {
            assertThat(printed(b -> b.setResolution(4, 4).build().render()))
                    .singleElement().asString().startsWith("render SummaryLineTest.Naming.testName(): ").contains(" s, 4x4 [NONE, ");
        }

        @ParameterizedTest(name = "render {0}")
        @ValueSource(ints = {1, 2})
        @DisplayName("a parameterized test is a test too")
        void parameterizedTestName(int run) {
            assertThat(printed(b -> b.setResolution(4, 4).build().render())).singleElement().asString()
                    .startsWith("render SummaryLineTest.Naming.parameterizedTestName(): ").contains(" s, 4x4 [");
        }

        @Test
        @DisplayName("outside a test method (here: a thread of its own): (unnamed)")
        void outsideATest() throws InterruptedException {
            AtomicReference<List<String>> lines = new AtomicReference<>();
            Thread main = new Thread(() -> lines.set(printed(b -> b.setResolution(4, 4).build().render())));
            main.start();
            main.join();
            assertThat(lines.get()).singleElement().asString().startsWith("render (unnamed): ").contains(" s, 4x4 [");
        }

        @Test
        @DisplayName("the scene's name follows the settings; a camera given no tracer renders the builder's empty scene")
        void sceneName() {
            assertThat(printed(b -> b.setRayTracer(new RayTracerBasic(new Scene("Two spheres"))).build().render()))
                    .singleElement().asString().startsWith("render SummaryLineTest.Naming.sceneName(): ").contains(" s, 1x1 [NONE, ")
                    .contains(", seed 0] of scene 'Two spheres', 1 px, ");
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Vector.AXIS_Y).setVpSize(1, 1)
                    .setVpDistance(1).setOutput(new PrintStream(bytes, true, StandardCharsets.UTF_8)).build().render();
            assertThat(bytes.toString(StandardCharsets.UTF_8)).contains("] of scene 'empty scene', ");
        }
    }

    @Nested
    @DisplayName("writing")
    class Writing {
        @Test
        @DisplayName("render, then write: the second line gives the file's absolute path and the write time")
        void writeLine() throws Exception {
            Path file = Path.of("images", "summary", "written.png");
            Files.deleteIfExists(file);
            List<String> lines = printed(b -> b.setImageWriter(new ImageWriter("summary/written", 4, 4)).build()
                    .renderImage().writeToImage());
            assertThat(lines).hasSize(2);
            assertThat(lines.get(0)).startsWith("render summary/written: ").contains(" s, 4x4 [");
            assertThat(lines.get(1)).matches("write summary/written: \\S+ in \\d+\\.\\d{3} s")
                    .contains(" " + file.toAbsolutePath() + " in ");
            assertThat(file).isRegularFile();
            Files.delete(file);
        }

        @Test
        @DisplayName("2024–25: both lines carry the test's name, the write line the file named at last")
        void courseYear5785() throws Exception {
            Path file = Path.of("images", "summary", "5785.png");
            List<String> lines = printed(b -> b.setResolution(4, 4).build().renderImage().writeToImage("summary/5785"));
            assertThat(lines).hasSize(2);
            assertThat(lines.get(0)).startsWith("render SummaryLineTest.Writing.courseYear5785(): ");
            assertThat(lines.get(1)).startsWith("write SummaryLineTest.Writing.courseYear5785(): " + file.toAbsolutePath() + " in ");
            Files.delete(file);
        }

        @Test
        @DisplayName("a write of an image nothing was drawn on says so on its line, and still writes the PNG")
        void blankImage() throws Exception {
            Path file = Path.of("images", "summary", "blank.png");
            List<String> lines = printed(b -> b.setImageWriter(new ImageWriter("summary/blank", 4, 4)).build().writeToImage());
            assertThat(lines).singleElement().asString().startsWith("write summary/blank: ")
                    .endsWith(" s (nothing was drawn on this image (no render, grid or writePixel before the write):"
                            + " its PNG is all black)");
            assertThat(file).isRegularFile();
            Files.delete(file);
        }

        @Test
        @DisplayName("the course's grid test draws only the grid: its write line is the usual one")
        void gridOnly() throws Exception {
            Path file = Path.of("images", "summary", "grid.png");
            List<String> lines = printed(b -> b.setImageWriter(new ImageWriter("summary/grid", 4, 4)).build()
                    .printGrid(2, new primitives.Color(255, 0, 0)).writeToImage());
            assertThat(lines).singleElement().asString().matches("write summary/grid: \\S+ in \\d+\\.\\d{3} s");
            Files.delete(file);
        }

        @Test
        @DisplayName("setSummary(false) silences the write line too")
        void silent() throws Exception {
            assertThat(printed(b -> b.setSummary(false).setResolution(4, 4).build().renderImage()
                    .writeToImage("summary/silent"))).isEmpty();
            Files.delete(Path.of("images", "summary", "silent.png"));
        }
    }

    @ParameterizedTest(name = "{0} → ''{1}''")
    @CsvSource(delimiter = '|', value = {"0|calling thread", "1|1 thread", "2|2 threads"})
    @DisplayName("the thread count in words: the calling thread, 1 thread, n threads")
    void threadCount(int threads, String words) {
        assertThat(printed(b -> b.setImageWriter(new ImageWriter("threads", 4, 4)).setMultithreading(threads).build()
                .render())).singleElement().asString().contains(", " + words + ", prepared in ");
    }

    @Test
    @DisplayName("the line ends with the BVH's walk (vector or scalar, and why), and says nothing of it without the BVH")
    void walk() {
        assertThat(printed(b -> b.setResolution(4, 4).build().render())).singleElement().asString()
                .matches(".*, prepared in \\d+\\.\\d{3} s, (\\d-wide vector walk \\(trees of \\d+ primitives or more\\)|scalar walk \\(.+\\))");
        RayTracerBasic flat = new RayTracerBasic(new Scene("flat"));
        flat.setBvh(false);
        assertThat(printed(b -> b.setResolution(4, 4).setRayTracer(flat).build().render())).singleElement().asString()
                .matches(".*, prepared in \\d+\\.\\d{3} s");
    }
}
