package renderer;

import java.nio.file.Path;
import java.util.Locale;

/**
 * What reports say of a camera: its image's name, its scene's name and its sampling settings in
 * words, and (package-private) the lines its renders and writes print. Static, and apart from
 * {@link Camera}, so that a student completing {@code camera.} sees the course's methods only; the
 * JUnit reports ({@code renderer.junit}) and the Spark entry, in other packages, call these.
 *
 * @hidden internal: the camera's words for reports; a scene test renders and writes the image
 */
public final class CameraReports {
    private CameraReports() {
    }

    /**
     * The name the summary and write lines, progress lines, test reports and JFR events give the
     * image: its writer's name, or for an unnamed writer (named only when written, the 2024–25
     * flow) the calling test method ({@code SpheresTest.twoSpheres()}), or {@code (unnamed)}
     * outside a test.
     *
     * @param camera a built camera
     * @return the image's name as the camera's reports show it
     */
    public static String imageLabel(Camera camera) {
        ImageWriter image = camera.imageWriter();
        return image.hasName() ? image.getImageName() : CallingTest.find().orElse(image.getImageName());
    }

    /**
     * @param camera a built camera
     * @return the name of the scene the camera's tracer traces ({@code Scene.name})
     */
    public static String sceneName(Camera camera) {
        return camera.rayTracer().sceneName();
    }

    /**
     * @param camera a built camera
     * @return its sampling settings, tracer and seed in words, for summaries and benchmark tables
     */
    public static String describe(Camera camera) {
        return camera.describe();
    }

    /**
     * The line a render prints unless silenced: {@code render NAME: TIME, WxH [settings] of scene
     * 'SCENE', figures}, the time and figures those of {@link RenderStats#toString()}, then the
     * tracer's walk (docs/student-guide.md, "What a render prints").
     */
    static String renderLine(Camera camera, String name, String scene, RenderStats stats) {
        ImageWriter image = camera.imageWriter();
        return "render " + name + ": " + stats.time() + ", " + image.getNx() + "x" + image.getNy() + " [" + camera.describe()
                + "] of scene '" + scene + "', " + stats.figures() + camera.rayTracer().walk();
    }

    /**
     * The line a write prints unless silenced: {@code write NAME: /absolute/path.png in 0.042 s},
     * and a note at the end when nothing was drawn on the image (the PNG is all black).
     */
    static String writeLine(String name, Path file, double seconds, ImageWriter image) {
        return String.format(Locale.ROOT, "write %s: %s in %.3f s", name, file, seconds)
                + (image.isBlank() ? " (" + ImageWriter.BLANK + ")" : "");
    }

    /**
     * A builder's settings in words, checked as its {@code build()} checks them (the view, the ray
     * budget) without allocating the image or preparing the scene: what a cluster's driver says
     * of a render whose image it assembles from tiles.
     *
     * @param camera the builder whose settings are described
     * @return the words a camera built from it would describe itself with
     * @throws java.util.MissingResourceException as {@link Camera.Builder#build()}
     * @throws IllegalArgumentException           as {@link Camera.Builder#build()}
     */
    public static String describe(Camera.Builder camera) {
        return camera.setup().describe();
    }

    /**
     * Holds a builder's settings to the ray budget its {@code build()} holds them to, before any
     * view is set: the budget depends on the sampling, the lens, the tracer and its scene's lights
     * alone. How a scene file's or a command line's settings are checked, replayed onto a builder.
     *
     * @param camera the builder whose settings are checked
     * @throws IllegalArgumentException as {@link Camera.Builder#build()} for a budget exceeded, with its message
     */
    public static void requireRayBudget(Camera.Builder camera) {
        camera.requireRayBudget();
    }
}
