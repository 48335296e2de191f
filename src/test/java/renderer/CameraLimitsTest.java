package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/**
 * The camera's stated limits: threads and samples per pixel, each refused when set,
 * naming the value and the limit.
 */
class CameraLimitsTest {
    private static final int CORES = Runtime.getRuntime().availableProcessors();

    @Test
    @DisplayName("threads: at most 8 per core")
    void threads() {
        assertThat(Camera.maxThreads()).isEqualTo(Camera.MAX_THREADS_PER_CORE * CORES);
        Camera.getBuilder().setMultithreading(Camera.maxThreads());
        assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setMultithreading(100_000))
                .withMessage("thread count 100000 is more than the limit of " + Camera.maxThreads() + " (8 per core, "
                        + CORES + " cores)");
        assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setMultithreading(Camera.maxThreads() + 1));
    }

    @Test
    @DisplayName("a RANDOM grid of at most 65536 samples: 65536x65536 no longer overflows an int")
    void grid() {
        Camera.getBuilder().setAntiAliasingGrid(256, 256).setAntiAliasingGrid(65536, 1);
        assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setAntiAliasingGrid(65536, 65536))
                .withMessage("anti-aliasing grid 65536x65536 has 4294967296 samples per pixel, more than the limit of 65536");
        assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setAntiAliasingGrid(257, 256));
    }

    @Test
    @DisplayName("at most 65536 lens samples")
    void lensSamples() {
        Camera.getBuilder().setDepthOfFieldSamples(Camera.MAX_SAMPLES_PER_PIXEL);
        assertThatIllegalArgumentException().isThrownBy(() -> Camera.getBuilder().setDepthOfFieldSamples(65_537))
                .withMessage("depth-of-field samples must be from 1 to 65536, got 65537");
    }
}
