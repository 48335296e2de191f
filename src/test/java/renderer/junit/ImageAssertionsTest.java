package renderer.junit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatNoException;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestReporter;
import org.junit.jupiter.api.extension.ConditionEvaluationResult;
import org.junit.jupiter.api.extension.ExecutionCondition;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.platform.engine.reporting.ReportEntry;
import org.junit.platform.testkit.engine.EngineTestKit;
import org.opentest4j.AssertionFailedError;

import primitives.Color;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.CameraReports;
import renderer.ImageWriter;
import renderer.ImageWriters;
import renderer.RayTracerBasic;
import renderer.RenderStats;
import scene.Scene;

/**
 * The image assertions: verdicts by the verification script's rules (its parity with OpenImageIO
 * is proven by scripts/test_image_assertions_parity.py), what a failure says and writes, bad
 * input, recording references, and what a test's report shows. Every file goes to a temporary
 * folder, but for the one PNG the 2024–25 flow writes into images/, which its test deletes.
 */
@DisplayName("Image assertions")
class ImageAssertionsTest {
    private static final int W = 32, H = 24;

    @TempDir
    Path dir;
    private Path references;
    private Path output;
    /** The JVM's environment and properties left out: nothing recorded, CI unset, unless a test says so. */
    private ImageAssertions assertions;

    @BeforeEach
    void folders() throws IOException {
        references = Files.createDirectories(dir.resolve("references"));
        output = dir.resolve("output");
        assertions = ImageAssertions.defaults().withReferenceFolder(references).withOutputFolder(output)
                .withLookups(key -> null, key -> null);
    }

