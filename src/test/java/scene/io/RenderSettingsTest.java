package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.lang.reflect.RecordComponent;
import java.util.Map;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Color;
import primitives.Point;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;

/**
 * {@link RenderSettings}: what {@code applyTo} sets on a camera builder. Cameras are only built
 * and described here, never rendered.
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

    @Nested
    @DisplayName("anti-aliasing: the grid belongs to RANDOM alone")
    class AntiAliasingGrid {
        @Test
        @DisplayName("RANDOM sets its grid")
        void random() {
            RenderSettings s = RenderSettings.defaults("x").withAntiAliasing(AntiAliasing.RANDOM)
                    .withAntiAliasingParameters(3, 5, 3, 8);
            assertThat(apply(s, view()).describe()).startsWith("RANDOM 3x5,");
        }

        /**
         * The camera accepts a grid only together with RANDOM, so for the other modes the
         * settings do not pass theirs: a grid set on the builder before stays.
         */
        @ParameterizedTest(name = "{0}")
        @EnumSource(value = AntiAliasing.class, names = "RANDOM", mode = EnumSource.Mode.EXCLUDE)
        @DisplayName("another mode leaves the builder's grid alone")
        void otherModes(AntiAliasing mode) {
            RenderSettings s = RenderSettings.defaults("x").withAntiAliasing(mode).withAntiAliasingParameters(3, 5, 3, 8);
            Camera.Builder camera = view().setAntiAliasingGrid(7, 2);
            assertThat(apply(s, camera).describe()).startsWith(mode.name());
            assertThat(camera.setAntiAliasing(AntiAliasing.RANDOM).setSummary(false).build().describe())
                    .startsWith("RANDOM 7x2,");
        }
    }

    @Nested
    @DisplayName("each with… method changes the values it names and nothing else")
    class With {
        /** Every value differs from the defaults and from every other value of its type. */
        private static final RenderSettings BASE = new RenderSettings("base", 10, 20, 3, new Color(1, 2, 3),
                AntiAliasing.CORNERS, 4, 5, 6, 7.5, 8.5, 9.5, 11, 12, 13L, false, 14, 15);
        private static final Color GREEN = new Color(0, 255, 0);

        static Stream<Arguments> edits() {
            return Stream.of(
                    edit("withImage", s -> s.withImage("other", 30, 40), Map.of("imageName", "other", "width", 30, "height", 40)),
                    edit("withGrid", s -> s.withGrid(50, GREEN), Map.of("gridInterval", 50, "gridColor", GREEN)),
                    edit("withAntiAliasing", s -> s.withAntiAliasing(AntiAliasing.ADAPTIVE),
                            Map.of("antiAliasing", AntiAliasing.ADAPTIVE)),
                    edit("withAntiAliasingParameters", s -> s.withAntiAliasingParameters(60, 70, 2, 80.5),
                            Map.of("aaColumns", 60, "aaRows", 70, "adaptiveDepth", 2, "adaptiveThreshold", 80.5)),
                    edit("withDepthOfField", s -> s.withDepthOfField(90.5, 100.5, 110),
                            Map.of("focalDistance", 90.5, "aperture", 100.5, "dofSamples", 110)),
                    edit("withThreads", s -> s.withThreads(120), Map.of("threads", 120)),
                    edit("withSeed", s -> s.withSeed(-130L), Map.of("seed", -130L)),
                    edit("withTracer", s -> s.withTracer(true, 140, 150),
                            Map.of("bvh", true, "beamSize", 140, "shadowSamples", 150)));
        }

        private static Arguments edit(String name, UnaryOperator<RenderSettings> change, Map<String, Object> changed) {
            return Arguments.of(name, change, changed);
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("edits")
        void changesWhatItNames(String name, UnaryOperator<RenderSettings> change, Map<String, Object> changed)
                throws ReflectiveOperationException {
            RenderSettings edited = change.apply(BASE);
            for (RecordComponent c : RenderSettings.class.getRecordComponents()) {
                Object expected = changed.containsKey(c.getName()) ? changed.get(c.getName())
                        : c.getAccessor().invoke(BASE);
                assertThat(c.getAccessor().invoke(edited)).as(c.getName()).isEqualTo(expected);
            }
        }

        @Test
        @DisplayName("the defaults, value by value")
        void defaults() {
            RenderSettings d = RenderSettings.defaults("scene");
            assertThat(d).isEqualTo(new RenderSettings("scene", 500, 500, 0, RenderSettings.DEFAULT_GRID_COLOR,
                    AntiAliasing.NONE, 4, 4, 3, 8, 0, 0, 16, -2, 0, true, 16, 16));
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
    @DisplayName("the ray budget: samples per pixel × beam size × shadow samples at most 2^24")
    class RayBudget {
        @ParameterizedTest(name = "{0}")
        @CsvSource({ "NONE, 1", "CORNERS, 5", "RANDOM, 12", "ADAPTIVE, 81" })
        @DisplayName("samples per pixel of each mode (ADAPTIVE: its whole lattice at depth 3, (2^3 + 1)² points)")
        void samplesPerPixel(AntiAliasing mode, long samples) {
            RenderSettings s = RenderSettings.defaults("x").withAntiAliasingParameters(3, 4, 3, 8).withAntiAliasing(mode);
            assertThat(s.samplesPerPixel()).isEqualTo(samples);
        }

        @Test
        @DisplayName("lens samples count without anti-aliasing")
        void lensSamples() {
            assertThat(RenderSettings.defaults("x").withDepthOfField(10, 1, 40).samplesPerPixel()).isEqualTo(40);
        }

        @Test
        @DisplayName("up to the budget accepted; one factor more refused, naming every factor")
        void limit() {
            RenderSettings grid = RenderSettings.defaults("x").withAntiAliasingParameters(256, 256, 3, 8)
                    .withAntiAliasing(AntiAliasing.RANDOM);
            assertThat(grid.withTracer(true, 16, 16).samplesPerPixel() * 16 * 16).isEqualTo(RenderSettings.MAX_RAYS_PER_PIXEL);
            assertThatThrownBy(() -> grid.withTracer(true, 17, 16)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("RANDOM sampling with 65536 samples per pixel × beam size 17 × 16 shadow samples is 17825792"
                            + " rays per pixel, more than the limit of 16777216");
        }

        @Test
        @DisplayName("factors whose product overflows a long are still refused")
        void noOverflow() {
            assertThatThrownBy(() -> RenderSettings.defaults("x").withAntiAliasingParameters(65536, 65536, 3, 8)
                    .withAntiAliasing(AntiAliasing.RANDOM).withTracer(true, Integer.MAX_VALUE, Integer.MAX_VALUE))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("more than the limit of 16777216");
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
                            + " (the file name would display as something else)");
        }

        @Test
        @DisplayName("at most 200 characters")
        void length() {
            RenderSettings.defaults("x".repeat(RenderSettings.MAX_IMAGE_NAME_LENGTH));
            assertThatThrownBy(() -> RenderSettings.defaults("x".repeat(201))).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("the image name has 201 characters, more than the limit of 200");
        }
    }
}
