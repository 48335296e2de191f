package lighting;

/**
 * What the renderer asks of a scene's lights beyond the course's {@link LightSource} methods: the
 * same three questions about a point given as doubles, and the checks of a light's settings before
 * and after a render. Static, and apart from the lights, so that a student completing
 * {@code light.} sees the course's methods only. A library light answers with its own arithmetic
 * (the same numbers as its course methods); any other light, a user's own {@link LightSource}, is
 * asked through its course methods. One type test and one call, which the JIT inlines.
 *
 * @hidden internal: the renderer's questions to a light; a scene test asks getIntensity(Point), getL(Point), getDistance(Point)
 */
public final class LightQueries {
    private LightQueries() {
    }

    /**
     * {@link LightSource#getIntensity(primitives.Point)} of the point (x, y, z).
     *
     * @param light the light asked
     * @param x     the shaded point's x coordinate
     * @param y     its y coordinate
     * @param z     its z coordinate
     * @param out   receives the intensity's red, green and blue in {@code out[0..2]}
     */
    public static void getIntensity(LightSource light, double x, double y, double z, double[] out) {
        if (light instanceof DoublesLight d) d.getIntensity(x, y, z, out);
        else DoublesLight.intensityOf(light, x, y, z, out);
    }

    /**
     * {@link LightSource#getL(primitives.Point)} of the point (x, y, z).
     *
     * @param light the light asked
     * @param x     the shaded point's x coordinate
     * @param y     its y coordinate
     * @param z     its z coordinate
     * @param out   receives the unit direction from the light to the point in {@code out[0..2]}
     */
    public static void getL(LightSource light, double x, double y, double z, double[] out) {
        if (light instanceof DoublesLight d) d.getL(x, y, z, out);
        else DoublesLight.directionOf(light, x, y, z, out);
    }

    /**
     * {@link LightSource#getDistance(primitives.Point)} of the point (x, y, z).
     *
     * @param light the light asked
     * @param x     the shaded point's x coordinate
     * @param y     its y coordinate
     * @param z     its z coordinate
     * @return the distance from the light to the point, in scene units; +∞ for a light at infinity
     */
    public static double getDistance(LightSource light, double x, double y, double z) {
        return light instanceof DoublesLight d ? d.getDistance(x, y, z) : DoublesLight.distanceOf(light, x, y, z);
    }

    /**
     * Checks the settings of a light that only make sense together (a point light's attenuation
     * coefficients must not all be zero); a user's own light has none to check.
     *
     * @param light the light to check, once the scene is built and before it is rendered
     * @throws IllegalArgumentException naming the values that do not fit together
     */
    public static void validate(LightSource light) {
        if (light instanceof DoublesLight d) d.validate();
    }

    /**
     * A fingerprint of the light's settings that can change after it is made: a render notes it
     * when it starts and fails, instead of writing an image lit by two states, when it differs at
     * the end.
     *
     * @param light a light of the scene
     * @return a number that differs whenever a setting the shading reads differs (up to a 2^-64
     *         chance); 0 for a user's own light, which has none the library can watch
     */
    public static long settingsStamp(LightSource light) {
        return light instanceof DoublesLight d ? d.settingsStamp() : 0;
    }

    /**
     * Whether {@code light} is one of the library's own lights, not a user's subclass of one: only
     * those answer the doubles forms with their own arithmetic; a subclass, which may override a
     * course method, is asked through its course methods.
     *
     * @param light any object
     * @return true for an instance of exactly one of the library's light classes (ambient included)
     */
    public static boolean isLibraryLight(Object light) {
        return light instanceof Light l && l.isLibraryLight();
    }
}
