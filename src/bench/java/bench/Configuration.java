package bench;

import java.util.function.Supplier;

import renderer.Camera;
import scene.Scene;

/**
 * One row of the benchmark: a scene, a resolution and the settings to render it with.
 *
 * @param group       the group it belongs to (teapot, glossy, showcase, scaling)
 * @param sceneKey    identifies the scene: consecutive configurations with the same key share one
 *                    scene instance (scenes are built outside the timing)
 * @param scene       builds the scene
 * @param sceneLabel  the scene column of the table
 * @param settings    the settings column, in words
 * @param width       image columns
 * @param height      image rows
 * @param threads     render threads (setMultithreading)
 * @param bvh         whether the tracer uses the BVH (the harness times the build separately)
 * @param primitives  the scaling group's primitive count, 0 elsewhere
 * @param warmupScale the warm-up render's side as a fraction of the timed one: 1 for a full
 *                    render; less for costly configurations whose code the group's earlier
 *                    configurations already warmed up
 * @param camera      a builder for the scene with view, tracer and sampling set; the harness adds
 *                    the image writer, threads and silences the summary
 */
record Configuration(String group, String sceneKey, Supplier<Scene> scene, String sceneLabel, String settings,
                     int width, int height, int threads, boolean bvh, long primitives, double warmupScale,
                     CameraFactory camera) {

    /** Makes the camera builder of a configuration for its (shared) scene. */
    @FunctionalInterface
    interface CameraFactory {
        Camera.Builder builder(Scene scene);
    }

    /** "group settings, N threads", e.g. "teapot BVH, 2 threads": what {@code --match} matches. */
    String describe() {
        return group + " " + settings + ", " + threads + (threads == 1 ? " thread" : " threads");
    }

    String resolution() {
        return width + "×" + height;
    }
}
