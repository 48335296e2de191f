package lighting;

import java.util.Objects;

import primitives.Color;
import primitives.CourseClassGuard;
import primitives.LibraryClasses;

/** The part every light shares: its intensity, and whether it is one of the library's lights. */
abstract class Light {
    /** The library's own lights: the one list behind {@link #isLibraryLight()}. */
    private static final LibraryClasses LIGHTS = LibraryClasses.of(AmbientLight.class, DirectionalLight.class,
            PointLight.class, SpotLight.class);

    /** The emitted intensity, on the colour scale (0..255 per channel is "full"). */
    protected final Color intensity;
    /** {@link #isLibraryLight()}, fixed per object: the doubles forms read it for every shaded point. */
    private final boolean library;

    protected Light(Color intensity) {
        CourseClassGuard.check();
        this.intensity = Objects.requireNonNull(intensity, "light intensity");
        this.library = LIGHTS.contains(this);
    }

    /**
     * Whether this is one of the library's own lights, not a user's subclass of one. The
     * library's lights answer the renderer's questions about points given as doubles
     * ({@code getL(x, y, z, out)} and the like) with their own arithmetic, the same as their
     * object forms'; a subclass may override an object form ({@code getL(Point)},
     * {@code getIntensity(Point)}, {@code getDistance(Point)}, a point light's
     * {@code attenuation(Point)}), so for it, even one that overrides nothing, the doubles forms
     * ask the object forms.
     *
     * @return true for an instance of exactly one of the library's light classes
     */
    final boolean isLibraryLight() {
        return library;
    }

    /** @return the emitted intensity, before any attenuation by distance or beam shape */
    public Color getIntensity() {
        return intensity;
    }
}
