package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jdk.jfr.Recording;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordingFile;
import scene.Scene;

/** Each render is a JDK Flight Recorder event with what it rendered, for recordings and profilers. */
class RenderEventTest {
    @Test
    @DisplayName("a recording holds one raytracer.Render event per render, with its image, size, sampling, threads and rays")
    void recorded(@TempDir Path dir) throws Exception {
        ImageWriter image = new ImageWriter("jfr", 32, 16);
        RenderStats stats;
        try (Recording recording = new Recording()) {
            recording.enable(RenderEvent.NAME);
            recording.start();
            stats = TestScenes.camera(new Scene("jfr"), image).setAntiAliasing(AntiAliasing.CORNERS)
                    .setMultithreading(2).build().render();
            recording.stop();
            recording.dump(dir.resolve("render.jfr"));
        }
        List<RecordedEvent> events = RecordingFile.readAllEvents(dir.resolve("render.jfr")).stream()
                .filter(e -> e.getEventType().getName().equals(RenderEvent.NAME)).toList();

        assertThat(events).hasSize(1);
        RecordedEvent e = events.get(0);
        assertThat(e.getString("image")).isEqualTo("jfr");
        assertThat(e.getInt("width")).isEqualTo(32);
        assertThat(e.getInt("height")).isEqualTo(16);
        assertThat(e.getString("sampling")).isEqualTo("CORNERS");
        assertThat(e.getInt("threads")).isEqualTo(2);
        // CORNERS: the centre and the (33 x 17) shared corners of an empty scene, no shadow rays.
        assertThat(e.getLong("cameraRays")).isEqualTo(stats.cameraRays()).isEqualTo(32 * 16 + 33 * 17);
        assertThat(e.getLong("shadowRays")).isZero();
        assertThat(e.getLong("secondaryRays")).isZero();
        assertThat(e.getDuration("preparation")).isEqualTo(Duration.ofNanos(Math.round(stats.prepareSeconds() * 1e9)));
        assertThat(e.getDuration()).as("the event spans preparation and render loop")
                .isGreaterThanOrEqualTo(Duration.ofNanos((long) ((stats.seconds() + stats.prepareSeconds()) * 1e9 * 0.99)));
    }
}
