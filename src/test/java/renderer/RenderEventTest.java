package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import jdk.jfr.Recording;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordingFile;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * Each render, and each PNG write, is a JDK Flight Recorder event with what it rendered or wrote,
 * for recordings and profilers.
 */
class RenderEventTest {
    @Test
    @DisplayName("a recording holds one raytracer.Render event per render, with its image, size, sampling, threads and rays")
    void recorded(@TempDir Path dir) throws Exception {
        ImageWriter image = new ImageWriter("jfr", 32, 16);
        RenderStats stats;
        try (Recording recording = new Recording()) {
            recording.enable(RenderEvent.NAME);
            recording.start();
            stats = TestScenes.camera(new Scene("jfr scene"), image).setAntiAliasing(AntiAliasing.CORNERS)
                    .setMultithreading(2).build().render();
            recording.stop();
            recording.dump(dir.resolve("render.jfr"));
        }
        List<RecordedEvent> events = RecordingFile.readAllEvents(dir.resolve("render.jfr")).stream()
                .filter(e -> e.getEventType().getName().equals(RenderEvent.NAME)).toList();

        assertThat(events).hasSize(1);
        RecordedEvent e = events.get(0);
        assertThat(e.getString("image")).isEqualTo("jfr");
        assertThat(e.getString("scene")).isEqualTo("jfr scene");
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

    @Test
    @DisplayName("a recording holds one raytracer.ImageWrite event per PNG written: the writer's name (else the file's), file, size, bytes")
    void write(@TempDir Path dir) throws Exception {
        Path direct = dir.resolve("direct.png");
        Path named = Path.of("images", "jfr", "flow-5785.png");
        try (Recording recording = new Recording()) {
            recording.enable(ImageWriteEvent.NAME);
            recording.start();
            new ImageWriter(7, 5).writeToImage(direct);                        // written directly, no name: the file's
            Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Vector.AXIS_Y).setVpSize(1, 1)
                    .setVpDistance(1).setResolution(6, 4).setSummary(false).build().renderImage()
                    .writeToImage("jfr/flow-5785");                              // 2024–25 flow: named by the file
            recording.stop();
            recording.dump(dir.resolve("write.jfr"));
        } finally {
            Files.deleteIfExists(named);
        }
        List<RecordedEvent> events = RecordingFile.readAllEvents(dir.resolve("write.jfr")).stream()
                .filter(e -> e.getEventType().getName().equals(ImageWriteEvent.NAME)).toList();

        assertThat(events).hasSize(2);
        RecordedEvent first = events.get(0), second = events.get(1);
        assertThat(first.getString("image")).isEqualTo("direct");
        assertThat(first.getString("file")).isEqualTo(direct.toAbsolutePath().toString());
        assertThat(first.getInt("width")).isEqualTo(7);
        assertThat(first.getInt("height")).isEqualTo(5);
        assertThat(first.getLong("bytes")).isEqualTo(Files.size(direct));
        assertThat(second.getString("image")).isEqualTo("flow-5785");
        assertThat(second.getString("file")).isEqualTo(named.toAbsolutePath().toString());
        assertThat(second.getInt("width")).isEqualTo(6);
        assertThat(second.getLong("bytes")).isPositive();
    }
}
