package app.spark;

import java.io.IOException;
import java.io.Serializable;

import renderer.Camera;
import renderer.ImageWriter;
import scene.io.LoadedScene;
import scene.io.RenderSettings;
import scene.io.SceneFormatException;

/**
 * One image of a job as it travels to the executors: the scene's captured files and the settings
 * the driver resolved (the file's, with the command line's overrides).
 *
 * @param files    the scene file and its meshes
 * @param settings the resolved settings; the executor renders on the task's own thread whatever
 *                 their thread count says (Spark runs one task per core)
 */
record Frame(SceneFiles files, RenderSettings settings) implements Serializable {
    /**
     * Parses the scene and builds the camera an executor renders tiles with: the driver's
     * settings, the calling thread only, no progress lines and no summary.
     *
     * @param image the camera's pixel buffer, of the frame's size: region renders write there
     * @return the built camera
     *
     * @throws IllegalStateException when the captured files no longer make a valid scene, which
     *                               the driver's validation rules out
     */
    Camera executorCamera(ImageWriter image) {
        try {
            LoadedScene loaded = files.load();
            return settings.withThreads(0).applyTo(loaded.requireView(), loaded.scene(), image)
                    .setDebugPrint(0).setSummary(false).build();
        } catch (IOException | SceneFormatException e) {
            throw new IllegalStateException("the scene " + files.scene() + " the driver validated fails on the executor: "
                    + e.getMessage(), e);
        }
    }
}
