package renderer.junit;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.function.BiConsumer;

import org.junit.jupiter.api.TestReporter;

import renderer.Camera;
import renderer.ImageWriter;
import renderer.RenderStats;

/**
 * Publishes each render's figures in a JUnit test's report, where the IDE's test view and
 * Surefire's XML report show them:
 *
 * <pre>{@code
 * @Test
 * void spheres(TestReporter reporter) {
 *     camera.setRenderListener(RenderReports.to(reporter)).build().renderImage();
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
     *         entry per render: {@code image} (its name), {@code size} (columns x rows),
     *         {@code mode} (the sampling settings, as the summary line shows them), {@code time}
     *         (the render loop's wall time), {@code rays} (all kinds) and {@code Mrays/s}
     * @throws NullPointerException when it is null
     */
    public static BiConsumer<Camera, RenderStats> to(TestReporter reporter) {
        Objects.requireNonNull(reporter, "reporter");
        return (camera, stats) -> reporter.publishEntry(figures(camera, stats));
    }

    /** The entry {@link #to} publishes for one render. */
    static Map<String, String> figures(Camera camera, RenderStats stats) {
        ImageWriter image = camera.getImageWriter();
        Map<String, String> entry = new LinkedHashMap<>();
        entry.put("image", image.getImageName());
        entry.put("size", image.getNx() + "x" + image.getNy());
        entry.put("mode", camera.describe());
        entry.put("time", String.format(Locale.ROOT, "%.3f s", stats.seconds()));
        entry.put("rays", Long.toString(stats.totalRays()));
        entry.put("Mrays/s", String.format(Locale.ROOT, "%.2f", stats.mraysPerSecond()));
        return entry;
    }
}
