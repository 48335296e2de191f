package lighting;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/**
 * The library's lights that illuminate points (directional, point, spot): the renderer asks them
 * the three questions of {@link LightSource} about a point given as doubles (no object per shaded
 * point), and checks their settings before and after a render. These forms are package-private, so
 * that a student completing {@code light.} sees the course's methods only; the renderer reaches
 * them through {@link LightQueries}, which asks a user's own {@link LightSource} through its course
 * methods ({@link #intensityOf}, {@link #directionOf}, {@link #distanceOf}). A user's subclass of a
 * library light inherits these forms, which ask its course methods (it may override them).
 */
abstract class DoublesLight extends Light implements LightSource {
    DoublesLight(Color intensity) {
        super(intensity);
    }

    /** {@link #getIntensity(Point)} of (x, y, z) into {@code out[0..2]} (red, green, blue). */
    abstract void getIntensity(double x, double y, double z, double[] out);

    /** {@link #getL(Point)} of (x, y, z): the unit direction from the light into {@code out[0..2]}. */
    abstract void getL(double x, double y, double z, double[] out);

    /** @return {@link #getDistance(Point)} of (x, y, z), in scene units; +∞ for a light at infinity */
    abstract double getDistance(double x, double y, double z);

    /**
     * Checks the settings that only make sense together, once the scene is built and before it
     * is rendered, so that a bad light fails before the first pixel rather than in the middle of a
     * render. Setters cannot do it: course code sets related values one at a time, passing through
     * invalid combinations ({@code setKc(0)} before {@code setKl}). Nothing to check by default.
     *
     * @throws IllegalArgumentException naming the values that do not fit together
     */
    void validate() {
    }

    /**
     * A fingerprint of the settings that can change after the light is made (attenuation, radius,
     * narrow beam): a render notes it when it starts and fails, instead of writing an image lit by
     * two states, when it differs at the end.
     *
     * @return a number that differs whenever a setting the shading reads differs (up to a 2^-64
     *         chance); 0 when there is none to watch
     */
    long settingsStamp() {
        return changes;
    }

    /**
     * How many times a setting was given a different value: counted, not only compared, so that a
     * change made and put back during a render (kL to 0.5 and back 3 ms later) still shows at its
     * end. A value set equal to the old one is no change. Volatile: a setter may run on another
     * thread than the render that compares.
     */
    private volatile int changes;

    /**
     * A setting's new value, counted as a change when it differs from the old (see {@link #changes}).
     *
     * @return {@code now}, for the setter to store
     */
    final double changed(double old, double now) {
        if (Double.compare(old, now) != 0) changes++;
        return now;
    }

    /** @return the number of settings given a different value so far */
    final int changes() {
        return changes;
    }

    /** {@link LightSource#getIntensity(Point)} of any light, asked at (x, y, z), into {@code out[0..2]}. */
    static void intensityOf(LightSource light, double x, double y, double z, double[] out) {
        Color c = light.getIntensity(new Point(x, y, z));
        out[0] = c.getR();
        out[1] = c.getG();
        out[2] = c.getB();
    }

    /** {@link LightSource#getL(Point)} of any light, asked at (x, y, z), into {@code out[0..2]}. */
    static void directionOf(LightSource light, double x, double y, double z, double[] out) {
        Vector l = light.getL(new Point(x, y, z));
        out[0] = l.getX();
        out[1] = l.getY();
        out[2] = l.getZ();
    }

    /** @return {@link LightSource#getDistance(Point)} of any light, asked at (x, y, z) */
    static double distanceOf(LightSource light, double x, double y, double z) {
        return light.getDistance(new Point(x, y, z));
    }
}
