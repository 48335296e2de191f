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
                        .setDepthOfFieldSamples(3)),
                Arguments.of("CORNERS + depth of field", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.CORNERS).setDepthOfField(10, 0.2)),
                Arguments.of("ADAPTIVE + depth of field", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(2, 2).setDepthOfField(10, 0.2)));
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
        RegionRenderer regions = RegionRenderer.of(camera(mode, new ImageWriter("unused", NX, NY), 0));
        int[] xs = { 0, 7, 30, 31, NX }, ys = { 0, 13, 22, NY };
        for (int j = 0; j + 1 < ys.length; ++j)
            for (int i = 0; i + 1 < xs.length; ++i) {
                int w = xs[i + 1] - xs[i], h = ys[j + 1] - ys[j];
                RegionRenderer.Pixels p = regions.render(xs[i], ys[j], xs[i + 1], ys[j + 1]);
                assertThat(p.stats().pixels()).isEqualTo((long) w * h);
                assertThat(p.rgb()).hasSize(w * h);
                parts.writeTile(xs[i], ys[j], w, h, p.rgb());
            }
        assertThat(Pixels.of(parts)).isEqualTo(Pixels.of(whole));
    }

    @Test
    @DisplayName("a rectangle's pixels come back row by row; the camera's image is not written")
    void onlyTheRectangle() {
        ImageWriter whole = new ImageWriter("whole", NX, NY);
        camera(b -> b, whole, 0).render();
        ImageWriter image = new ImageWriter("region", NX, NY);
        int[] rgb = RegionRenderer.of(camera(b -> b, image, 0)).render(10, 5, 20, 9).rgb();
        for (int y = 5; y < 9; ++y)
            for (int x = 10; x < 20; ++x)
                assertThat(rgb[(y - 5) * 10 + (x - 10)]).as("pixel (%d,%d)", x, y).isEqualTo(whole.getRgb(x, y));
        assertThat(Pixels.of(image)).as("the camera's image").containsOnly(0);
    }

    @Test
    @DisplayName("the builder's region renderer allocates no image: a 40000x40000 frame renders a tile")
    void withoutAnImage() {
        Camera.Builder builder = TestScenes.camera(TestScenes.everyEffect(), new ImageWriter("whole", NX, NY)).setSeed(5);
        Camera camera = builder.build();
        camera.render();
        ImageWriter whole = camera.getImageWriter();
        int[] rgb = RegionRenderer.of(builder.setResolution(NX, NY)).render(4, 6, 7, 8).rgb();
        assertThat(rgb).containsExactly(whole.getRgb(4, 6), whole.getRgb(5, 6), whole.getRgb(6, 6),
                whole.getRgb(4, 7), whole.getRgb(5, 7), whole.getRgb(6, 7));
        // 6.4 GB as an image: more than the test JVM's heap.
        assertThat(RegionRenderer.of(builder.setResolution(40_000, 40_000)).render(0, 0, 3, 2).rgb()).hasSize(6);
    }

    @Test
    @DisplayName("an empty rectangle or one reaching outside the image is refused, naming it")
    void badRectangles() {
        RegionRenderer regions = RegionRenderer.of(camera(b -> b, new ImageWriter("bad", NX, NY), 0));
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(5, 5, 5, 10))
                .withMessage("region [5,5)x[5,10) must be a non-empty rectangle inside the 53x37 image");
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(-1, 0, 5, 5)).withMessageContaining("[-1,5)");
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(0, 0, NX + 1, 5)).withMessageContaining("[0,54)");
        assertThatIllegalArgumentException().isThrownBy(() -> regions.render(0, 30, 5, NY + 1)).withMessageContaining("[30,38)");
    }
}
