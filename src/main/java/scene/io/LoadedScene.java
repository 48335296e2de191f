package scene.io;

import java.util.Objects;
import java.util.Optional;

import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;

/**
 * What a scene file describes: the scene, and the specification of its render as the file states
 * it, the view when the file has a camera and the {@linkplain RenderSettings settings}. Reading a
 * file allocates nothing of the image's size: a camera builder, with its image writer and tracer,
 * is made when asked for, the specification replayed onto it, either with the file's settings
 * ({@link #requireCamera()}) or with the caller's ({@link #requireView()} and
 * {@link RenderSettings#applyTo(Camera.Builder, Scene, ImageWriter)}).
 */
public final class LoadedScene {
    private final Scene scene;
    /** The file's {@code <camera>}; null when it has none. */
    private final ViewSpec view;
    private final RenderSettings settings;
    /** The error to report when a caller needs the camera that is not there (at {@code <scene>}). */
    private final SceneFormatException noCamera;

    LoadedScene(Scene scene, ViewSpec view, RenderSettings settings, SceneFormatException noCamera) {
        this.scene = Objects.requireNonNull(scene, "scene");
        this.view = view;
        this.settings = Objects.requireNonNull(settings, "settings");
        this.noCamera = noCamera;
    }

    /** @return the scene the file describes, complete (its geometries and lights added) */
    public Scene scene() {
        return scene;
    }

    /**
     * @return a new camera builder with the file's view and {@linkplain #settings() settings}
     *         applied, ready to {@code build()} or to be changed first; empty when the file has no
     *         {@code <camera>} (the course's scene files describe only the scene). Each call
     *         allocates a new image of the file's size.
     */
    public Optional<Camera.Builder> camera() {
        return view == null ? Optional.empty() : Optional.of(settings.applyTo(newView(), scene));
    }

    /**
     * @return as {@link #camera()}
     * @throws SceneFormatException at the {@code <scene>} element when the file has no camera
     */
    public Camera.Builder requireCamera() throws SceneFormatException {
        return settings.applyTo(requireView(), scene);
    }

    /**
     * @return a new camera builder with only the file's view (location, direction, view plane):
     *         the caller sets the rest, typically with changed settings and
     *         {@link RenderSettings#applyTo(Camera.Builder, Scene, ImageWriter)}, so that the image
     *         is allocated once, at its final size
     * @throws SceneFormatException at the {@code <scene>} element when the file has no camera
     */
    public Camera.Builder requireView() throws SceneFormatException {
        if (view == null) throw noCamera;
        return newView();
    }

    private Camera.Builder newView() {
        return view.applyTo(Camera.getBuilder());
    }

    /** @return the render settings as the file states them (the library's defaults where it says nothing) */
    public RenderSettings settings() {
        return settings;
    }
}
