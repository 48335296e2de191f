package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowable;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import lighting.DirectionalLight;
import lighting.PointLight;
import geometries.Sphere;
import primitives.Color;
import primitives.Point;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.CameraValues;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.Sampling;
import scene.Scene;

/**
 * {@link RenderSettings} as a specification: it states only what it is given, replays that onto a
 * camera builder, and leaves everything else, defaults and limits, to the library. Cameras are
 * built here and compared by their values ({@link CameraValues}); a few are rendered to show what a
 * value does.
 */
class RenderSettingsTest {
    private static final Scene SCENE = new Scene("empty");

    /** A builder with a complete view, ready for the settings. */
    private static Camera.Builder view() {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(0, 0, -1)).setVpSize(1, 1)
                .setVpDistance(1);
    }

    private static Camera apply(RenderSettings settings, Camera.Builder camera) {
        return settings.applyTo(camera, SCENE, new ImageWriter("settings", 1, 1)).setSummary(false).build();
    }

    /** A sphere at distance 10 whose edge a lens blurs. */
    private static final Scene SPHERE = new Scene("sphere");

    static {
        SPHERE.geometries.add(new Sphere(new Point(0, 0, -10), 2).setEmission(new Color(200, 100, 50)));
    }

    /** A view of {@link #SPHERE}, 6×6 scene units at distance 10. */
    private static Camera.Builder lensView() {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(0, 0, -1)).setVpSize(6, 6)
                .setVpDistance(10);
    }

    /** Replays {@code settings} onto {@code camera} over {@link #SPHERE}, renders 6×6 pixels and returns them, row-major. */
    private static int[] pixels(RenderSettings settings, Camera.Builder camera) {
        Camera rendered = settings.applyTo(camera, SPHERE, new ImageWriter("settings", 6, 6)).setSummary(false).build()
                .renderImage();
        int[] rgb = new int[36];
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 6; ++x) rgb[y * 6 + x] = rendered.getImageWriter().getRgb(x, y);
        return rgb;
    }

    /** The values of a camera built with the library's defaults and {@code change}. */
    private static CameraValues library(UnaryOperator<Camera.Builder> change) {
        return CameraValues.of(change.apply(view()).setSummary(false).build());
    }

    @Nested
    @DisplayName("replayed onto the builder: each stated value through the builder's own setter, nothing else")
    class Replay {
        @Test
        @DisplayName("a specification that states nothing leaves the camera as the library makes it")
        void nothingStated() {
            assertThat(CameraValues.of(apply(RenderSettings.empty(), view()))).isEqualTo(library(b -> b));
            assertThat(RenderSettings.empty()).hasToString("RenderSettings[]");
        }

        static Stream<Arguments> statements() {
            return Stream.of(
                    Arguments.of("withAntiAliasing", (UnaryOperator<RenderSettings>) s -> s.withAntiAliasing(AntiAliasing.CORNERS),
                            (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.CORNERS)),
                    Arguments.of("withAntiAliasingGrid", (UnaryOperator<RenderSettings>) s -> s
                            .withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(3, 5),
                            (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.RANDOM, 3, 5)),
                    Arguments.of("withAdaptiveDepth and withAdaptiveThreshold", (UnaryOperator<RenderSettings>) s -> s
                            .withAntiAliasing(AntiAliasing.ADAPTIVE).withAdaptiveDepth(5).withAdaptiveThreshold(2.5),
                            (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(5, 2.5)),
                    Arguments.of("withDepthOfField and withDepthOfFieldSamples", (UnaryOperator<RenderSettings>) s -> s
                            .withDepthOfField(900, 5).withDepthOfFieldSamples(12),
                            (UnaryOperator<Camera.Builder>) b -> b.setDepthOfField(900, 5).setDepthOfFieldSamples(12)),
                    Arguments.of("withSeed", (UnaryOperator<RenderSettings>) s -> s.withSeed(-42),
                            (UnaryOperator<Camera.Builder>) b -> b.setSeed(-42)),
                    Arguments.of("withBvh, withBeamSize and withShadowSamples", (UnaryOperator<RenderSettings>) s -> s
                            .withBvh(false).withBeamSize(7).withShadowSamples(9),
                            (UnaryOperator<Camera.Builder>) b -> b.setRayTracer(new renderer.RayTracerBasic(SCENE)
                                    .setBvh(false).setBeamSize(7).setShadowSamples(9))));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("statements")
        @DisplayName("the camera is the one the builder's setters make")
        void sameAsTheSetters(String name, UnaryOperator<RenderSettings> statement, UnaryOperator<Camera.Builder> setters) {
            CameraValues replayed = CameraValues.of(apply(statement.apply(RenderSettings.empty()), view()));
            assertThat(replayed).isEqualTo(library(setters)).as("a change from the library's camera")
                    .isNotEqualTo(library(b -> b));
        }

        @Test
        @DisplayName("what is not stated stays as the builder has it")
        void unstatedStays() {
            Camera.Builder camera = view().setAntiAliasingGrid(7, 2).setSeed(9).setAdaptive(5, 2.5);
            apply(RenderSettings.empty().withAntiAliasing(AntiAliasing.RANDOM), camera);
            assertThat(CameraValues.of(camera.setSummary(false).build()).sampling()).isEqualTo(Sampling.DEFAULT
                    .withAntiAliasing(AntiAliasing.RANDOM).withGrid(7, 2).withAdaptive(5, 2.5).withSeed(9));
        }

        /** The builder keeps the grid for RANDOM whatever the mode: a later {@code --aa random} finds it. */
        @Test
        @DisplayName("a stated grid is replayed whatever the mode")
        void gridWithAnotherMode() {
            Camera corners = apply(RenderSettings.empty().withAntiAliasing(AntiAliasing.CORNERS).withAntiAliasingGrid(3, 5), view());
            assertThat(CameraValues.of(corners).sampling()).isEqualTo(Sampling.DEFAULT.withAntiAliasing(AntiAliasing.CORNERS)
                    .withGrid(3, 5));
            assertThat(CameraValues.of(Camera.getBuilder(corners).setAntiAliasing(AntiAliasing.RANDOM).build()).sampling()
                    .grid()).isEqualTo(new Sampling.Grid(3, 5));
        }

        /** Focal distance 0 is the pinhole whatever the aperture (it was a lens focused at 1 for aperture 5). */
        @ParameterizedTest(name = "withDepthOfField(0, {0})")
        @ValueSource(doubles = { 0, 5 })
        @DisplayName("a stated pinhole (focal distance 0, any aperture) renders as the pinhole, undoing a lens set before")
        void pinhole(double aperture) {
            RenderSettings pinhole = RenderSettings.defaults("x").withDepthOfField(0, aperture);
            int[] library = pixels(RenderSettings.empty(), lensView());
            assertThat(pixels(pinhole, lensView().setDepthOfField(10, 2))).as("the pixels of the stated pinhole")
                    .isEqualTo(library);
            assertThat(pixels(RenderSettings.empty(), lensView().setDepthOfField(1, 5)))
                    .as("a lens focused at 1, to show the scene tells it from the pinhole").isNotEqualTo(library);
        }

        @Test
        @DisplayName("a specification without an image name replays an unnamed image of the format's size")
        void noImageName() {
            Camera camera = RenderSettings.empty().applyTo(view(), SCENE).setSummary(false).build();
            assertThat(camera.getImageWriter().getImageName()).isEqualTo("(unnamed)");
            assertThat(camera.getImageWriter().getNx()).isEqualTo(RenderSettings.DEFAULT_SIZE);
            assertThat(camera.getImageWriter().getNy()).isEqualTo(RenderSettings.DEFAULT_SIZE);
        }

        /** A half-stated ADAPTIVE pair is completed with the builder's own value of the other half. */
        @ParameterizedTest(name = "{0}")
        @CsvSource({ "depth only, 5, ", "threshold only, , 2.5" })
        @DisplayName("ADAPTIVE's depth or threshold alone: the other is the library's")
        void adaptiveHalf(String name, Integer depth, Double threshold) {
            RenderSettings s = RenderSettings.empty().withAntiAliasing(AntiAliasing.ADAPTIVE);
            if (depth != null) s = s.withAdaptiveDepth(depth);
            if (threshold != null) s = s.withAdaptiveThreshold(threshold);
            Sampling.Adaptive library = library(b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE)).sampling().adaptive();
            int expectedDepth = depth != null ? depth : library.depth();
            double expectedThreshold = threshold != null ? threshold : library.threshold();
            assertThat(CameraValues.of(apply(s, view())))
                    .isEqualTo(library(b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(expectedDepth, expectedThreshold)));
            assertThat(new Sampling.Adaptive(expectedDepth, expectedThreshold)).as("the stated half, the library's other")
                    .isNotEqualTo(library);
        }

        @Test
        @DisplayName("a value the library refuses is refused when replayed, with the library's message")
        void refusedByTheLibrary() {
            assertThatThrownBy(() -> apply(RenderSettings.empty().withAdaptiveDepth(7), view()))
                    .isInstanceOf(IllegalArgumentException.class).hasMessage("adaptive depth must be in 1..6, got 7");
            assertThatThrownBy(() -> apply(RenderSettings.empty().withBeamSize(0), view()))
                    .isInstanceOf(IllegalArgumentException.class).hasMessage("beam size must be at least 1 ray, got 0");
        }
    }

    @Nested
    @DisplayName("then: a second specification replayed after the first (a command line's options over a file)")
    class Then {
        /** A specification that states every value, each different from the one of LATER. */
        private static final RenderSettings FILE = RenderSettings.defaults("file").withImage("file", 10, 20)
                .withGrid(3, new Color(1, 2, 3)).withAntiAliasing(AntiAliasing.CORNERS).withAntiAliasingGrid(4, 5)
                .withAdaptiveDepth(6).withAdaptiveThreshold(7.5).withDepthOfField(8.5, 9.5).withDepthOfFieldSamples(11)
                .withThreads(1).withSeed(13).withBvh(false).withBeamSize(14).withShadowSamples(15);

        static Stream<Arguments> later() {
            return Stream.of(
                    Arguments.of("withImage", (UnaryOperator<RenderSettings>) s -> s.withImage("other", 30, 40)),
                    Arguments.of("withImageSize", (UnaryOperator<RenderSettings>) s -> s.withImageSize(30, 40)),
                    Arguments.of("withGrid", (UnaryOperator<RenderSettings>) s -> s.withGrid(50, new Color(0, 255, 0))),
                    Arguments.of("withAntiAliasing", (UnaryOperator<RenderSettings>) s -> s.withAntiAliasing(AntiAliasing.ADAPTIVE)),
                    Arguments.of("withAntiAliasingGrid", (UnaryOperator<RenderSettings>) s -> s.withAntiAliasingGrid(60, 70)),
                    Arguments.of("withAdaptiveDepth", (UnaryOperator<RenderSettings>) s -> s.withAdaptiveDepth(2)),
                    Arguments.of("withAdaptiveThreshold", (UnaryOperator<RenderSettings>) s -> s.withAdaptiveThreshold(80.5)),
                    Arguments.of("withDepthOfField", (UnaryOperator<RenderSettings>) s -> s.withDepthOfField(90.5, 100.5)),
                    Arguments.of("withDepthOfFieldSamples", (UnaryOperator<RenderSettings>) s -> s.withDepthOfFieldSamples(110)),
                    Arguments.of("withThreads", (UnaryOperator<RenderSettings>) s -> s.withThreads(2)),
                    Arguments.of("withSeed", (UnaryOperator<RenderSettings>) s -> s.withSeed(-130)),
                    Arguments.of("withBvh", (UnaryOperator<RenderSettings>) s -> s.withBvh(true)),
                    Arguments.of("withBeamSize", (UnaryOperator<RenderSettings>) s -> s.withBeamSize(140)),
                    Arguments.of("withShadowSamples", (UnaryOperator<RenderSettings>) s -> s.withShadowSamples(150)));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("later")
        @DisplayName("the later's stated values win; the first's stay elsewhere")
        void laterWins(String name, UnaryOperator<RenderSettings> statement) {
            RenderSettings later = statement.apply(RenderSettings.empty());
            assertThat(later).as("states something").isNotEqualTo(RenderSettings.empty());
            assertThat(FILE.then(later)).isEqualTo(statement.apply(FILE)).isNotEqualTo(FILE);
        }

        @Test
        @DisplayName("nothing stated on either side changes nothing")
        void identity() {
            assertThat(FILE.then(RenderSettings.empty())).isEqualTo(FILE);
            assertThat(RenderSettings.empty().then(FILE)).isEqualTo(FILE);
        }
    }

    @Nested
    @DisplayName("the format's own values: the image and the thread count")
    class FormatDefaults {
        @Test
        @DisplayName("a file that states nothing: its name, 500×500, no grid, yellow")
        void image() {
            RenderSettings d = RenderSettings.defaults("scene");
            assertThat(d.imageName()).isEqualTo("scene");
            assertThat(new int[] { d.width(), d.height(), d.gridInterval() }).containsExactly(500, 500, 0);
            assertThat(d.gridColor().toRgb()).isEqualTo(java.awt.Color.YELLOW.getRGB() & 0xFFFFFF);
            assertThat(d).hasToString("RenderSettings[image=scene]");
        }

        @Test
        @DisplayName("threads: all cores unless stated, where the builder's default is the calling thread")
        void threads() {
            Camera.Builder unstated = view();
            apply(RenderSettings.empty(), unstated);
            Camera.Builder stated = view();
            apply(RenderSettings.empty().withThreads(0), stated);
            assertThat(threadsOf(unstated)).isEqualTo(Runtime.getRuntime().availableProcessors());
            assertThat(threadsOf(stated)).isZero();
        }

        /** The thread count a builder's camera renders with, as its render reports it (a 1×1 empty image). */
        private static int threadsOf(Camera.Builder camera) {
            return camera.setSummary(false).build().render().threads();
        }

        @Test
        @DisplayName("drawGrid draws only when a grid is stated")
        void grid() {
            Camera noGrid = apply(RenderSettings.defaults("x"), view());
            RenderSettings.defaults("x").drawGrid(noGrid);
            assertThat(noGrid.getImageWriter().getRgb(0, 0)).isZero();
            Camera grid = apply(RenderSettings.defaults("x").withGrid(1, new Color(0, 255, 0)), view());
            RenderSettings.defaults("x").withGrid(1, new Color(0, 255, 0)).drawGrid(grid);
            assertThat(grid.getImageWriter().getRgb(0, 0)).isEqualTo(0x00FF00);
        }
    }

    @Nested
    @DisplayName("the ray budget: the library's, checked as build() checks it")
    class RayBudget {
        static Stream<RenderSettings> specifications() {
            RenderSettings none = RenderSettings.empty();
            return Stream.of(none, none.withBeamSize(1 << 16).withShadowSamples(1 << 8),
                    none.withBeamSize(1 << 16).withShadowSamples((1 << 8) + 1),
                    none.withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(256, 256),
                    none.withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(256, 256).withBeamSize(17),
                    none.withAntiAliasingGrid(256, 256).withBeamSize(17),
                    none.withAntiAliasing(AntiAliasing.ADAPTIVE).withAdaptiveDepth(6).withBeamSize(248),
                    none.withAntiAliasing(AntiAliasing.ADAPTIVE).withAdaptiveDepth(6).withBeamSize(256),
                    none.withAntiAliasing(AntiAliasing.ADAPTIVE).withBeamSize(256).withShadowSamples(256),
                    none.withDepthOfField(10, 1).withDepthOfFieldSamples(60000).withBeamSize(100),
                    none.withAntiAliasing(AntiAliasing.CORNERS).withDepthOfField(10, 1).withDepthOfFieldSamples(60000)
                            .withBeamSize(100),
                    none.withBeamSize(Integer.MAX_VALUE).withShadowSamples(Integer.MAX_VALUE));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("specifications")
        @DisplayName("requireRayBudget refuses exactly what building the camera refuses, with its message")
        void sameAsBuild(RenderSettings s) {
            Throwable built = catchThrowable(() -> apply(s, view()));
            Throwable checked = catchThrowable(() -> s.requireRayBudget(SCENE));
            if (built == null) assertThat(checked).isNull();
            else assertThat(checked).isInstanceOf(IllegalArgumentException.class).hasMessage(built.getMessage())
                    .hasMessageContaining("more than the limit of " + RenderSettings.MAX_RAYS_PER_PIXEL);
        }

        @Test
        @DisplayName("the library's figures: a 256×256 grid with beams of 127 is the limit; ADAPTIVE depth 3 at 256×256 fits")
        void figures() {
            RenderSettings grid = RenderSettings.empty().withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(256, 256);
            assertThat(grid.withBeamSize(127).requireRayBudget(SCENE)).isNotNull(); // 65536 × 255
            assertThatThrownBy(() -> grid.withBeamSize(128).requireRayBudget(SCENE)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("RANDOM sampling with 65536 samples per pixel × (1 + 2 beams of 128 rays: reflection and"
                            + " transmission) × (1 + 16 shadow samples × 0 soft lights + 0 other lights) is 16842752"
                            + " rays per pixel, more than the limit of 16777216");
            // The lattice of depth 3 traces at most (2^3 + 1)² = 81 camera rays: 81 × 513 × 257 < 2^24.
            Scene oneSoftLight = new Scene("soft");
            oneSoftLight.lights.add(new PointLight(new Color(1, 1, 1), new Point(0, 5, 0)).setRadius(1));
            RenderSettings.empty().withAntiAliasing(AntiAliasing.ADAPTIVE).withBeamSize(256).withShadowSamples(256)
                    .requireRayBudget(oneSoftLight);
        }

        @Test
        @DisplayName("requireRayBudget(scene) counts the scene's lights: shadow samples for each soft light, one ray for each other")
        void lights() {
            Scene scene = new Scene("lights");
            RenderSettings s = RenderSettings.empty().withBeamSize(256).withShadowSamples(256);
            for (int i = 0; i < 127; ++i) scene.lights.add(new PointLight(new Color(1, 1, 1), new Point(0, 5, i)).setRadius(1));
            assertThat(s.requireRayBudget(scene)).isSameAs(s); // 513 × 32,513
            scene.lights.add(new DirectionalLight(new Color(1, 1, 1), new Vector(0, -1, 0)));
            assertThat(s.requireRayBudget(scene)).isSameAs(s); // 513 × 32,514
            scene.lights.add(new PointLight(new Color(1, 1, 1), new Point(0, 5, -1)).setRadius(1));
            assertThatThrownBy(() -> s.requireRayBudget(scene)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("× (1 + 256 shadow samples × 128 soft lights + 1 other light) is 16811010 rays");
        }
    }

    @Nested
    @DisplayName("the image size: each side at least 1, at most MAX_PIXELS pixels, checked without allocating")
    class ImageSize {
        @ParameterizedTest(name = "{0}x{1}")
        @CsvSource({ "0, 1", "1, 0", "-3, 5", "50000, 50000", "1, 2147483640", "16383, 131080" })
        @DisplayName("refused, naming the size")
        void refused(int width, int height) {
            assertThatThrownBy(() -> RenderSettings.defaults("x").withImage("x", width, height))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining(width + "x" + height);
            assertThatThrownBy(() -> RenderSettings.empty().withImageSize(width, height))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining(width + "x" + height);
        }

        /** 16383 × 131080 = 2^31 - 8 = MAX_PIXELS + 1 (16383 = 2^14 - 1, 131080 = 8 (2^14 + 1)). */
        @Test
        @DisplayName("the limit is ImageWriter's: one pixel more and both refuse")
        void imageWritersLimit() {
            assertThat(16383L * 131080).isEqualTo(RenderSettings.MAX_PIXELS + 1);
            assertThatThrownBy(() -> new ImageWriter("x", 16383, 131080)).isInstanceOf(IllegalArgumentException.class);
            assertThatThrownBy(() -> RenderSettings.defaults("x").withImage("x", 16383, 131080))
                    .isInstanceOf(IllegalArgumentException.class);
        }

        @ParameterizedTest(name = "{0}x{1}")
        @CsvSource({ "1, 1", "2147483639, 1", "1, 2147483639", "46340, 46340" })
        @DisplayName("accepted up to the limit (nothing is allocated)")
        void accepted(int width, int height) {
            RenderSettings s = RenderSettings.defaults("x").withImage("x", width, height);
            assertThat(new int[] { s.width(), s.height() }).containsExactly(width, height);
        }
    }

    @Nested
    @DisplayName("the image name is a file name in images/, not a path")
    class ImageName {
        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = { "/tmp/x", "../../x", "a/b", "a\\b", "c:x", "..", "a..b",
                "tab\there", " " })
        @DisplayName("refused")
        void refused(String name) {
            assertThatThrownBy(() -> RenderSettings.defaults(name)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageStartingWith("the image name");
        }

        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = { "x", "two colors", "teapot-1.5", "été" })
        @DisplayName("accepted")
        void accepted(String name) {
            assertThat(RenderSettings.defaults(name).imageName()).isEqualTo(name);
        }

        @ParameterizedTest(name = "U+{0}")
        @CsvSource({ "202E", "202A", "2066", "2069", "200E", "200F", "061C", "200B", "FEFF", "2060" })
        @DisplayName("refused: bidirectional controls and invisible format characters, naming the code point")
        void invisible(String hex) {
            String name = "invoice" + Character.toString(Integer.parseInt(hex, 16)) + "gnp.exe";
            assertThatThrownBy(() -> RenderSettings.defaults(name)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("the image name contains U+" + hex + ", an invisible or direction-changing character"
                            + " (the file name would display as something else, or not at all)");
        }

        @ParameterizedTest(name = "U+{0}: {1}")
        @CsvSource(delimiter = '|', value = {
                "3164|an invisible character (Unicode's Default_Ignorable_Code_Point)", // Hangul filler, a letter by category
                "115F|an invisible character (Unicode's Default_Ignorable_Code_Point)",
                "FFA0|an invisible character (Unicode's Default_Ignorable_Code_Point)",
                "034F|an invisible character (Unicode's Default_Ignorable_Code_Point)", // combining grapheme joiner
                "FE0F|an invisible character (Unicode's Default_Ignorable_Code_Point)", // variation selector
                "2800|a blank-looking character (the empty braille pattern)",
                "1D159|a blank-looking character (the musical null notehead)",
                "16FE4|a blank-looking character (the Khitan small script filler)",
                "2028|a line or paragraph separator",
                "00A0|a space other than U+0020 (it looks like one and is another character)",
                "3000|a space other than U+0020 (it looks like one and is another character)",
                "009B|a control character", // C1: a terminal's control sequence introducer
                "0007|a control character",
                "E000|a private-use, unassigned or surrogate code point" })
        @DisplayName("refused: every character that would not show as what it is, naming the code point and its kind")
        void hidden(String hex, String kind) {
            String name = "render" + Character.toString(Integer.parseInt(hex, 16)) + "1";
            assertThatThrownBy(() -> RenderSettings.defaults(name)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("the image name contains U+" + hex + ", " + kind
                            + " (the file name would display as something else, or not at all)");
        }

        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = { "תמונה 1", "שָׁלוֹם", "e\u0301te", "日本", "a+b (2)", "x_y-z.v2" })
        @DisplayName("accepted: letters of any script with their marks (Hebrew points, combining accents), digits, punctuation, the plain space")
        void visibleNames(String name) {
            assertThat(RenderSettings.defaults(name).imageName()).isEqualTo(name);
        }

        @Test
        @DisplayName("at most 200 characters")
        void length() {
            RenderSettings.defaults("x".repeat(RenderSettings.MAX_IMAGE_NAME_LENGTH));
            assertThatThrownBy(() -> RenderSettings.defaults("x".repeat(201))).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("the image name has 201 characters, more than the limit of 200");
        }
    }

    @Test
    @DisplayName("serialized and read back (as a cluster's executors receive it): equal, the stated values kept")
    void serializable() throws IOException, ClassNotFoundException {
        RenderSettings s = Then.FILE.then(RenderSettings.empty().withAntiAliasing(AntiAliasing.RANDOM));
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(s);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            Object copy = in.readObject();
            assertThat(copy).isEqualTo(s).hasSameHashCodeAs(s).hasToString(s.toString());
        }
    }
}
