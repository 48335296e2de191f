package lighting;

import java.util.Objects;

import primitives.Checks;
import primitives.Color;
import primitives.Point;
import primitives.Util;
import primitives.Vector;

/**
 * A point light with a direction: intensity is scaled by max(0, direction · l)^narrowBeam, so a
 * larger narrow-beam exponent gives a tighter spot.
 */
public class SpotLight extends PointLight {
    private final Vector direction;
    private double narrowBeam = 1;

    /**
     * @param intensity the intensity on the beam's axis at the light (before attenuation), non-negative
     * @param position  where the light is, in scene coordinates
     * @param direction the axis of the beam, pointing from the light toward what it lights; any
     *                  length (it is normalized). Points at 90° or more from it, seen from the
     *                  light, get no light at all.
     */
    public SpotLight(Color intensity, Point position, Vector direction) {
        super(intensity, position);
        this.direction = Objects.requireNonNull(direction, "spot direction").normalize();
    }

    @Override
    public SpotLight setKc(double kC) {
        super.setKc(kC);
        return this;
    }

    @Override
    public SpotLight setKl(double kL) {
        super.setKl(kL);
        return this;
    }

    @Override
    public SpotLight setKq(double kQ) {
        super.setKq(kQ);
        return this;
    }

    /**
     * @param kC constant attenuation, ≥ 0
     * @return this light
     */
    @Override
    public SpotLight setKC(double kC) {
        return setKc(kC);
    }

    /**
     * @param kL linear attenuation per unit distance, ≥ 0
     * @return this light
     */
    @Override
    public SpotLight setKL(double kL) {
        return setKl(kL);
    }

    /**
     * @param kQ quadratic attenuation per squared unit distance, ≥ 0
     * @return this light
     */
    @Override
    public SpotLight setKQ(double kQ) {
        return setKq(kQ);
    }

    @Override
    public SpotLight setkC(double kC) {
        return setKc(kC);
    }

    @Override
    public SpotLight setkL(double kL) {
        return setKl(kL);
    }

    @Override
    public SpotLight setkQ(double kQ) {
        return setKq(kQ);
    }

    @Override
    public SpotLight setRadius(double radius) {
        super.setRadius(radius);
        return this;
    }

    /**
     * @param narrowBeam the beam exponent, a positive number: the intensity falls off as
     *                   max(0, cos θ)^narrowBeam away from the axis; 1 (the default) is the plain cosine
     * @return this light, for chaining
     * @throws IllegalArgumentException when it is not a positive finite number, naming it
     */
    public SpotLight setNarrowBeam(double narrowBeam) {
        this.narrowBeam = changed(this.narrowBeam, Checks.requirePositive(narrowBeam, "spot light narrow beam"));
        return this;
    }

    /**
     * @return the point light's fingerprint and the narrow beam's (see {@link DoublesLight#settingsStamp()})
     */
    @Override
    long settingsStamp() {
        return mix(super.settingsStamp(), narrowBeam);
    }

    /** The attenuation times the beam's weight max(0, cos θ)^narrowBeam; 0 outside the beam. */
    @Override
    double intensityFactor(double x, double y, double z) {
        // cos of the angle between the beam axis and the light-to-point direction
        double dx = x - position.getX(), dy = y - position.getY(), dz = z - position.getZ();
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len == 0) throw atPosition(x, y, z); // else cos = 0/0 and the NaN fails far from here
        double cos = Util.alignZero((direction.getX() * dx + direction.getY() * dy + direction.getZ() * dz) / len);
        if (cos <= 0) return 0;
        double factor = narrowBeam == 1 ? cos : Math.pow(cos, narrowBeam);
        return factor * attenuation(x, y, z);
    }
}
