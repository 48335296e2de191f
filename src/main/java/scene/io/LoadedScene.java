package scene.io;

import java.util.Objects;
import java.util.Optional;

import renderer.Camera;
import scene.Scene;

/**
 * What a scene file describes: the scene, the camera when the file has one (a builder with the
 * view and the file's {@link RenderSettings} already applied, ready to {@code build()} or to
 * be overridden first) and the render settings themselves.
 */
public final class LoadedScene {
    private final Scene scene;
    private final Camera.Builder camera;
    private final RenderSettings settings;
    /** The error to report when a caller needs the camera that is not there (at {@code <scene>}). */
    private final SceneFormatException noCamera;

    LoadedScene(Scene scene, Camera.Builder camera, RenderSettings settings, SceneFormatException noCamera) {
        this.scene = Objects.requireNonNull(scene, "scene");
        this.camera = camera;
        this.settings = Objects.requireNonNull(settings, "settings");
        this.noCamera = noCamera;
    }

    public Scene scene() {
        return scene;
    }

    /**
     * @return the camera builder, empty when the file has no {@code <camera>} (the course's scene
     *         files describe only the scene)
     */
    public Optional<Camera.Builder> camera() {
        return Optional.ofNullable(camera);
    }

    /**
     * @return the camera builder
     * @throws SceneFormatException at the {@code <scene>} element when the file has no camera
     */
    public Camera.Builder requireCamera() throws SceneFormatException {
        if (camera == null) throw noCamera;
        return camera;
    }

    public RenderSettings settings() {
        return settings;
    }
}
