package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The render's figures and the one-line summary that prints them. */
class RenderStatsTest {
    /** 2 s, 100 pixels, 400 camera rays (4 a pixel), 300 shadow and 100 secondary rays: 800 in all. */
    private final RenderStats stats = new RenderStats(2.0, 100, 400, 300, 100, 2, 0.25);

    @Nested
    @DisplayName("figures")
    class Figures {
        @Test
        @DisplayName("samples per pixel counts camera rays only, not shadow or secondary rays")
        void samplesPerPixel() {
            assertThat(stats.samplesPerPixel()).isEqualTo(4.0);
        }

        @Test
        @DisplayName("the ray rate counts rays of every kind")
        void rate() {
            assertThat(stats.totalRays()).isEqualTo(800);
            assertThat(stats.mraysPerSecond()).isEqualTo(800 / 2.0 / 1e6);
        }

        @Test
        @DisplayName("an empty render has rates of zero, not NaN")
        void empty() {
            RenderStats none = new RenderStats(0, 0, 0, 0, 0, 0, 0);
            assertThat(none.samplesPerPixel()).isZero();
            assertThat(none.mraysPerSecond()).isZero();
        }
    }

    @Nested
    @DisplayName("summary line")
    class Summary {
        @Test
        @DisplayName("names what each figure counts: the per-pixel figure is camera rays, the rate is all rays")
        void labels() {
            assertThat(stats.toString()).isEqualTo("2.000 s, 100 px, rays: camera 400, shadow 300, secondary 100, "
                    + "4.00 camera rays per px, 0.00 Mrays/s (all rays), 2 threads, prepared in 0.250 s");
        }

        @ParameterizedTest(name = "{0} → ''{1}''")
        @CsvSource(delimiter = '|', value = {"0|calling thread", "1|1 thread", "2|2 threads", "16|16 threads"})
        @DisplayName("says 'calling thread' when no worker thread was used, the singular for one")
        void threads(int threads, String words) {
            assertThat(new RenderStats(1, 1, 1, 0, 0, threads, 0).toString()).contains(", " + words + ", ");
        }
    }
}
