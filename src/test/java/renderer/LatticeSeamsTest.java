package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import primitives.Color;
import scene.Scene;

/**
 * The pixel corners on the borders between a pass's tiles are traced once for the pass: each
 * has its own slot, the first worker to need one traces it, and the others take its colour.
 */
class LatticeSeamsTest {
    @Nested
    @DisplayName("which corners are kept")
    class Corners {
        @ParameterizedTest(name = "pixels [{0}, {2}) x [{1}, {3}) in tiles of {4}")
        @CsvSource({ "0, 0, 100, 70, 32", "10, 5, 75, 70, 16", "0, 0, 64, 64, 32", "3, 4, 50, 9, 8", "0, 0, 33, 2, 32" })
        @DisplayName("each corner on a border between two tiles has a slot of its own; the tiles' insides and the pass's edge have none")
        void bordersOnly(int x0, int y0, int x1, int y1, int tile) {
            LatticeSeams seams = LatticeSeams.of(x0, y0, x1, y1, tile);
            Set<Integer> slots = new HashSet<>();
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    boolean border = x > x0 && x < x1 && (x - x0) % tile == 0 || y > y0 && y < y1 && (y - y0) % tile == 0;
                    int s = seams.index(x, y);
                    if (border) {
                        assertThat(s).as("corner (%d,%d)", x, y).isNotNegative();
                        assertThat(slots.add(s)).as("corner (%d,%d)'s slot %d is its own", x, y, s).isTrue();
                    } else {
                        assertThat(s).as("corner (%d,%d)", x, y).isEqualTo(-1);
                    }
                }
            int crossings = ((x1 - x0 - 1) / tile) * ((y1 - y0 - 1) / tile);
            assertThat(slots).as("slots below the size").allMatch(s -> s < seams.size());
            assertThat(seams.size() - slots.size()).as("unused slots: a crossing's in its horizontal border").isEqualTo(crossings);
        }

        @Test
        @DisplayName("a pass of one tile has no borders")
        void oneTile() {
            assertThat(LatticeSeams.of(0, 0, 32, 20, 32)).isNull();
            assertThat(LatticeSeams.of(5, 5, 6, 6, 1)).isNull();
        }

        @Test
        @DisplayName("a pass with more border corners than the limit keeps none (its borders are traced twice, as without seams)")
        void tooMany() {
            assertThat(LatticeSeams.of(0, 0, 2000, 2000, 4)).as("2000x2000 in tiles of 4").isNull();
            assertThat(LatticeSeams.of(0, 0, 2000, 2000, 32).size()).as("2000x2000 in tiles of 32")
                    .isLessThanOrEqualTo(LatticeSeams.MAX_POINTS);
        }
    }

    @Nested
    @DisplayName("who traces a corner")
    class Claims {
        private final LatticeSeams seams = LatticeSeams.of(0, 0, 64, 64, 32);
        private final int s = seams.index(32, 10);

        @Test
        @DisplayName("the first claim traces it; the later ones read its published colour")
        void firstTraces() {
            assertThat(seams.claim(s)).isTrue();
            seams.publish(s, 1.5, -2, 300);
            assertThat(seams.claim(s)).isFalse();
            assertThat(new double[] { seams.red(s), seams.green(s), seams.blue(s) }).containsExactly(1.5, -2, 300);
        }

        @Test
        @DisplayName("a corner given back after a failed trace is traced by the next claim")
        void releasedIsTracedAgain() {
            assertThat(seams.claim(s)).isTrue();
            seams.release(s);
            assertThat(seams.claim(s)).isTrue();
        }

        /** Claims the corner here, then has another worker claim it: @return that worker's claim, still waiting */
        private CompletableFuture<Boolean> claimedHereWanted() throws InterruptedException {
            assertThat(seams.claim(s)).isTrue();
            CompletableFuture<Boolean> other = CompletableFuture.supplyAsync(() -> seams.claim(s));
            Thread.sleep(50);
            assertThat(other).as("the other worker, while the corner is traced").isNotDone();
            return other;
        }

        @Test
        @DisplayName("a worker that needs a corner being traced waits for its colour")
        void waitsForTheTracer() throws Exception {
            CompletableFuture<Boolean> other = claimedHereWanted();
            seams.publish(s, 7, 8, 9);
            assertThat(other.get(10, TimeUnit.SECONDS)).as("the other worker takes the colour, untraced").isFalse();
            assertThat(seams.blue(s)).isEqualTo(9);
        }

        @Test
        @DisplayName("a worker waiting on a corner whose trace failed traces it itself")
        void waitsThenTraces() throws Exception {
            CompletableFuture<Boolean> other = claimedHereWanted();
            seams.release(s);
            assertThat(other.get(10, TimeUnit.SECONDS)).as("the other worker traces it").isTrue();
        }
    }

    @Nested
    @DisplayName("in a render")
    class InARender {
        private final Scene flat = new Scene("flat").setBackground(new Color(30, 60, 90));

        @ParameterizedTest(name = "{0} threads")
        @CsvSource({ "0", "2", "3" })
        @DisplayName("CORNERS over several tiles traces every pixel's centre and every pixel corner once")
        void cornersOnce(int threads) {
            int nx = 150, ny = 70; // tiles of 64: 3 x 2
            assertThat(LatticeSampler.Plan.corners(0, false).tileSize()).isLessThan(ny);
            ImageWriter image = new ImageWriter("flat-corners", nx, ny);
            RenderStats stats = TestScenes.camera(flat, image).setAntiAliasing(AntiAliasing.CORNERS).setMultithreading(threads)
                    .setSummary(false).build().render();
            assertThat(stats.cameraRays()).isEqualTo((long) nx * ny + (long) (nx + 1) * (ny + 1));
            assertThat(Pixels.of(image)).containsOnly(0x1E3C5A);
        }
    }
}
