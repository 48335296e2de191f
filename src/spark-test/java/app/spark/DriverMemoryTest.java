package app.spark;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import app.Project;

/**
 * A job that fails because the driver ran out of memory (its tasks could not be serialized beside
 * the job's images) ends in the command line's one line naming the images, the limit and
 * --driver-memory, not in Spark's "Task serialization failed: java.lang.OutOfMemoryError".
 */
class DriverMemoryTest {
    private static final long MB = 1 << 20;

    @Test
    @DisplayName("the images of a job: sizes and the MB they hold")
    void imageSizes() throws Exception {
        SparkFrame f = SparkFrame.read(Project.file("scenes/glossy.xml"));
        SparkFrame big = f.withSettings(f.settings().withImage("big", 11000, 11000));
        SparkFrame small = f.withSettings(f.settings().withImage("small", 100, 50));
        assertThat(SparkRenderer.imageSizes(List.of(big))).isEqualTo("11000x11000, 462 MB");
        assertThat(SparkRenderer.imageSizes(List.of(big, small))).isEqualTo("11000x11000 + 100x50, 462 MB");
    }

    @Test
    @DisplayName("task serialization out of memory: one line, the images, the limit, --driver-memory")
    void serialization() {
        RuntimeException failed = new RuntimeException("Job aborted due to stage failure: Task serialization failed:"
                + " java.lang.OutOfMemoryError: Java heap space\njava.lang.OutOfMemoryError: Java heap space\n\tat"
                + " java.base/java.util.Arrays.copyOf(Arrays.java:3537)");
        assertThat(SparkRenderer.driverOutOfMemory(failed, "11000x11000, 462 MB", 512 * MB))
                .isEqualTo("the driver ran out of memory serializing the job's tasks beside the job's images (11000x11000,"
                        + " 462 MB); Java may use at most 512 MB there (give the driver more memory with spark-submit"
                        + " --driver-memory, or -Xmx for a local master; or render it smaller)");
    }

    @Test
    @DisplayName("an OutOfMemoryError among the causes: the same line; any other failure: not this one")
    void causes() {
        assertThat(SparkRenderer.driverOutOfMemory(new IllegalStateException("job failed", new OutOfMemoryError("Java heap space")),
                "64x64, 1 MB", 512 * MB)).startsWith("the driver ran out of memory during the job beside the job's images (64x64, 1 MB)");
        assertThat(SparkRenderer.driverOutOfMemory(new IllegalStateException("Task 0 failed 4 times"), "64x64, 1 MB", 512 * MB))
                .isNull();
        // an executor's own lack of memory, its trace in the job's message: the executors' option, not the driver's
        assertThat(SparkRenderer.driverOutOfMemory(new RuntimeException("Job aborted due to stage failure: Task 3 in stage 0.0"
                + " failed 4 times, most recent failure: Lost task 3.3 in stage 0.0 (TID 7) (127.0.0.1 executor 0):"
                + " java.lang.OutOfMemoryError: Java heap space\n\tat app.spark.FrameSet.render"), "64x64, 1 MB", 512 * MB))
                .isEqualTo("an executor ran out of memory rendering the job's tiles (give the executors more memory with"
                        + " spark-submit --executor-memory, or -Xmx for a local master; or render it smaller)");
    }

    @Test
    @DisplayName("up front: the images and the tasks against the heap; a job that fits passes")
    void upFront() throws Exception {
        SparkFrame f = SparkFrame.read(Project.file("scenes/glossy.xml"));
        SparkFrame big = f.withSettings(f.settings().withImage("big", 11000, 11000));
        // 11000² in 64-pixel tiles: 172 × 172 tasks; 4 bytes a pixel, 1700 bytes a task, 1 MB besides
        long needed = 4L * 11000 * 11000 + 29584 * SparkRenderer.BYTES_PER_TASK + MB;
        assertThat(SparkRenderer.driverBytesNeeded(List.of(big), 29584)).isEqualTo(needed);
        assertThatThrownBy(() -> SparkRenderer.requireDriverMemory("spark render big", List.of(big), 29584, 512 * MB, 40 * MB))
                .isInstanceOf(SparkRenderException.class)
                .hasMessage("spark render big: the driver cannot hold the job: its images (11000x11000, 462 MB) and 29584"
                        + " tasks (about 48 MB) need about 511 MB; Java may use at most 512 MB here, of which about 472 MB"
                        + " were free (give the driver more memory with spark-submit --driver-memory, or -Xmx for a local"
                        + " master; or render it smaller)");
        SparkRenderer.requireDriverMemory("spark render big", List.of(big), 29584, 1024 * MB, 40 * MB);
        SparkRenderer.requireDriverMemory("spark render big", List.of(big), 29584, Long.MAX_VALUE, 40 * MB);
        SparkFrame small = f.withSettings(f.settings().withImage("small", 100, 50));
        assertThatThrownBy(() -> SparkRenderer.requireDriverMemory("spark render small", List.of(small), 1, 64 * MB, 64 * MB))
                .hasMessageContaining("and 1 task (about 1 MB)");
    }
}
