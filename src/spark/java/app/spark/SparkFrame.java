package app.spark;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

import renderer.Camera;
import renderer.CameraReports;
import renderer.ImageWriter;
import scene.Scene;
import scene.io.LoadedScene;
import scene.io.RenderSettings;
import scene.io.SceneFormatException;

/**
 * One image for {@link SparkRenderer}: a scene file read and validated on the driver (with the
 * bytes of every file it needs, which travel to the executors), the settings to render it with
 * and the PNG to write. Immutable; the {@code with…} methods return changed copies.
 */
public final class SparkFrame {
    private final SceneFiles.Captured scene;
    private final RenderSettings settings;
    private final Path output;
    /** The camera's description of the settings, for the summary line. */
    private final String description;

    private SparkFrame(SceneFiles.Captured scene, RenderSettings settings, Path output) {
        this.scene = scene;
        this.settings = settings;
        this.output = output;
        // The settings replayed onto a builder are checked as a local render's are (the ray budget
        // of the command line's changes, say), with no image: it is allocated only to assemble the tiles.
        this.description = CameraReports.describe(builder());
    }

    /**
     * Reads and validates a scene file with its own settings; its PNG goes to
     * images/&lt;image name&gt;.png.
     *
     * @param scene the scene file (XML); its meshes are found relative to its folder
     * @return the frame
     * @throws IOException              when the scene file cannot be read
     * @throws SceneFormatException     when it is not a valid scene, with the one-line
     *                                  {@code FILE:LINE:COLUMN: message} of the local renderer
     * @throws IllegalArgumentException when the camera refuses a value of the file
     */
    public static SparkFrame read(Path scene) throws IOException, SceneFormatException {
        return read(scene, null);
    }

    /**
     * As {@link #read(Path)}, with the folder the scene's meshes may be read from (the command
     * line's {@code --mesh-root}); the executors hold the meshes to the same folder.
     *
     * @param scene    the scene file (XML); its meshes are found relative to its folder
     * @param meshRoot the folder meshes may be read from, sub-folders included; null: the scene
     *                 file's own folder
     * @return the frame
     * @throws IOException              when the scene file cannot be read
     * @throws SceneFormatException     when it is not a valid scene (a mesh outside the folder
     *                                  included), with the local renderer's one-line message
     * @throws IllegalArgumentException when the camera refuses a value of the file
     */
    public static SparkFrame read(Path scene, Path meshRoot) throws IOException, SceneFormatException {
        SceneFiles.Captured captured = SceneFiles.read(scene, meshRoot);
        captured.loaded().requireView(); // no camera: the reader's error at <scene>, here on the driver
        RenderSettings settings = captured.loaded().settings();
        return new SparkFrame(captured, settings, defaultOutput(settings));
    }

    private static Path defaultOutput(RenderSettings settings) {
        return ImageWriter.IMAGES.resolve(settings.imageName() + ".png");
    }

    /**
     * @param settings the settings to render with (typically {@link #settings()} with changes);
     *                 the thread count does not matter: executors render one tile per task
     * @return this frame with other settings; its output follows the image name unless
     *         {@link #withOutput(Path)} set it
     * @throws IllegalArgumentException when the camera refuses a value of {@code settings}
     */
    public SparkFrame withSettings(RenderSettings settings) {
        Objects.requireNonNull(settings, "settings");
        Path out = output.equals(defaultOutput(this.settings)) ? defaultOutput(settings) : output;
        return new SparkFrame(scene, settings, out);
    }

    /**
     * @param png the PNG file to write (written atomically once every tile is back)
     * @return this frame writing to {@code png}
     */
    public SparkFrame withOutput(Path png) {
        return new SparkFrame(scene, settings, Objects.requireNonNull(png, "output"));
    }

    /** @return the settings the frame renders with */
    public RenderSettings settings() {
        return settings;
    }

    /** @return the PNG file the frame is written to */
    public Path output() {
        return output;
    }

    /** @return the scene file as it was named */
    public String scene() {
        return scene.files().scene();
    }

    /** @return the sampling settings in words, as the local render's summary has them */
    String describe() {
        return description;
    }

    /** @return what travels to the executors */
    Frame frame() {
        return new Frame(scene.files(), settings);
    }

    /** @return the frame's scene as the driver read it (the command line's checks read its lights) */
    Scene loadedScene() {
        return scene.loaded().scene();
    }

    /**
     * A camera over this frame's scene with its settings, writing into {@code image} (the driver
     * uses it to describe the settings and to draw the grid the settings may ask for).
     */
    Camera camera(ImageWriter image) {
        return builder().setImageWriter(image).build();
    }

    /** A builder of this frame's view with its settings replayed, quiet. */
    private Camera.Builder builder() {
        try {
            LoadedScene loaded = scene.loaded();
            return settings.replay(loaded.requireView(), loaded.scene()).setSummary(false).setDebugPrint(0);
        } catch (SceneFormatException e) {
            // read() checked that the file has a camera.
            throw new IllegalStateException(e.getMessage(), e);
        }
    }
}
