package lighting;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/** A light that illuminates points of the scene (everything but the ambient light). */
public interface LightSource {
    /**
     * @param p the shaded point
     * @return the light's intensity arriving at {@code p} (attenuation and beam shape included)
     */
    Color getIntensity(Point p);

    /**
     * @param p the shaded point
     * @return the unit direction from the light to {@code p}
     */
    Vector getL(Point p);

    /**
     * @param p the shaded point
     * @return the distance from the light to {@code p}, in scene units; +∞ for a light at infinity
     * (shadow rays test occluders up to this distance)
     */
    double getDistance(Point p);

    /*
     * The same three questions about a point given as doubles, for a renderer that keeps its
     * shading state in doubles (no object per shaded point). The library's lights answer them
     * directly, and their object forms above call them; the defaults, for users' own lights,
     * ask the object forms.
     */

    /**
     * {@link #getIntensity(Point)} of the point (x, y, z).
     *
     * @param x   the shaded point's x coordinate
     * @param y   its y coordinate
     * @param z   its z coordinate
     * @param out receives the intensity's red, green and blue in {@code out[0..2]}
     */
    default void getIntensity(double x, double y, double z, double[] out) {
        Color c = getIntensity(new Point(x, y, z));
        out[0] = c.getR();
        out[1] = c.getG();
        out[2] = c.getB();
    }

    /**
     * {@link #getL(Point)} of the point (x, y, z).
     *
     * @param x   the shaded point's x coordinate
     * @param y   its y coordinate
     * @param z   its z coordinate
     * @param out receives the unit direction from the light to the point in {@code out[0..2]}
     */
    default void getL(double x, double y, double z, double[] out) {
        Vector l = getL(new Point(x, y, z));
        out[0] = l.getX();
        out[1] = l.getY();
        out[2] = l.getZ();
    }

    /**
     * {@link #getDistance(Point)} of the point (x, y, z).
     *
     * @param x the shaded point's x coordinate
     * @param y its y coordinate
     * @param z its z coordinate
     * @return the distance from the light to the point; +∞ for a light at infinity
     */
    default double getDistance(double x, double y, double z) {
        return getDistance(new Point(x, y, z));
    }

    /**
     * The radius of the light's disk, for soft shadows; 0 is a point (hard shadows).
     * Lights at infinity have none.
     *
     * @return the radius in scene units, ≥ 0; 0 by default
     */
    default double getRadius() {
        return 0;
    }

    /** @return the light's position, or null for a light at infinity */
    default Point getPosition() {
        return null;
    }

    /**
     * Checks the settings that only make sense together, once the scene is built and before it
     * is rendered (the renderer calls it while preparing), so that a bad light fails before the
     * first pixel rather than in the middle of a render. Setters cannot do it: course code sets
     * related values one at a time, passing through invalid combinations (setKc(0) before setKl).
     * Nothing to check by default.
     *
     * @throws IllegalArgumentException naming the values that do not fit together
     *
     * @hidden internal: the renderer's checks of a light before and after a render
     */
    default void validate() {
    }

    /**
     * A fingerprint of the settings that can change after the light is made (the library's
     * lights: attenuation, radius, narrow beam): a render notes it when it starts and fails,
     * instead of writing an image lit by two states, when it differs at the end. The engine's,
     * not the course's: a light of your own whose settings change returns a number that changes
     * with them; the default, 0, says it has none to watch.
     *
     * @return a number that differs whenever a setting the shading reads differs (up to a 2^-64 chance)
     *
     * @hidden internal: the renderer's checks of a light before and after a render
     */
    default long settingsStamp() {
        return 0;
    }
}