    /** Mid-range values, so that ±steps never clip. */
    private static int[] gradient() {
        int[] rgb = new int[W * H];
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                int base = 40 + (x * 5 + y * 3) % 170;
                rgb[y * W + x] = base << 16 | (base + 10) << 8 | (base + 20);
            }
        return rgb;
    }

    private static Path png(Path file, int w, int h, int[] rgb) {
        ImageWriter image = new ImageWriter(w, h);
        ImageWriters.writeTile(image, 0, 0, w, h, rgb);
        image.writeToImage(file);
        return file;
    }

    private static Path png(Path file, int[] rgb) {
        return png(file, W, H, rgb);
    }

    /** {@code rgb} with the green channel of pixel (x, y) moved up by {@code steps}. */
    private static int[] greenUp(int[] rgb, int x, int y, int steps) {
        int[] copy = rgb.clone();
        copy[y * W + x] += steps << 8;
        return copy;
    }

    private static List<Path> files(Path folder) throws IOException {
        try (Stream<Path> all = Files.walk(folder)) {
            return all.filter(Files::isRegularFile).sorted().toList();
        }
    }

    /** A camera whose image holds {@code rgb} (no render needed: the assertion reads its image writer). */
    private static Camera cameraShowing(int[] rgb) {
        ImageWriter image = new ImageWriter("junit/gradient", W, H);
        ImageWriters.writeTile(image, 0, 0, W, H, rgb);
        return view().setImageWriter(image).build();
    }

    private static Camera.Builder view() {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Vector.AXIS_Y).setVpSize(1, 1)
                .setVpDistance(1).setSummary(false);
    }

    @Nested
    @DisplayName("verdicts, by the script's rules")
    class Verdicts {
        private Comparison compare(int[] render, int[] reference, ImageThresholds t) {
            return Comparison.of(Picture.of(writer(render)), Picture.of(writer(reference)), t);
        }

        private ImageWriter writer(int[] rgb) {
            ImageWriter image = new ImageWriter(W, H);
            ImageWriters.writeTile(image, 0, 0, W, H, rgb);
            return image;
        }

        @Test
        @DisplayName("identical images pass with infinite PSNR and no difference at (0,0)")
        void identical() {
            Comparison c = compare(gradient(), gradient(), ImageThresholds.DEFAULTS);
            assertThat(c.status()).isEqualTo(Comparison.Status.PASS);
            assertThat(c.metrics().psnr()).isInfinite();
            assertThat(c.metrics().maxError()).isZero();
            assertThat(List.of(c.metrics().maxX(), c.metrics().maxY(), c.metrics().maxChannel())).containsExactly(0, 0, 0);
        }

        @Test
        @DisplayName("one channel 4 steps off fails by hardfail, naming the pixel and channel")
        void hardFail() {
            Comparison c = compare(greenUp(gradient(), 7, 5, 4), gradient(), ImageThresholds.DEFAULTS);
            assertThat(c.status()).isEqualTo(Comparison.Status.FAIL);
            assertThat(c.message()).startsWith("max error 0.01569 at (7,5) channel 1 exceeds hardfail 0.012");
            assertThat(c.metrics().failing()).isEqualTo(1);
        }

        @ParameterizedTest(name = "{0} pixel(s) {1} step(s) off in a 32x24 image: {2}")
        @CsvSource({
                "1, 1, PASS", // 0.0039 is within failthresh 0.004
                "768, 1, PASS", // every pixel one step off: still within
                "1, 3, FAIL", // 0.0118 < hardfail, but 1 of 768 pixels = 0.13 % > 0.02 %
                "64, 2, FAIL", // 8.3 % of the pixels over failthresh
        })
        void steps(int pixels, int steps, Comparison.Status expected) {
            int[] render = gradient();
            for (int i = 0; i < pixels; ++i) render[i] += steps << 8;
            assertThat(compare(render, gradient(), ImageThresholds.DEFAULTS).status()).isEqualTo(expected);
        }

        @Test
        @DisplayName("a passing image with many pixels over warnthresh gets a warning, not a failure")
        void warning() {
            ImageThresholds loose = ImageThresholds.DEFAULTS.withFailPercent(50).withWarnThreshold(0.005).withWarnPercent(1);
            int[] render = gradient();
            for (int i = 0; i < 100; ++i) render[i] += 2 << 8;
            Comparison c = compare(render, gradient(), loose);
            assertThat(c.status()).isEqualTo(Comparison.Status.WARN);
            assertThat(c.message()).isEqualTo("warning: 13.021% of pixels differ by more than warnthresh 0.005 (warnpercent 1%)");
        }

        @Test
        @DisplayName("a camera's image holds the very values of the PNG it writes (the parity proof reads PNGs)")
        void cameraAsItsPng() throws Exception {
            ImageWriter image = writer(gradient());
            image.writeToImage(dir.resolve("gradient.png"));
            Picture fromPng = Picture.read(dir.resolve("gradient.png"), "render");
            assertThat(fromPng.channels()).isEqualTo(3);
            assertThat(Picture.of(image).values()).containsExactly(fromPng.values());
        }

        @Test
        @DisplayName("a palette PNG is read as RGB, as OpenImageIO expands it")
        void palette() throws Exception {
            BufferedImage indexed = new BufferedImage(W, H, BufferedImage.TYPE_BYTE_INDEXED);
            BufferedImage rgb = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
            int[] colours = gradient();
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) indexed.setRGB(x, y, colours[y * W + x]);
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) rgb.setRGB(x, y, indexed.getRGB(x, y));
            ImageIO.write(indexed, "png", dir.resolve("indexed.png").toFile());
            ImageIO.write(rgb, "png", dir.resolve("rgb.png").toFile());
            Picture a = Picture.read(dir.resolve("indexed.png"), "render"), b = Picture.read(dir.resolve("rgb.png"), "reference");
            assertThat(a.channels()).isEqualTo(3);
            assertThat(a.values()).containsExactly(b.values());
        }

        @Test
        @DisplayName("a 16-bit grey PNG reads on the same 0..1 scale as an 8-bit one")
        void sixteenBits() throws Exception {
            BufferedImage eight = new BufferedImage(4, 1, BufferedImage.TYPE_BYTE_GRAY);
            BufferedImage sixteen = new BufferedImage(4, 1, BufferedImage.TYPE_USHORT_GRAY);
            for (int x = 0; x < 4; ++x) {
                eight.getRaster().setSample(x, 0, 0, 80 * x);
                sixteen.getRaster().setSample(x, 0, 0, 80 * x * 257);
            }
            ImageIO.write(eight, "png", dir.resolve("8.png").toFile());
            ImageIO.write(sixteen, "png", dir.resolve("16.png").toFile());
            Picture a = Picture.read(dir.resolve("8.png"), "render"), b = Picture.read(dir.resolve("16.png"), "reference");
            assertThat(a.channels()).isEqualTo(1);
            assertThat(Comparison.of(a, b, ImageThresholds.DEFAULTS.withFailThreshold(0)).metrics().maxError()).isLessThan(1e-6);
        }

        @ParameterizedTest(name = "{0}")
        @CsvSource({ "failThreshold, -1", "hardFail, NaN", "failPercent, 101", "warnPercent, Infinity" })
        @DisplayName("a limit out of range is refused, by name")
        void badThresholds(String name, double value) {
            assertThatThrownBy(() -> {
                switch (name) {
                    case "failThreshold" -> ImageThresholds.DEFAULTS.withFailThreshold(value);
                    case "hardFail" -> ImageThresholds.DEFAULTS.withHardFail(value);
                    case "failPercent" -> ImageThresholds.DEFAULTS.withFailPercent(value);
                    default -> ImageThresholds.DEFAULTS.withWarnPercent(value);
                }
            }).isInstanceOf(IllegalArgumentException.class).hasMessageStartingWith(name);
        }
    }

    @Nested
    @DisplayName("a failure")
    class Failure {
        private Path render;
        private AssertionFailedError failure;

        @BeforeEach
        void failOnePixel() {
            png(references.resolve("gradient.png"), gradient());
            render = png(dir.resolve("renders").resolve("gradient.png"), greenUp(gradient(), 7, 5, 25));
            failure = catchThrowableOfType(AssertionFailedError.class, () -> assertions.assertMatches(render, "gradient"));
        }

        @Test
        @DisplayName("says PSNR, the largest difference and where, the failing pixels' share and count, and the diff images")
        void message() {
            assertThat(failure).isNotNull();
            assertThat(failure.getMessage()).contains("render " + render, "does not match reference " + references.resolve("gradient.png"),
                    "max error 0.09804 at (7,5) channel 1 exceeds hardfail 0.012", "PSNR 53.8 dB",
                    "largest difference 0.0980 (25 of 255 steps) at pixel (7,5) channel 1", "failing pixels 0.130% (1 of 768)",
                    "diff:     " + render.resolveSibling("gradient.diff.png"), "heat map: " + render.resolveSibling("gradient.heat.png"));
        }

        @Test
        @DisplayName("writes a diff (difference × 20) and a heat map next to the render")
        void diffImages() throws IOException {
            BufferedImage diff = ImageIO.read(render.resolveSibling("gradient.diff.png").toFile());
            BufferedImage heat = ImageIO.read(render.resolveSibling("gradient.heat.png").toFile());
            // 25 steps × 20 saturates; the other channels and pixels are black.
            assertThat(diff.getRGB(7, 5) & 0xFFFFFF).isEqualTo(0x00FF00);
            assertThat(diff.getRGB(0, 0) & 0xFFFFFF).isZero();
            // 0.098 lies between hardfail (red) and 0.25 (yellow): red with some green.
            int hot = heat.getRGB(7, 5);
            assertThat((hot >> 16) & 0xFF).isEqualTo(255);
            assertThat((hot >> 8) & 0xFF).isBetween(85, 100);
            assertThat(heat.getRGB(1, 1) & 0xFFFFFF).isZero();
        }

        @Test
        @DisplayName("is an AssertionFailedError whose stack trace starts in the test, not inside the library")
        void stackTrace() {
            assertThat(failure.getCause()).isNull();
            assertThat(failure.getStackTrace()[0].getClassName()).doesNotStartWith(ImageAssertions.class.getName());
        }

        @Test
        @DisplayName("of a camera writes its render, the diff and the heat map in the test's folder under the output folder")
        void camera() throws IOException {
            Camera camera = cameraShowing(greenUp(gradient(), 3, 3, 9));
            Path mine = output.resolve("ImageAssertionsTest.Failure.camera");
            assertThatThrownBy(() -> assertions.assertMatches(camera, "gradient")).isInstanceOf(AssertionFailedError.class)
                    .hasMessageContaining("the render of junit/gradient does not match reference")
                    .hasMessageContaining("diff:     " + mine.resolve("gradient.diff.png"))
                    .hasMessageContaining("render:   " + mine.resolve("gradient.png"));
            assertThat(files(output)).containsExactly(mine.resolve("gradient.diff.png"), mine.resolve("gradient.heat.png"),
                    mine.resolve("gradient.png"));
            assertThat(ImageIO.read(mine.resolve("gradient.png").toFile()).getRGB(3, 3) & 0xFFFFFF)
                    .isEqualTo(greenUp(gradient(), 3, 3, 9)[3 * W + 3]);
        }

        @Test
        @DisplayName("of an image named only when written (2024–25) names the test in its message")
        void unnamedImage() {
            ImageWriter image = new ImageWriter(W, H);
            ImageWriters.writeTile(image, 0, 0, W, H, greenUp(gradient(), 3, 3, 9));
            Camera camera = view().setImageWriter(image).build();
            assertThatThrownBy(() -> assertions.assertMatches(camera, "gradient"))
                    .hasMessageStartingWith("the render of ImageAssertionsTest.Failure.unnamedImage() does not match reference");
        }

        @Test
        @DisplayName("two tests comparing with one reference keep their own files, and each message names its own")
        void twoTestsOneReference() throws IOException {
            SharedReferenceSample.dir = dir;
            List<Throwable> failures = EngineTestKit.engine("junit-jupiter").selectors(selectClass(SharedReferenceSample.class))
                    .configurationParameter(ReportingSample.RUN, "true").execute().testEvents().failed().stream()
                    .map(e -> e.getRequiredPayload(org.junit.platform.engine.TestExecutionResult.class).getThrowable().orElseThrow())
                    .toList();
            assertThat(failures).hasSize(2);
            for (String test : List.of("first", "second")) {
                Path folder = output.resolve("ImageAssertionsTest.SharedReferenceSample." + test);
                assertThat(files(folder)).containsExactly(folder.resolve("gradient.diff.png"), folder.resolve("gradient.heat.png"),
                        folder.resolve("gradient.png"));
                assertThat(failures).filteredOn(f -> f.getMessage().contains("diff:     " + folder.resolve("gradient.diff.png")))
                        .as("the failure of %s names its own diff", test).hasSize(1);
            }
            int steps = SharedReferenceSample.SECOND_STEPS;
            assertThat(ImageIO.read(output.resolve("ImageAssertionsTest.SharedReferenceSample.second").resolve("gradient.png")
                    .toFile()).getRGB(3, 3) & 0xFFFFFF).as("the second test's render, not overwritten by the first's")
                    .isEqualTo(greenUp(gradient(), 3, 3, steps)[3 * W + 3]);
        }
    }

    @Nested
    @DisplayName("a match")
    class Match {
        @Test
        @DisplayName("of a camera's image or of a PNG passes and writes nothing")
        void passes() throws IOException {
            png(references.resolve("sub/gradient.png"), gradient());
            Path render = png(dir.resolve("render.png"), greenUp(gradient(), 1, 1, 1));
            List<Path> before = files(dir);
            assertThatNoException().isThrownBy(() -> assertions.assertMatches(cameraShowing(gradient()), "sub/gradient.png"));
            assertThatNoException().isThrownBy(() -> assertions.assertMatches(render, "sub/gradient"));
            assertThat(files(dir)).isEqualTo(before);
        }

        @Test
        @DisplayName("of a rendered camera, against src/test/resources (figures and verdict in this test's report)")
        void staticEntry(TestReporter reporter) {
            // src/test/resources/renderer/junit/background.png: a 4x3 render of a background only,
            // recorded by this test with -Draytracer.updateReferences=true.
            Scene scene = new Scene("background").setBackground(new Color(30, 60, 90));
            Camera camera = view().setImageWriter(new ImageWriter("background", 4, 3)).setRayTracer(new RayTracerBasic(scene))
                    .setRenderListener(RenderReports.to(reporter)).build().renderImage();
            assertThatNoException().isThrownBy(() -> ImageAssertions.assertImageMatches(camera, "renderer/junit/background"));
            assertThatNoException().isThrownBy(
                    () -> ImageAssertions.defaults().reportingTo(reporter).assertMatches(camera, "renderer/junit/background"));
        }
    }

    @Nested
    @DisplayName("bad input: one clear message each, nothing written or overwritten")
    class BadInput {
        private List<Path> before;
        private byte[] reference;

        @BeforeEach
        void reference() throws IOException {
            reference = Files.readAllBytes(png(references.resolve("gradient.png"), gradient()));
        }

        private AssertionFailedError fails(Path render, String name) throws IOException {
            before = files(dir);
            AssertionFailedError e = catchThrowableOfType(AssertionFailedError.class, () -> assertions.assertMatches(render, name));
            assertThat(e).as("the assertion fails").isNotNull();
            assertThat(e.getCause()).isNull();
            assertThat(files(dir)).as("files after the failure").isEqualTo(before);
            assertThat(references.resolve("gradient.png")).hasBinaryContent(reference);
            return e;
        }

        @Test
        @DisplayName("a reference of another size")
        void otherSize() throws IOException {
            Path render = png(dir.resolve("wide.png"), W + 1, H, new int[(W + 1) * H]);
            assertThat(fails(render, "gradient")).hasMessage("render " + render + " does not match reference "
                    + references.resolve("gradient.png") + ": size differs: render 33x24, reference 32x24; nothing was written");
        }

        @Test
        @DisplayName("a reference with another channel count")
        void otherChannels() throws IOException {
            BufferedImage rgba = new BufferedImage(W, H, BufferedImage.TYPE_INT_ARGB);
            Path render = dir.resolve("rgba.png");
            ImageIO.write(rgba, "png", render.toFile());
            assertThat(fails(render, "gradient").getMessage())
                    .endsWith("channel count differs: render 32x24, 4 channels (RGBA), reference 32x24, 3 channels (RGB); nothing was written");
        }

        @Test
        @DisplayName("a missing reference")
        void missingReference() throws IOException {
            Path render = png(dir.resolve("render.png"), gradient());
            assertThat(fails(render, "spheres")).hasMessage("no reference image " + references.resolve("spheres.png") + " for render "
                    + render + "; record it with -Draytracer.updateReferences=true (refused when CI is set), look at it and commit it");
        }

        @ParameterizedTest(name = "holding \"{0}\"")
        @ValueSource(strings = { "not a PNG", "" })
        @DisplayName("an unreadable reference")
        void unreadableReference(String content) throws IOException {
            Files.writeString(references.resolve("broken.png"), content);
            Path render = png(dir.resolve("render.png"), gradient());
            assertThat(fails(render, "broken").getMessage()).startsWith("cannot read reference " + references.resolve("broken.png") + ": ")
                    .endsWith("; nothing was written");
        }

        @Test
        @DisplayName("a truncated render")
        void truncatedRender() throws IOException {
            Path render = dir.resolve("truncated.png");
            Files.write(render, java.util.Arrays.copyOf(reference, reference.length / 2));
            assertThat(fails(render, "gradient").getMessage()).startsWith("cannot read render " + render + ": ");
        }

        @Test
        @DisplayName("a render that does not exist")
        void missingRender() throws IOException {
            Path render = dir.resolve("nowhere.png");
            assertThat(fails(render, "gradient")).hasMessage("cannot read render " + render + ": no such file");
        }

        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = { " ", "../outside", "/absolute/path" })
        @DisplayName("a reference name that is blank or leaves the reference folder is a programming error")
        void badName(String name) {
            assertThatThrownBy(() -> assertions.assertMatches(cameraShowing(gradient()), name))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("reference name");
        }
    }

    @Nested
    @DisplayName("recording references on purpose (-Draytracer.updateReferences=true)")
    class Recording {
        private ImageAssertions recording(String ci) {
            return assertions.withLookups(key -> key.equals("CI") ? ci : null,
                    key -> key.equals(ImageAssertions.UPDATE_PROPERTY) ? "true" : null);
        }

        @Test
        @DisplayName("a new reference is written from the camera, and the assertion fails saying so")
        void records() throws IOException {
            assertThatThrownBy(() -> recording(null).assertMatches(cameraShowing(gradient()), "new/gradient"))
                    .isInstanceOf(AssertionFailedError.class)
                    .hasMessageStartingWith("recorded reference " + references.resolve("new/gradient.png") + " (new) from the render of junit/gradient")
                    .hasMessageEndingWith("run again without -Draytracer.updateReferences to verify");
            assertThatNoException().isThrownBy(() -> assertions.assertMatches(cameraShowing(gradient()), "new/gradient"));
        }

        @Test
        @DisplayName("a changed reference is overwritten with the PNG's bytes")
        void overwrites() throws IOException {
            png(references.resolve("gradient.png"), gradient());
            Path render = png(dir.resolve("render.png"), greenUp(gradient(), 2, 2, 1));
            assertThatThrownBy(() -> recording("").assertMatches(render, "gradient")).isInstanceOf(AssertionFailedError.class)
                    .hasMessageContaining("(changed: max error 0.003922, 0.130% of pixels differ)");
            assertThat(references.resolve("gradient.png")).hasSameBinaryContentAs(render);
        }

        @Test
        @DisplayName("an identical reference is left alone and the assertion passes")
        void unchanged() throws IOException {
            Path reference = png(references.resolve("gradient.png"), gradient());
            long modified = Files.getLastModifiedTime(reference).toMillis();
            assertThatNoException().isThrownBy(() -> recording(null).assertMatches(cameraShowing(gradient()), "gradient"));
            assertThat(Files.getLastModifiedTime(reference).toMillis()).isEqualTo(modified);
        }

        @ParameterizedTest(name = "CI={0}")
        @ValueSource(strings = { "true", "1" })
        @DisplayName("is refused when CI is set: nothing is written")
        void refusedUnderCi(String ci) throws IOException {
            byte[] old = Files.readAllBytes(png(references.resolve("gradient.png"), gradient()));
            List<Path> before = files(dir);
            assertThatThrownBy(() -> recording(ci).assertMatches(cameraShowing(greenUp(gradient(), 0, 0, 50)), "gradient"))
                    .isInstanceOf(AssertionFailedError.class)
                    .hasMessage("refusing to record reference " + references.resolve("gradient.png")
                            + ": -Draytracer.updateReferences is set, and so is CI (CI='" + ci
                            + "'); references are recorded on purpose on a developer machine and committed");
            assertThat(files(dir)).isEqualTo(before);
            assertThat(references.resolve("gradient.png")).hasBinaryContent(old);
        }

        @Test
        @DisplayName("only when the property says true")
        void onlyWhenAsked() throws IOException {
            ImageAssertions off = assertions.withLookups(key -> null, key -> "false");
            assertThatThrownBy(() -> off.assertMatches(cameraShowing(gradient()), "gradient"))
                    .hasMessageStartingWith("no reference image");
            assertThat(files(dir)).isEmpty();
        }
    }

    @Nested
    @DisplayName("the test report")
    class Reports {
        private final List<Map<String, String>> published = new ArrayList<>();
        private final TestReporter reporter = published::add;

        @Test
        @DisplayName("RenderReports publishes each render's image, scene, size, mode, threads, time, rays and Mrays/s")
        void renderFigures() {
            Scene scene = new Scene("background").setBackground(new Color(30, 60, 90));
            Camera camera = view().setImageWriter(new ImageWriter("junit/figures", 6, 4)).setRayTracer(new RayTracerBasic(scene))
                    .setMultithreading(2).setRenderListener(RenderReports.to(reporter)).build();
            RenderStats stats = camera.render();
            camera.render();
            assertThat(published).hasSize(2);
            assertThat(published.get(0)).containsOnlyKeys("image", "scene", "size", "mode", "threads", "time", "rays", "Mrays/s")
                    .containsEntry("image", "junit/figures").containsEntry("scene", "background").containsEntry("size", "6x4")
                    .containsEntry("mode", CameraReports.describe(camera)).containsEntry("threads", "2")
                    .containsEntry("rays", Long.toString(stats.totalRays()));
            assertThat(published.get(0).get("time")).matches("\\d+\\.\\d{3} s");
        }

        @Test
        @DisplayName("2024–25 flow: the render's and the write's entries name the test, the write's with its file and time")
        void courseYear5785() throws IOException {
            Camera camera = view().setResolution(3, 2).setRayTracer(new RayTracerBasic(new Scene("flow")))
                    .setRenderListener(RenderReports.to(reporter)).build();
            Path file = Path.of("images", "junit", "reports-5785.png");
            try {
                camera.renderImage().writeToImage("junit/reports-5785");
            } finally {
                Files.deleteIfExists(file);
            }
            String test = "ImageAssertionsTest.Reports.courseYear5785()";
            assertThat(published).hasSize(2);
            assertThat(published.get(0)).containsEntry("image", test).containsEntry("scene", "flow").containsEntry("threads", "0");
            assertThat(published.get(1)).containsOnlyKeys("image", "file", "write time").containsEntry("image", test)
                    .containsEntry("file", file.toAbsolutePath().toString());
            assertThat(published.get(1).get("write time")).matches("\\d+\\.\\d{3} s");
        }

        @Test
        @DisplayName("the assertion publishes its verdict, PSNR, largest difference and failing pixels")
        void verdicts() {
            png(references.resolve("gradient.png"), gradient());
            assertions.reportingTo(reporter).assertMatches(cameraShowing(gradient()), "gradient");
            catchThrowableOfType(AssertionFailedError.class,
                    () -> assertions.reportingTo(reporter).assertMatches(cameraShowing(greenUp(gradient(), 7, 5, 25)), "gradient"));
            assertThat(published).hasSize(2);
            assertThat(published.get(0)).containsEntry("image", "gradient.png").containsEntry("verdict", "PASS")
                    .containsEntry("PSNR", "inf dB").containsEntry("failing pixels", "0.000% (0 of 768)");
            assertThat(published.get(1)).containsEntry("verdict", "FAIL").containsEntry("PSNR", "53.8 dB")
                    .containsEntry("max difference", "0.0980 at (7,5) channel 1")
                    .containsEntry("diff", output.resolve("ImageAssertionsTest.Reports.verdicts").resolve("gradient.diff.png").toString())
                    .containsKey("heat map");
        }

        @Test
        @DisplayName("a render listener is required to be someone")
        void nullListener() {
            assertThatThrownBy(() -> view().setRenderListener(null)).isInstanceOf(NullPointerException.class)
                    .hasMessage("render listener");
        }

        @Test
        @DisplayName("through JUnit itself: the entries reach the engine's listeners (the IDE, Surefire's report)")
        void throughJUnit() {
            List<ReportEntry> entries = EngineTestKit.engine("junit-jupiter").selectors(selectClass(ReportingSample.class))
                    .configurationParameter(ReportingSample.RUN, "true").execute().allEvents().reportingEntryPublished().stream()
                    .map(e -> e.getRequiredPayload(ReportEntry.class)).toList();
            assertThat(entries).hasSize(2);
            assertThat(entries.get(0).getKeyValuePairs()).containsEntry("image", "sample").containsEntry("size", "5x5");
            assertThat(entries.get(1).getKeyValuePairs()).containsEntry("verdict", "PASS");
        }
    }

    /**
     * Two scene tests as users write them, each failing against one shared reference with its
     * own render, run by {@link Failure#twoTestsOneReference} alone (never by Surefire).
     */
    @ExtendWith(ReportingSample.OnlyInTestKit.class)
    static class SharedReferenceSample {
        static final int FIRST_STEPS = 9, SECOND_STEPS = 30;
        /** The calling test's temporary folder, set before the test kit runs the sample. */
        static volatile Path dir;

        private static void fails(int steps) {
            ImageAssertions assertions = ImageAssertions.defaults().withReferenceFolder(dir.resolve("references"))
                    .withOutputFolder(dir.resolve("output")).withLookups(key -> null, key -> null);
            png(dir.resolve("references").resolve("gradient.png"), gradient());
            assertions.assertMatches(cameraShowing(greenUp(gradient(), 3, 3, steps)), "gradient");
        }

        @Test
        void first() {
            fails(FIRST_STEPS);
        }

        @Test
        void second() {
            fails(SECOND_STEPS);
        }
    }

    /** A scene test as a user writes it, run by {@link Reports#throughJUnit} alone (never by Surefire). */
    @ExtendWith(ReportingSample.OnlyInTestKit.class)
    static class ReportingSample {
        static final String RUN = "renderer.junit.sample";

        /** Lets the sample run only when the test kit passes {@link #RUN}. */
        static class OnlyInTestKit implements ExecutionCondition {
            @Override
            public ConditionEvaluationResult evaluateExecutionCondition(ExtensionContext context) {
                return context.getConfigurationParameter(RUN).isPresent() ? ConditionEvaluationResult.enabled("test kit")
                        : ConditionEvaluationResult.disabled("run by ImageAssertionsTest through the test kit only");
            }
        }

        @Test
        void rendersAndMatches(TestReporter reporter, @TempDir Path folder) {
            Camera camera = view().setImageWriter(new ImageWriter("sample", 5, 5)).setRenderListener(RenderReports.to(reporter))
                    .build().renderImage();
            camera.getImageWriter().writeToImage(folder.resolve("sample.png"));
            ImageAssertions.defaults().withReferenceFolder(folder).reportingTo(reporter).assertMatches(camera, "sample");
        }
    }
}
