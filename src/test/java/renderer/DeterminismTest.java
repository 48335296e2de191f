package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Sphere;
import primitives.Color;
import primitives.Point;
import scene.Scene;

/**
 * Images depend on nothing but the scene and the settings: not on the thread count, not on
 * which worker renders which tile, not on the run. Checked for every sampling mode on a scene
 * where every effect draws random numbers, so that a shared or thread-dependent random stream
 * would show.
 */
class DeterminismTest {
    private static final int NX = 60, NY = 40;

    private static Arguments mode(String name, UnaryOperator<Camera.Builder> settings) {
        return Arguments.of(name, settings);
    }

    static Stream<Arguments> modes() {
        return Stream.of(
                mode("NONE", b -> b.setAntiAliasing(AntiAliasing.NONE)),
                mode("RANDOM 3x3", b -> b.setAntiAliasing(AntiAliasing.RANDOM, 3, 3)),
                mode("CORNERS", b -> b.setAntiAliasing(AntiAliasing.CORNERS)),
                // Depth 2: the noisy glossy floor and penumbrae subdivide nearly everywhere, and the
                // property does not depend on the depth.
                mode("ADAPTIVE depth 2", b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(2, 8)),
                mode("NONE + depth of field", b -> b.setDepthOfField(10, 0.2).setDepthOfFieldSamples(4)),
                mode("RANDOM 2x2 + depth of field", b -> b.setAntiAliasing(AntiAliasing.RANDOM, 2, 2)
                        .setDepthOfField(11, 0.3)),
                mode("CORNERS + depth of field", b -> b.setAntiAliasing(AntiAliasing.CORNERS).setDepthOfField(10, 0.2)),
                // Threshold 2: pixels stop after 8, 16, ... samples, so the stopping rule is exercised.
                mode("ADAPTIVE + depth of field", b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(2, 2)
                        .setDepthOfField(10, 0.2)));
    }

    private static int[] render(UnaryOperator<Camera.Builder> mode, int threads, long seed) {
        ImageWriter image = new ImageWriter("determinism", NX, NY);
        mode.apply(TestScenes.camera(TestScenes.everyEffect(), image)).setMultithreading(threads).setSeed(seed)
                .build().renderImage();
        return Pixels.of(image);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("modes")
    @DisplayName("the same image for 0, 1, 2 and 4 threads and for a second run; another seed changes it")
    void sameBytesForAnyThreadCount(String name, UnaryOperator<Camera.Builder> mode) {
        int[] reference = render(mode, 0, 42);
        for (int threads : new int[] {1, 2, 4})
            assertThat(render(mode, threads, 42)).as("%s with %d threads", name, threads).isEqualTo(reference);
        assertThat(render(mode, 0, 42)).as("%s, second run", name).isEqualTo(reference);
        // The guard: the random streams do matter in this scene, so the equalities above say something.
        assertThat(render(mode, 0, 43)).as("%s with another seed", name).isNotEqualTo(reference);
    }

    @Test
    @DisplayName("the BVH and the flat geometry list give the same image")
    void bvhOnOrOff() {
        ImageWriter withBvh = new ImageWriter("bvh-on", NX, NY), flat = new ImageWriter("bvh-off", NX, NY);
        TestScenes.camera(TestScenes.everyEffect(), withBvh).setAntiAliasing(AntiAliasing.CORNERS).build().renderImage();
        TestScenes.camera(TestScenes.everyEffect(), flat).setAntiAliasing(AntiAliasing.CORNERS)
                .setRayTracer(new RayTracerBasic(TestScenes.everyEffect()).setBvh(false).setBeamSize(4).setShadowSamples(4))
                .build().renderImage();
        assertThat(Pixels.of(flat)).isEqualTo(Pixels.of(withBvh));
    }

    @Test
    @DisplayName("a 300x200 image rendered by workers equals the calling thread's, with the geometry where it belongs")
    void nonSquareWithThreads() {
        Color red = new Color(255, 0, 0), background = new Color(0, 0, 60);
        Point centre = new Point(-9.5, 5.5, 0);
        double radius = 2;
        Scene scene = new Scene("non-square").setBackground(background);
        scene.geometries.add(new Sphere(centre, radius).setEmission(red));
        ImageWriter single = new ImageWriter("non-square-0", 300, 200), pooled = new ImageWriter("non-square-3", 300, 200);
        TestScenes.camera(scene, single).setMultithreading(0).build().renderImage();
        RenderStats stats = TestScenes.camera(scene, pooled).setMultithreading(3).build().render();

        assertThat(stats.threads()).isEqualTo(3);
        assertThat(stats.pixels()).isEqualTo(300 * 200);
        assertThat(Pixels.of(pooled)).isEqualTo(Pixels.of(single));

        // The sphere is up and to the left: pixel (55, 44) looks at (−9.45, 5.55, 0), near its centre.
        int r = red.toRgb(), bg = background.toRgb();
        assertThat(pooled.getRgb(55, 44)).as("sphere centre").isEqualTo(r);
        assertThat(pooled.getRgb(300 - 1 - 55, 44)).as("mirrored to the right half").isEqualTo(bg);
        assertThat(pooled.getRgb(55, 200 - 1 - 44)).as("mirrored to the bottom half").isEqualTo(bg);
        // Every pixel, against an independent ray–sphere test: the ray from the eye along
        // d = ((x + 0.5 − 150)/10, (100 − y − 0.5)/10, −10) hits when (d·oc)² − |d|²(|oc|² − r²) ≥ 0,
        // oc = eye − centre (the sphere is in front of the eye, so a real root is a hit).
        double ox = TestScenes.EYE.getX() - centre.getX(), oy = TestScenes.EYE.getY() - centre.getY(),
                oz = TestScenes.EYE.getZ() - centre.getZ();
        double ocSquared = ox * ox + oy * oy + oz * oz;
        int hits = 0;
        for (int y = 0; y < 200; ++y)
            for (int x = 0; x < 300; ++x) {
                double dx = (x + 0.5 - 150) / 10, dy = (100 - y - 0.5) / 10, dz = -10;
                double b = dx * ox + dy * oy + dz * oz;
                double discriminant = b * b - (dx * dx + dy * dy + dz * dz) * (ocSquared - radius * radius);
                if (Math.abs(discriminant) < 1e-6) continue; // grazing: either answer is right
                boolean hit = discriminant > 0;
                if (hit) ++hits;
                assertThat(pooled.getRgb(x, y)).as("pixel (%d,%d)", x, y).isEqualTo(hit ? r : bg);
            }
        assertThat(hits).as("pixels on the sphere").isGreaterThan(1000);
    }
}
