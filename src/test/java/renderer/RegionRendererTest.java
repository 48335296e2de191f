package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Rectangles rendered apart assemble to the whole image's bytes, whatever their cut: the
 * property a distributed render (app.spark) rests on. The cuts are deliberately not aligned
 * with the render loop's tiles (16 pixels), so the lattice samplers'
 * per-tile caches start at other points than in the whole render.
 */
class RegionRendererTest {
    private static final int NX = 53, NY = 37;

    static Stream<Arguments> modes() {
        return Stream.of(
                Arguments.of("NONE", (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.NONE)),
                Arguments.of("RANDOM 2x3", (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.RANDOM, 2, 3)),
                Arguments.of("CORNERS", (UnaryOperator<Camera.Builder>) b -> b.setAntiAliasing(AntiAliasing.CORNERS)),
                Arguments.of("ADAPTIVE depth 2", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(2, 8)),
                Arguments.of("depth of field", (UnaryOperator<Camera.Builder>) b -> b.setDepthOfField(10, 0.2)
                        .setDepthOfFieldSamples(3)));
    }

    private static Camera camera(UnaryOperator<Camera.Builder> mode, ImageWriter image, int threads) {
        return mode.apply(TestScenes.camera(TestScenes.everyEffect(), image)).setMultithreading(threads).setSeed(5)
                .setSummary(false).build();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("modes")
    @DisplayName("rectangles of uneven, unaligned sizes assemble to the whole render's pixels")
    void regionsAssembleToTheWholeImage(String name, UnaryOperator<Camera.Builder> mode) {
        ImageWriter whole = new ImageWriter("whole", NX, NY);
        camera(mode, whole, 2).render();

        ImageWriter parts = new ImageWriter("parts", NX, NY);
        RegionRenderer regions = camera(mode, parts, 0).regionRenderer();
        int[] xs = { 0, 7, 30, 31, NX }, ys = { 0, 13, 22, NY };
        for (int j = 0; j + 1 < ys.length; ++j)
            for (int i = 0; i + 1 < xs.length; ++i) {
                RenderStats stats = regions.render(xs[i], ys[j], xs[i + 1], ys[j + 1]);
                assertThat(stats.pixels()).isEqualTo((long) (xs[i + 1] - xs[i]) * (ys[j + 1] - ys[j]));
            }
        assertThat(Pixels.of(parts)).isEqualTo(Pixels.of(whole));
    }

    @Test
    @DisplayName("a rectangle leaves the pixels outside it untouched")
    void onlyTheRectangle() {
        ImageWriter image = new ImageWriter("region", NX, NY);
        camera(b -> b, image, 0).regionRenderer().render(10, 5, 20, 9);
        int rendered = 0;
        for (int y = 0; y < NY; ++y)
            for (int x = 0; x < NX; ++x) {
                boolean inside = x >= 10 && x < 20 && y >= 5 && y < 9;
                if (!inside) assertThat(image.getRgb(x, y)).as("pixel (%d,%d)", x, y).isZero();
                else if (image.getRgb(x, y) != 0) ++rendered;
            }
        assertThat(rendered).as("rendered pixels inside").isPositive();
    }

    @Test
    @DisplayName("an empty rectangle or one reaching outside the image is refused, naming it")
    void badRectangles() {
        RegionRenderer regions = camera(b -> b, new ImageWriter("bad", NX, NY), 0).regionRenderer();
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(5, 5, 5, 10))
                .withMessage("region [5,5)x[5,10) must be a non-empty rectangle inside the 53x37 image");
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(-1, 0, 5, 5)).withMessageContaining("[-1,5)");
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(0, 0, NX + 1, 5)).withMessageContaining("[0,54)");
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(0, 30, 5, NY + 1)).withMessageContaining("[30,38)");
    }
}
