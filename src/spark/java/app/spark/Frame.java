package app.spark;

import java.io.IOException;
import java.io.Serializable;

import renderer.RegionRenderer;
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
     * Parses the scene and builds the renderer an executor renders tiles with: the driver's
     * settings, the calling thread only, no progress lines; it prepares the scene once and
     * allocates no image (a tile's pixels come back on their own).
     *
     * @return the region renderer
     *
     * @throws IllegalStateException when the captured files no longer make a valid scene, which
     *                               the driver's validation rules out
     */
    RegionRenderer executorRenderer() {
        try {
            LoadedScene loaded = files.load();
            return RegionRenderer.of(settings.withThreads(0).replay(loaded.requireView(), loaded.scene()).setDebugPrint(0)
                    .setSummary(false));
        } catch (IOException | SceneFormatException e) {
            throw new IllegalStateException("the scene " + files.scene() + " the driver validated fails on the executor: "
                    + e.getMessage(), e);
        }
    }
}
