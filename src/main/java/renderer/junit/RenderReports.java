package renderer.junit;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.function.BiConsumer;

import org.junit.jupiter.api.TestReporter;

import renderer.Camera;
import renderer.CameraReports;
import renderer.ImageWriter;
import renderer.RenderStats;
import renderer.WriteListener;

/**
 * Publishes each render's figures, and each write of its PNG, in a JUnit test's report, where the
 * IDE's test view and Surefire's XML report show them:
 *
 * <pre>{@code
 * @Test
 * void spheres(TestReporter reporter) {
 *     camera.setRenderListener(RenderReports.to(reporter)).build().renderImage().writeToImage("spheres");
 * }
 * }</pre>
 *
 * <p>The route is explicit: the test hands its own {@link TestReporter} (which JUnit passes to
 * any test method that asks for one) to the camera's builder, so no registry outlives a test.
 */
public final class RenderReports {
    private RenderReports() {
    }

    /**
     * @param reporter the test's reporter
     * @return a render listener for {@link Camera.Builder#setRenderListener} that publishes one
     *         entry per render: {@code image} (its name as the summary line gives it: the test's
     *         for an image named only when written), {@code scene} (the scene's name),
     *         {@code size} (columns x rows), {@code mode} (the sampling settings, as the summary
     *         line shows them), {@code threads} (0: the calling thread), {@code time} (the render
     *         loop's wall time), {@code rays} (all kinds) and {@code Mrays/s}; and, being a
     *         {@link WriteListener}, one per write of the camera's PNG: {@code image},
     *         {@code file} (its absolute path) and {@code write time}
     * @throws NullPointerException when it is null
     */
    public static BiConsumer<Camera, RenderStats> to(TestReporter reporter) {
        return new Publisher(Objects.requireNonNull(reporter, "reporter"));
    }

    /** The listener {@link #to} returns: both of a camera's callbacks, into one reporter. */
    private record Publisher(TestReporter reporter) implements BiConsumer<Camera, RenderStats>, WriteListener {
        @Override
        public void accept(Camera camera, RenderStats stats) {
            reporter.publishEntry(figures(camera, stats));
        }

        @Override
        public void written(Camera camera, Path file, double seconds) {
            reporter.publishEntry(write(camera, file, seconds));
        }
    }

    /** The entry {@link #to} publishes for one render. */
    static Map<String, String> figures(Camera camera, RenderStats stats) {
        ImageWriter image = camera.getImageWriter();
        Map<String, String> entry = new LinkedHashMap<>();
        entry.put("image", CameraReports.imageLabel(camera));
        entry.put("scene", CameraReports.sceneName(camera));
        entry.put("size", image.getNx() + "x" + image.getNy());
        entry.put("mode", CameraReports.describe(camera));
        entry.put("threads", Integer.toString(stats.threads()));
        entry.put("time", seconds(stats.seconds()));
        entry.put("rays", Long.toString(stats.totalRays()));
        entry.put("Mrays/s", String.format(Locale.ROOT, "%.2f", stats.mraysPerSecond()));
        return entry;
    }

    /** The entry {@link #to} publishes for one write. */
    static Map<String, String> write(Camera camera, Path file, double seconds) {
        Map<String, String> entry = new LinkedHashMap<>();
        entry.put("image", CameraReports.imageLabel(camera));
        entry.put("file", file.toString());
        entry.put("write time", seconds(seconds));
        return entry;
    }

    private static String seconds(double seconds) {
        return String.format(Locale.ROOT, "%.3f s", seconds);
    }
}
