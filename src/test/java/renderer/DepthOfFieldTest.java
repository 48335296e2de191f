package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Polygon;
import primitives.Color;
import primitives.Point;
import scene.Scene;

/**
 * The thin lens. Two white boards on black, both with a vertical edge on the camera's axis
 * (x = 0): the upper-left one at the focal distance (z = 0, 10 from the camera), the lower-left
 * one 30 behind it. A lens ray through focal point F from lens point u (|u| ≤ aperture) reaches
 * the far board at 4F − 3u, so the far edge is blurred over ±0.75·aperture on the focal plane,
 * i.e. ±7.5 pixels per unit of aperture (0.1 units per pixel); the near edge is not blurred.
 */
class DepthOfFieldTest {
    private static final int SIZE = 40;
    /** Row 5 sees y = 1.45 on the focal plane (only the near board); row 34 sees y = −1.45 (only the far one). */
    private static final int NEAR_ROW = 5, FAR_ROW = 34;

    /** Two white boards on black: a near one in focus and a far one 30 behind it (shared with NoiseAdaptiveSamplerTest). */
    static Scene boards() {
        Color white = new Color(255, 255, 255);
        Scene scene = new Scene("boards");
        scene.geometries.add(
                new Polygon(new Point(-100, 0, 0), new Point(0, 0, 0), new Point(0, 100, 0), new Point(-100, 100, 0))
                        .setEmission(white),
                new Polygon(new Point(-400, -400, -30), new Point(0, -400, -30), new Point(0, 0, -30),
                        new Point(-400, 0, -30)).setEmission(white));
        return scene;
    }

    private static ImageWriter render(UnaryOperator<Camera.Builder> settings) {
        ImageWriter image = new ImageWriter("dof", SIZE, SIZE);
        settings.apply(TestScenes.camera(boards(), image)).setMultithreading(2).build().renderImage();
        return image;
    }

    /** The number of pixels of row y strictly between 10 % and 90 % of the white-to-black step. */
    private static int edgeWidth(ImageWriter image, int y) {
        int count = 0;
        for (int x = 0; x < SIZE; ++x) {
            int r = Pixels.red(image.getRgb(x, y));
            if (r > 0.1 * 255 && r < 0.9 * 255) ++count;
        }
        return count;
    }

    /** The row's first column darker than half white: where the edge is. */
    private static int edgeColumn(ImageWriter image, int y) {
        for (int x = 0; x < SIZE; ++x)
            if (Pixels.red(image.getRgb(x, y)) < 128) return x;
        return SIZE;
    }

    private static UnaryOperator<Camera.Builder> lens(double aperture) {
        return b -> b.setDepthOfField(10, aperture).setDepthOfFieldSamples(64);
    }

    @Test
    @DisplayName("the pinhole camera shows both edges sharp, at the image centre")
    void pinholeSharp() {
        ImageWriter image = render(b -> b);
        for (int y : new int[] {NEAR_ROW, FAR_ROW}) {
            assertThat(edgeWidth(image, y)).as("row %d", y).isZero();
            assertThat(edgeColumn(image, y)).as("row %d", y).isEqualTo(SIZE / 2);
        }
    }

    @Test
    @DisplayName("with a lens, the edge at the focal distance stays sharp and the far edge blurs")
    void focalPlaneSharpFarBlurred() {
        ImageWriter image = render(lens(1));
        assertThat(edgeWidth(image, NEAR_ROW)).as("edge at the focal distance").isZero();
        assertThat(edgeColumn(image, NEAR_ROW)).isEqualTo(SIZE / 2);
        // A disk of radius 7.5 pixels spreads the step over about 10 pixels between 10 % and 90 %.
        assertThat(edgeWidth(image, FAR_ROW)).as("edge 30 behind the focal plane").isBetween(6, 14);
        assertThat(edgeColumn(image, FAR_ROW)).as("the blurred edge stays centred").isBetween(SIZE / 2 - 1, SIZE / 2 + 1);
    }

    @Test
    @DisplayName("the blur grows with the aperture")
    void blurGrowsWithAperture() {
        int small = edgeWidth(render(lens(0.3)), FAR_ROW), large = edgeWidth(render(lens(1)), FAR_ROW);
        assertThat(small).isPositive().isLessThan(large);
    }

    private static Arguments mode(String name, UnaryOperator<Camera.Builder> settings) {
        return Arguments.of(name, settings);
    }

    static Stream<Arguments> modes() {
        return Stream.of(
                mode("NONE", b -> b),
                mode("RANDOM 3x3", b -> b.setAntiAliasing(AntiAliasing.RANDOM, 3, 3)),
                mode("ADAPTIVE", b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(2, 8)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("modes")
    @DisplayName("aperture 0 reproduces the pinhole image byte for byte, random effects included")
    void zeroApertureIsPinhole(String name, UnaryOperator<Camera.Builder> mode) {
        ImageWriter pinhole = new ImageWriter("pinhole", 60, 40), lens = new ImageWriter("zero-aperture", 60, 40);
        mode.apply(TestScenes.camera(TestScenes.everyEffect(), pinhole)).setSeed(5).build().renderImage();
        mode.apply(TestScenes.camera(TestScenes.everyEffect(), lens)).setSeed(5).setDepthOfField(7, 0)
                .setDepthOfFieldSamples(8).build().renderImage();
        assertThat(Pixels.of(lens)).isEqualTo(Pixels.of(pinhole));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("modes")
    @DisplayName("setPinhole() after a depth of field turns it off: the pinhole image byte for byte, and the summary's words")
    void pinholeTurnsTheLensOff(String name, UnaryOperator<Camera.Builder> mode) {
        ImageWriter pinhole = new ImageWriter("pinhole", 60, 40), undone = new ImageWriter("lens-undone", 60, 40);
        Camera plain = mode.apply(TestScenes.camera(TestScenes.everyEffect(), pinhole)).setSeed(5).build();
        Camera off = mode.apply(TestScenes.camera(TestScenes.everyEffect(), undone)).setSeed(5).setDepthOfField(7, 2)
                .setPinhole().build();
        plain.renderImage();
        off.renderImage();
        assertThat(Pixels.of(undone)).isEqualTo(Pixels.of(pinhole));
        assertThat(off.describe()).isEqualTo(plain.describe()).doesNotContain("DOF");
    }
}
