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
}
