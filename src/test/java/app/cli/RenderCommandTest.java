package app.cli;

import static app.cli.Cli.run;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import app.cli.Cli.Run;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.io.Messages;
import scene.samples.Showcase;

/**
 * The {@code render} command, run in-process through picocli with captured streams. Renders are
 * tiny; every image goes to the test's temporary folder.
 */
class RenderCommandTest {
    @TempDir
    Path dir;

    /** The shared small scene ({@link Cli#SMALL}). */
    private static final String SMALL = Cli.SMALL;

    private Path write(String name, String xml) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, xml);
        return file;
    }

    private Path small() throws IOException {
        return write("small.xml", SMALL);
    }

    /** Runs the jar's entry point in a new JVM with this JVM's Java, the classes and picocli. */
    private Run runJava(String heap, String... args) throws IOException, InterruptedException {
        return Cli.runJava(dir, heap, args);
    }

    private static BufferedImage image(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        assertThat(image).as("a PNG at " + png).isNotNull();
        return image;
    }

    @Test
    @DisplayName("out of memory while rendering or writing: one line, the library's own when it named the need, else what and -Xmx")
    void outOfMemoryLine() {
        String bvh = "the BVH over 4500000 primitives needs about 996 MB; Java may use at most 1200 MB here, of which about"
                + " 900 MB were free (give Java more memory with -Xmx, …)";
        assertThat(RenderCommand.outOfMemory(new OutOfMemoryError(bvh), "render teapot (100x100)")).isEqualTo("raytracer: " + bvh);
        String obj = "the OBJ file big.obj (147 MB) did not fit in memory: 10 triangles and 30 vertices read when Java ran out;"
                + " Java may use at most 900 MB here (give Java more memory with -Xmx; …)";
        assertThat(RenderCommand.outOfMemory(new OutOfMemoryError(obj), "render teapot (100x100)")).isEqualTo("raytracer: " + obj);
        assertThat(RenderCommand.named(new OutOfMemoryError("Java heap space"))).isFalse();
        assertThat(RenderCommand.outOfMemory(new OutOfMemoryError("Java heap space"), "write images/x.png (100x100)"))
                .startsWith("raytracer: not enough memory to write images/x.png (100x100)")
                .endsWith("(give Java more memory with -Xmx, or render it smaller)").doesNotContain("\n");
    }

    @Nested
    @DisplayName("--help and --version")
    class HelpAndVersion {
        @Test
        void help() {
            Run r = run("--help");
            assertThat(r.exitCode()).isZero();
            assertThat(r.out()).startsWith("Usage: java -jar raytracer.jar ")
                    .contains("[SCENE]", "--output=FILE", "--width=N", "--height=N", "--threads=N", "--aa=MODE", "--seed=N",
                            "--quiet", "--version", "NONE, RANDOM, CORNERS, ADAPTIVE", "Exit codes:");
            assertThat(r.err()).isEmpty();
        }

        @Test
        @DisplayName("--help explains every option and parameter, and lists the three exit codes")
        void helpIsComplete() {
            String help = run("--help").out();
            CommandSpec spec = RenderCommand.commandLine(System.out, System.err, false).getCommandSpec();
            for (OptionSpec option : spec.options()) {
                assertThat(option.description()).as(option.longestName()).isNotEmpty();
                assertThat(help).contains(option.longestName()).contains(option.description()[0].substring(0, 20));
            }
            assertThat(spec.positionalParameters()).allSatisfy(p -> assertThat(p.description()).isNotEmpty());
            assertThat(help.lines().filter(l -> l.matches("  [012]   \\S.*"))).hasSize(3);
        }

        @Test
        void version() {
            Run r = run("--version");
            assertThat(r.exitCode()).isZero();
            assertThat(r.out()).startsWith("raytracer ");
        }

        @Test
        @DisplayName("the jar's entry point runs the command and exits with its code")
        void entryPoint() throws Exception {
            Run version = runJava("-Xmx64m", "--version");
            assertThat(version.exitCode()).isZero();
            assertThat(version.out()).startsWith("raytracer ");
            Run usage = runJava("-Xmx64m", "--width", "0");
            assertThat(usage.exitCode()).isEqualTo(2);
            assertThat(usage.err()).startsWith("raytracer: --width must be at least 1, got 0");
        }
    }

    @Nested
    @DisplayName("usage errors: exit code 2, a message and a hint, no image")
    class UsageErrors {
        @ParameterizedTest(name = "{0}")
        @ValueSource(strings = { "--width 0", "--height -3", "--threads -3", "--aa fast", "--seed x", "--bogus",
                "-o out.jpg", "a.xml b.xml", "--width 50000 --height 50000" })
        void usageError(String arguments) throws IOException {
            List<String> args = new ArrayList<>(List.of(arguments.split(" ")));
            if (!arguments.startsWith("-o")) args.addAll(List.of("-o", dir.resolve("out.png").toString()));
            else args.set(1, dir.resolve("out.jpg").toString());
            Run r = run(args.toArray(String[]::new));
            assertThat(r.exitCode()).isEqualTo(2);
            assertThat(r.errLines()).hasSize(2);
            assertThat(r.errLines().get(0)).startsWith("raytracer: ");
            assertThat(r.errLines().get(1)).isEqualTo("Try 'java -jar raytracer.jar --help' for more information.");
            assertThat(r.out()).isEmpty();
            try (Stream<Path> files = Files.list(dir)) {
                assertThat(files).isEmpty();
            }
        }

        @Test
        @DisplayName("the message names the bad value")
        void namesTheValue() {
            assertThat(run("--width", "0").errLines().get(0)).isEqualTo("raytracer: --width must be at least 1, got 0");
            assertThat(run("--threads", "-3").errLines().get(0)).isEqualTo(
                    "raytracer: --threads: thread count must be 0 (calling thread), a positive number, or -1 or -2 (all cores), got -3");
            // 50000 × 50000 = 2,500,000,000 > 2^31 - 9 = 2,147,483,639 pixels (one int array).
            assertThat(run("--width", "50000", "--height", "50000").errLines().get(0)).isEqualTo(
                    "raytracer: --width/--height: image size 50000x50000 is 2500000000 pixels, more than an image can hold"
                            + " (2147483639)");
        }

        /**
         * A name no file can have (a NUL; only an in-process run can pass one): picocli's own
         * words for a value its Path converter refuses, which the command's converter keeps.
         */
        @ParameterizedTest(name = "{0}")
        @ValueSource(strings = { "-o", "--mesh-root", "SCENE" })
        @DisplayName("a file name Java cannot hold is a usage error in picocli's words")
        void unholdableFileName(String option) {
            String name = "a\0b.png";
            Run r = option.equals("SCENE") ? run(name) : run(option, name);
            String which = option.equals("SCENE") ? "positional parameter at index 0 (SCENE)"
                    : "option '" + (option.equals("-o") ? "--output" : option) + "'";
            // The file system's own words for the refusal (they differ between Linux and Windows).
            String refusal = catchThrowableOfType(() -> Path.of(name),
                    InvalidPathException.class).toString();
            assertThat(r.exitCode()).isEqualTo(2);
            assertThat(r.errLines().get(0)).isEqualTo("raytracer: " + Messages.visible("Invalid value for " + which
                    + ": cannot convert '" + name + "' to interface java.nio.file.Path (" + refusal + ")"));
        }

        /**
         * A file 1 pixel wide and 1000 high: --width 4300000 alone makes the height 4.3e9, beyond
         * an int (it must not wrap around to a small height and render a stretched image).
         */
        @Test
        @DisplayName("one side whose aspect-ratio partner is beyond an int")
        void otherSideTooLarge() throws IOException {
            Path file = write("tall.xml", SMALL.replace("width=\"40\" height=\"20\"", "width=\"1\" height=\"1000\""));
            Run r = run(file.toString(), "-o", dir.resolve("out.png").toString(), "--width", "4300000");
            assertThat(r.exitCode()).isEqualTo(2);
            assertThat(r.errLines()).containsExactly(
                    "raytracer: --width 4300000 at the file's aspect ratio makes the other side 4300000000 pixels,"
                            + " more than an image can hold",
                    "Try 'java -jar raytracer.jar --help' for more information.");
        }
    }

    @Nested
    @DisplayName("bad scene files: exit code 2, one line FILE:LINE:COLUMN, no stack trace, no image")
    class BadSceneFiles {
        static Stream<Arguments> badScenes() {
            String head = "<scene>\n  <geometries>\n    ";
            String tail = "\n  </geometries>\n  <camera location=\"0 0 0\" target=\"0 0 -1\" vp-size=\"1\" vp-distance=\"1\"/>\n</scene>\n";
            return Stream.of(
                    Arguments.of("malformed XML", head + "<sphere center=\"0 0 -100\" radius=\"5\">" + tail, ":4:5: malformed XML"),
                    Arguments.of("unknown element", head + "<cube center=\"0 0 0\"/>" + tail, ":3:5: unknown element <cube>"),
                    Arguments.of("unknown attribute", head + "<sphere center=\"0 0 0\" radius=\"5\" size=\"2\"/>" + tail,
                            ":3:39: unknown attribute 'size' on <sphere>"),
                    Arguments.of("missing attribute", head + "<sphere radius=\"5\"/>" + tail,
                            ":3:5: <sphere> is missing attribute 'center'"),
                    Arguments.of("malformed number", head + "<sphere center=\"0 0 0\" radius=\"5cm\"/>" + tail,
                            ":3:28: <sphere radius=\"5cm\">: '5cm' is not a number"),
                    Arguments.of("non-finite number", head + "<sphere center=\"0 0 0\" radius=\"Infinity\"/>" + tail,
                            ":3:28: <sphere radius=\"Infinity\">: 'Infinity' is not a finite number"),
                    Arguments.of("collinear triangle", head + "<triangle p0=\"0 0 0\" p1=\"1 0 0\" p2=\"2 0 0\"/>" + tail,
                            ":3:5: invalid <triangle>: polygon points must not be collinear"),
                    Arguments.of("missing mesh file", head + "<mesh file=\"teapot.obj\"/>" + tail,
                            ":3:11: <mesh file=\"teapot.obj\">: cannot read "),
                    Arguments.of("no camera", "<scene>\n</scene>\n", ":1:1: the scene has no <camera>"));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("badScenes")
        void badScene(String name, String xml, String message) throws IOException {
            Path file = write("bad.xml", xml);
            Path png = dir.resolve("out.png");
            Run r = run(file.toString(), "-o", png.toString());
            assertThat(r.exitCode()).isEqualTo(2);
            assertThat(r.errLines()).hasSize(1);
            assertThat(r.errLines().get(0)).startsWith(file + message).contains("(expected ");
            assertThat(r.err()).doesNotContain("Exception", "\tat ");
            assertThat(r.out()).isEmpty();
            assertThat(png).doesNotExist();
        }

        @Test
        @DisplayName("a scene file that does not exist")
        void missingFile() {
            Path file = dir.resolve("absent.xml");
            Run r = run(file.toString(), "-o", dir.resolve("out.png").toString());
            assertThat(r.exitCode()).isEqualTo(2);
            assertThat(r.errLines()).containsExactly(
                    file + ": cannot read the scene file: no such file (expected a readable XML scene file)");
        }
    }

    @Nested
    @DisplayName("options override the file's settings")
    class Overrides {
        @Test
        @DisplayName("without options, the file's size, name and settings")
        void fileSettings() throws IOException {
            Path png = dir.resolve("out.png");
            Run r = run(small().toString(), "-o", png.toString());
            assertThat(r.exitCode()).isZero();
            assertThat(r.out()).contains(" s, 40x20 [NONE, bvh on, beam 3, shadow samples 3, seed 0]")
                    .contains("1 thread,").contains("wrote " + png + " (40x20)");
            assertThat(image(png).getWidth()).isEqualTo(40);
            assertThat(image(png).getHeight()).isEqualTo(20);
        }

        @Test
        @DisplayName("--width and --height set the image size")
        void size() throws IOException {
            Path png = dir.resolve("out.png");
            assertThat(run(small().toString(), "-o", png.toString(), "--width", "12", "--height", "9").exitCode()).isZero();
            assertThat(new int[] { image(png).getWidth(), image(png).getHeight() }).containsExactly(12, 9);
        }

        @Test
        @DisplayName("--width alone keeps the file's aspect ratio")
        void widthAlone() throws IOException {
            Path png = dir.resolve("out.png");
            assertThat(run(small().toString(), "-o", png.toString(), "--width", "10").exitCode()).isZero();
            assertThat(new int[] { image(png).getWidth(), image(png).getHeight() }).containsExactly(10, 5);
        }

        @Test
        @DisplayName("--aa changes the sampling: RANDOM with the default 4×4 grid takes 16 samples a pixel")
        void antiAliasing() throws IOException {
            Path none = dir.resolve("none.png"), random = dir.resolve("random.png");
            Run plain = run(small().toString(), "-o", none.toString());
            Run aa = run(small().toString(), "-o", random.toString(), "--aa", "random");
            assertThat(plain.out()).contains(", 1.00 camera rays per px,");
            assertThat(aa.out()).contains("[RANDOM 4x4,").contains(", 16.00 camera rays per px,");
            assertThat(Files.mismatch(none, random)).as("the images differ").isNotEqualTo(-1);
        }

        @Test
        @DisplayName("--aa over the file's values: the file's grid and seed stay, the option's mode wins")
        void optionsOverTheFile() throws IOException {
            Path file = write("grid.xml", SMALL.replace("<render threads=\"1\" beam-size=\"3\" shadow-samples=\"3\"/>",
                    "<render threads=\"1\" beam-size=\"3\" shadow-samples=\"3\" seed=\"4\">"
                            + "<anti-aliasing mode=\"corners\" grid=\"2 3\"/></render>"));
            Run r = run(file.toString(), "-o", dir.resolve("out.png").toString(), "--aa", "random", "--width", "8");
            assertThat(r.exitCode()).isZero();
            assertThat(r.out()).contains(" s, 8x4 [RANDOM 2x3, bvh on, beam 3, shadow samples 3, seed 4]");
        }

        @Test
        @DisplayName("--seed: the same seed gives the same image, another seed another")
        void seed() throws IOException {
            Path a = dir.resolve("a.png"), b = dir.resolve("b.png"), c = dir.resolve("c.png");
            assertThat(run(small().toString(), "-o", a.toString(), "--aa", "random", "--seed", "1").exitCode()).isZero();
            assertThat(run(small().toString(), "-o", b.toString(), "--aa", "random", "--seed", "1").exitCode()).isZero();
            Run other = run(small().toString(), "-o", c.toString(), "--aa", "random", "--seed", "2");
            assertThat(other.out()).contains("seed 2]");
            assertThat(Files.mismatch(a, b)).isEqualTo(-1);
            assertThat(Files.mismatch(a, c)).isNotEqualTo(-1);
        }

        @Test
        @DisplayName("--threads 1 and --threads 2 write the same bytes")
        void threads() throws IOException {
            Path one = dir.resolve("one.png"), two = dir.resolve("two.png");
            Run r1 = run(small().toString(), "-o", one.toString(), "--threads", "1", "--aa", "random");
            Run r2 = run(small().toString(), "-o", two.toString(), "--threads", "2", "--aa", "random");
            assertThat(r1.out()).contains(", 1 thread,");
            assertThat(r2.out()).contains(", 2 threads");
            assertThat(Files.mismatch(one, two)).isEqualTo(-1);
        }

        @Test
        @DisplayName("without -o the image goes to images/<image name>.png")
        void defaultOutput() throws IOException {
            String name = "cli-test-default-output";
            Path expected = ImageWriter.IMAGES.resolve(name + ".png");
            Files.deleteIfExists(expected);
            Run r = run(write("named.xml", SMALL.replace("<image name=\"small\"", "<image name=\"" + name + "\"")).toString(),
                    "--width", "4", "--quiet");
            assertThat(r.exitCode()).isZero();
            assertThat(expected).exists();
            assertThat(image(expected).getWidth()).isEqualTo(4);
        }
    }

    @Test
    @DisplayName("without a scene: the built-in showcase with the showcase camera")
    void showcase() throws IOException {
        Path png = dir.resolve("showcase.png");
        Run r = run("-o", png.toString(), "--width", "16", "--height", "16", "--aa", "none");
        assertThat(r.exitCode()).isZero();
        assertThat(r.out()).contains(" s, 16x16 [NONE,").contains("render showcase: ");

        ImageWriter expected = new ImageWriter("showcase", 16, 16);
        Camera.getBuilder().setLocation(Showcase.CAMERA_LOCATION).setDirection(Showcase.CAMERA_TARGET, Vector.AXIS_Y)
                .setVpSize(Showcase.VP_SIZE, Showcase.VP_SIZE).setVpDistance(Showcase.VP_DISTANCE)
                .setImageWriter(expected).setRayTracer(new RayTracerBasic(Showcase.create()))
                .setAntiAliasing(AntiAliasing.NONE).setSummary(false).build().renderImage();
        BufferedImage actual = image(png);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                assertThat(actual.getRGB(x, y) & 0xFFFFFF).as("pixel (%d,%d)", x, y).isEqualTo(expected.getRgb(x, y));
    }

    @Nested
    @DisplayName("progress")
    class ProgressOutput {
        private static final Pattern LINE = Pattern.compile("render small:\\s+(\\d+\\.\\d)%.*");

        @Test
        @DisplayName("not a terminal: plain progress lines in order, the summary, the result")
        void lines() throws IOException {
            Run r = run(small().toString(), "-o", dir.resolve("out.png").toString(), "--threads", "2");
            List<String> lines = r.out().lines().toList();
            List<Double> percents = new ArrayList<>();
            for (String line : lines) {
                Matcher m = LINE.matcher(line);
                if (m.matches()) percents.add(Double.parseDouble(m.group(1)));
            }
            assertThat(percents).hasSizeGreaterThanOrEqualTo(2).isSorted().last().isEqualTo(100.0);
            assertThat(r.out()).doesNotContain("\r");
            assertThat(lines.get(lines.size() - 2)).startsWith("render small: ").contains(" s, 40x20 [");
            assertThat(lines.get(lines.size() - 1)).startsWith("wrote ");
        }

        @Test
        @DisplayName("a terminal: one bar redrawn with \\r, then the summary on its own line")
        void bar() throws IOException {
            Run r = run(true, small().toString(), "-o", dir.resolve("out.png").toString());
            assertThat(r.exitCode()).isZero();
            assertThat(r.out()).contains("\rrender small [").contains("] 100.0%  elapsed ").contains("ETA ");
            assertThat(r.out().lines().filter(l -> LINE.matcher(l).matches())).as("no plain progress lines").isEmpty();
            List<String> lines = List.of(r.out().split("\n")); // not lines(): it would split at '\r'
            assertThat(lines).hasSize(3);
            assertThat(lines.get(0)).startsWith("\rrender small [");
            assertThat(lines.get(1)).startsWith("render small: ").contains(" s, 40x20 [");
            assertThat(lines.get(2)).startsWith("wrote ");
        }

        @Test
        @DisplayName("--quiet: nothing on either stream, and the image is written")
        void quiet() throws IOException {
            Path png = dir.resolve("out.png");
            Run r = run(true, small().toString(), "-o", png.toString(), "--quiet");
            assertThat(r.exitCode()).isZero();
            assertThat(r.out()).isEmpty();
            assertThat(r.err()).isEmpty();
            assertThat(png).exists();
        }
    }

    /**
     * The command in a JVM of its own with a small heap (64 MB), as {@code java -Xmx64m -jar}
     * runs it: the file asks for 40000 × 40000 pixels, 6.4 GB.
     */
    @Nested
    @DisplayName("memory: the image is allocated once, at its final size")
    class Memory {
        private static final String HUGE = SMALL.replace("width=\"40\" height=\"20\"", "width=\"40000\" height=\"40000\"");

        @Test
        @DisplayName("--width makes the file's huge image small: nothing of the file's size is allocated")
        void overriddenSize() throws Exception {
            Path png = dir.resolve("out.png");
            Run r = runJava("-Xmx64m", write("huge.xml", HUGE).toString(), "-o", png.toString(), "--width", "20", "--quiet");
            assertWritten(r, png, 20, 20);
        }

        /** A quiet run that succeeded: nothing printed, exit code 0, a PNG of this size. */
        private static void assertWritten(Run r, Path png, int width, int height) throws IOException {
            assertThat(r.err()).isEmpty();
            assertThat(r.exitCode()).isZero();
            assertThat(new int[] { image(png).getWidth(), image(png).getHeight() }).containsExactly(width, height);
        }

        /** 40000² pixels × 4 bytes = 6,400,000,000 bytes = 6103.5 MiB, rounded up. */
        @Test
        @DisplayName("an image that does not fit: exit code 1, one line with the memory it needs, no stack trace")
        void notEnoughMemory() throws Exception {
            Path png = dir.resolve("out.png");
            Run r = runJava("-Xmx64m", write("huge.xml", HUGE).toString(), "-o", png.toString());
            assertThat(r.exitCode()).isEqualTo(1);
            assertThat(r.errLines()).hasSize(1);
            assertThat(r.errLines().get(0)).matches(
                    "raytracer: image 40000x40000 needs 6104 MB; Java may use at most \\d+ MB here \\(render it smaller with"
                            + " --width or --height, or give Java more memory with -Xmx\\)");
            assertThat(png).doesNotExist();
        }

        /**
         * 2000 × 2000 pixels are 16 MB: they fit once in a 32 MB heap, not twice (as they did
         * when writing the PNG copied the pixels into a BufferedImage).
         */
        @Test
        @DisplayName("an image that fits in memory once is rendered and written: writing makes no copy of it")
        void fitsOnce() throws Exception {
            Path scene = write("empty.xml", """
                    <scene name="empty">
                        <camera location="0 0 0" direction="0 0 -1" up="0 1 0" vp-size="1" vp-distance="1"/>
                        <image width="2000" height="2000"/>
                    </scene>
                    """);
            Path png = dir.resolve("out.png");
            Run r = runJava("-Xmx32m", scene.toString(), "-o", png.toString(), "--quiet");
            assertWritten(r, png, 2000, 2000);
        }
    }

    @Test
    @DisplayName("a failure while writing the image: exit code 1, one line, no stack trace")
    void writeFailure() throws IOException {
        Path notADirectory = Files.writeString(dir.resolve("file"), "x");
        Run r = run(small().toString(), "-o", notADirectory.resolve("out.png").toString(), "--quiet");
        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.errLines()).hasSize(1);
        assertThat(r.errLines().get(0)).startsWith("raytracer: cannot write image ");
        assertThat(r.err()).doesNotContain("\tat ");
    }

    @Test
    @DisplayName("a PNG encoder that cannot work: exit code 1 before the render starts, one line, no image")
    void encoderFailure() throws IOException {
        Path png = dir.resolve("out.png");
        Run r = Cli.run(false, () -> EncoderWarmUp.start(() -> {
            throw new IOException("no PNG writer available");
        }), small().toString(), "-o", png.toString());
        assertThat(r.exitCode()).isEqualTo(1);
        assertThat(r.err()).isEqualTo("raytracer: cannot encode PNG images in this JVM: java.io.IOException: no PNG writer available\n");
        assertThat(r.out()).as("no progress: the render never started").isEmpty();
        assertThat(png).doesNotExist();
    }
}
