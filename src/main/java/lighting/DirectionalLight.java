package lighting;

import java.util.Objects;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/** A light at infinity: the same intensity and direction everywhere, no attenuation. */
public class DirectionalLight extends DoublesLight {
    private final Vector direction;

    /**
     * A light at infinity (the sun): the same intensity and direction at every point, no attenuation.
     *
     * @param intensity the intensity at every point, non-negative
     * @param direction the direction the light travels (normalized here)
     * @throws NullPointerException naming a null argument
     */
    public DirectionalLight(Color intensity, Vector direction) {
        super(intensity);
        this.direction = Objects.requireNonNull(direction, "light direction").normalize();
    }

    @Override
    public Color getIntensity(Point p) {
        return intensity;
    }

    @Override
    public Vector getL(Point p) {
        return direction;
    }

    @Override
    public double getDistance(Point p) {
        return Double.POSITIVE_INFINITY;
    }

    @Override
    void getIntensity(double x, double y, double z, double[] out) {
        if (!isLibraryLight()) {
            intensityOf(this, x, y, z, out);
            return;
        }
        out[0] = intensity.getR();
        out[1] = intensity.getG();
        out[2] = intensity.getB();
    }

    @Override
    void getL(double x, double y, double z, double[] out) {
        if (!isLibraryLight()) {
            directionOf(this, x, y, z, out);
            return;
        }
        out[0] = direction.getX();
        out[1] = direction.getY();
        out[2] = direction.getZ();
    }

    @Override
    double getDistance(double x, double y, double z) {
        return isLibraryLight() ? Double.POSITIVE_INFINITY : distanceOf(this, x, y, z);
    }
}
