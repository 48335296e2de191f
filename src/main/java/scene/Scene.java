package scene;

import java.util.LinkedList;
import java.util.List;
import java.util.Objects;

import geometries.Geometries;
import lighting.AmbientLight;
import lighting.LightSource;
import primitives.Color;
import primitives.CourseClassGuard;

/**
 * The scene you fill in a scene test, every course year (2023&ndash;24 to 2025&ndash;26):
 * {@code new Scene("name")}, then {@code scene.geometries.add(...)}, {@code scene.lights.add(...)}
 * and the fluent setters of the background and the ambient light.
 *
 * <p>What a render shows: geometries, lights, ambient light and background. Built by the scene test
 * (directly through the public fields, as in the course, or with the fluent setters) and then
 * left unchanged while a render runs.
 */
public class Scene {
    // Before the fields: their initialisers are the first to use other classes of the library.
    {
        CourseClassGuard.check();
    }

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

    /**
     * An empty scene: black background, no ambient light, no geometries, no lights.
     *
     * @param name the scene's name, for progress lines and reports
     * @throws NullPointerException when the name is null
     */
    public Scene(String name) {
        this.name = Objects.requireNonNull(name, "scene name");
    }

    /**
     * @param background the colour of rays that hit nothing
     * @return this scene, for chaining
     * @throws NullPointerException when it is null
     */
    public Scene setBackground(Color background) {
        this.background = Objects.requireNonNull(background, "background");
        return this;
    }

    /**
     * @param ambientLight the uniform light added at every hit, before the light sources
     * @return this scene, for chaining
     * @throws NullPointerException when it is null ({@link AmbientLight#NONE} is "none")
     */
    public Scene setAmbientLight(AmbientLight ambientLight) {
        this.ambientLight = Objects.requireNonNull(ambientLight, "ambient light");
        return this;
    }

    /**
     * @param geometries everything that can be hit, replacing the current composite
     * @return this scene, for chaining
     * @throws NullPointerException when it is null
     */
    public Scene setGeometries(Geometries geometries) {
        this.geometries = Objects.requireNonNull(geometries, "geometries");
        return this;
    }

    /**
     * @param lights the light sources, replacing the current list; the list is kept, not copied
     * @return this scene, for chaining
     * @throws NullPointerException when it is null
     */
    public Scene setLights(List<LightSource> lights) {
        this.lights = Objects.requireNonNull(lights, "lights");
        return this;
    }

    /**
     * The course spelling of "use a BVH for this scene" (2025–26 sources; also
     * {@link #makeBVH()}, {@link #enableBVH()}): {@link Geometries#buildBVH()} of
     * {@link #geometries}, which does nothing, since every render builds (or reuses) the tracer's
     * BVH over the scene as it is then.
     *
     * @return this scene, for chaining
     */
    public Scene buildBVH() {
        geometries.buildBVH();
        return this;
    }

    /**
     * Another course spelling of {@link #buildBVH()}: does nothing (see there).
     *
     * @return this scene, for chaining
     */
    public Scene makeBVH() {
        return buildBVH();
    }

    /**
     * Another course spelling of {@link #buildBVH()}: does nothing (see there).
     *
     * @return this scene, for chaining
     */
    public Scene enableBVH() {
        return buildBVH();
    }
}
