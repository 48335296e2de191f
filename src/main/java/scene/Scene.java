package scene;

import java.util.LinkedList;
import java.util.List;
import java.util.Objects;

import geometries.Geometries;
import lighting.AmbientLight;
import lighting.LightSource;
import primitives.Color;

/**
 * What a render shows: geometries, lights, ambient light and background. Built by the scene test
 * (directly through the public fields, as in the course, or with the fluent setters) and then
 * left unchanged while a render runs.
 */
public class Scene {
    /** The scene's name (used in progress lines and reports). */
    public final String name;
    /** The colour of rays that hit nothing. */
    public Color background = Color.BLACK;
    /** The uniform ambient light. */
    public AmbientLight ambientLight = AmbientLight.NONE;
    /** Everything that can be hit. */
    public Geometries geometries = new Geometries();
    /** The light sources (the ambient light excluded). */
    public List<LightSource> lights = new LinkedList<>();

    public Scene(String name) {
        this.name = Objects.requireNonNull(name, "scene name");
    }

    public Scene setBackground(Color background) {
        this.background = Objects.requireNonNull(background, "background");
        return this;
    }

    public Scene setAmbientLight(AmbientLight ambientLight) {
        this.ambientLight = Objects.requireNonNull(ambientLight, "ambient light");
        return this;
    }

    public Scene setGeometries(Geometries geometries) {
        this.geometries = Objects.requireNonNull(geometries, "geometries");
        return this;
    }

    public Scene setLights(List<LightSource> lights) {
        this.lights = Objects.requireNonNull(lights, "lights");
        return this;
    }
}
