package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.offset;

import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * The lens points NONE and ADAPTIVE take with depth of field: stratified over the lens, not
 * independent (CORNERS keeps independent ones: see {@link LatticeSampler}). A recording tracer
 * sees every camera ray; the test camera ({@link TestScenes#camera}) stands at (0, 0, 10) looking
 * down −z, so a ray's head is its lens point, (x, y) = aperture · √u · (cos 2πv, sin 2πv), and
 * with focal distance 10 it crosses the plane z = 0 at the film point it was aimed through, 0.1
 * units a pixel.
 */
class LensSamplesTest {
    private static final double APERTURE = 0.5, FOCAL = 10;

    /** A camera ray as the sampler chose it: its film point (pixels) and lens point (unit square). */
    private record Sample(double px, double py, double u, double v) {
    }

    /** Records every camera ray, colours it black. */
    private static final class Recorder extends RayTracerBase {
        final List<Sample> samples = new ArrayList<>();
        private final int nX, nY;

        Recorder(int nX, int nY) {
            super(new Scene("recorder"));
            this.nX = nX;
            this.nY = nY;
        }

        @Override
        public Color traceRay(Ray ray) {
            Point h = ray.getHead();
            Vector d = ray.getDirection();
            double t = h.getZ() / -d.getZ(); // to the focal plane z = 0
            double fx = h.getX() + d.getX() * t, fy = h.getY() + d.getY() * t;
            double lx = h.getX() / APERTURE, ly = h.getY() / APERTURE;
            double angle = Math.atan2(ly, lx);
            samples.add(new Sample(fx * 10 + nX / 2.0, nY / 2.0 - fy * 10, lx * lx + ly * ly,
                    (angle < 0 ? angle + 2 * Math.PI : angle) / (2 * Math.PI)));
            return Color.BLACK;
        }
    }

    private static List<Sample> render(int nX, int nY, UnaryOperator<Camera.Builder> mode) {
        Recorder recorder = new Recorder(nX, nY);
        mode.apply(TestScenes.camera(new Scene("empty"), new ImageWriter("lens", nX, nY))).setRayTracer(recorder)
                .setDepthOfField(FOCAL, APERTURE).build().render();
        return recorder.samples;
    }

    /** How many of the samples' lens points fall in each cell of the columns × rows grid of the unit square. */
    private static int[] lensCells(List<Sample> samples, int columns, int rows) {
        int[] cells = new int[columns * rows];
        for (Sample s : samples)
            ++cells[Math.min(rows - 1, (int) (s.v * rows)) * columns + Math.min(columns - 1, (int) (s.u * columns))];
        return cells;
    }

    @Nested
    @DisplayName("NONE: the lens samples of a pixel")
    class None {
        @ParameterizedTest(name = "{0} samples: one in each cell of every grid of {0} cells")
        @ValueSource(ints = { 4, 16, 64 })
        void stratified(int n) {
            List<Sample> samples = render(1, 1, b -> b.setDepthOfFieldSamples(n));
            assertThat(samples).hasSize(n);
            for (int columns = 1; columns <= n; columns *= 2)
                assertThat(lensCells(samples, columns, n / columns)).as("%d x %d grid", columns, n / columns).containsOnly(1);
        }

        @Test
        @DisplayName("all go through the pixel centre")
        void throughTheCentre() {
            for (Sample s : render(1, 1, b -> b.setDepthOfFieldSamples(16))) {
                assertThat(s.px).isCloseTo(0.5, offset(1e-9));
                assertThat(s.py).isCloseTo(0.5, offset(1e-9));
            }
        }

        @Test
        @DisplayName("each pixel has a pattern of its own")
        void pixelsDiffer() {
            List<Sample> samples = render(2, 1, b -> b.setDepthOfFieldSamples(4));
            assertThat(samples.subList(0, 4)).extracting(Sample::u)
                    .doesNotContainAnyElementsOf(samples.subList(4, 8).stream().map(Sample::u).toList());
        }
    }

    @Nested
    @DisplayName("ADAPTIVE: a pixel's own samples")
    class Adaptive {
        @Test
        @DisplayName("its first 8 samples are stratified over the pixel and, apart, over the lens")
        void firstSamplesStratified() {
            List<Sample> samples = render(1, 1, b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE));
            assertThat(samples).as("an empty scene is smooth: the first test stops it").hasSize(NoiseAdaptiveSampler.FIRST);
            assertThat(lensCells(samples, 4, 2)).as("lens, 4 x 2").containsOnly(1);
            assertThat(lensCells(samples, 2, 4)).as("lens, 2 x 4").containsOnly(1);
            int[] film = new int[8];
            for (Sample s : samples) ++film[(int) (s.py * 2) * 4 + (int) (s.px * 4)];
            assertThat(film).as("film, 4 x 2").containsOnly(1);
        }
    }
}
