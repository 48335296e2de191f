package lighting;

import java.util.Objects;

import primitives.Checks;
import primitives.Color;
import primitives.Point;
import primitives.Vector;

/**
 * A light at a position, attenuated with distance d by 1 / (kC + kL·d + kQ·d²). Each coefficient
 * is non-negative and they must not all be zero (the intensity would be infinite): that is checked
 * before rendering (the renderer checks its lights while preparing), not by the setters, so that {@code setKc(0).setKl(x)}
 * works in either order. Given a radius the light becomes a disk facing the shaded point, for
 * soft shadows.
 */
public class PointLight extends DoublesLight {
    /** Where the light is, in scene coordinates; the centre of its disk when it has a radius. */
    protected final Point position;
    private double kC = 1;
    private double kL = 0;
    private double kQ = 0;
    private double radius = 0;

    /**
     * A point light radiating equally in all directions, unattenuated until the coefficients are
     * set (kC = 1, kL = kQ = 0).
     *
     * @param intensity the intensity at the light (before attenuation), non-negative
     * @param position  where the light is, in scene coordinates
     */
    public PointLight(Color intensity, Point position) {
        super(intensity);
        this.position = Objects.requireNonNull(position, "light position");
    }

    /**
     * @param kC constant attenuation, finite and ≥ 0 (1 by default)
     * @return this light, for chaining
     * @throws IllegalArgumentException when kC is negative or not finite, naming it
     */
    public PointLight setKc(double kC) {
        this.kC = changed(this.kC, Checks.requireNonNegative(kC, "kC"));
        return this;
    }

    /**
     * @param kL linear attenuation per unit distance, finite and ≥ 0 (0 by default)
     * @return this light, for chaining
     * @throws IllegalArgumentException when kL is negative or not finite, naming it
     */
    public PointLight setKl(double kL) {
        this.kL = changed(this.kL, Checks.requireNonNegative(kL, "kL"));
        return this;
    }

    /**
     * @param kQ quadratic attenuation per squared unit distance, finite and ≥ 0 (0 by default)
     * @return this light, for chaining
     * @throws IllegalArgumentException when kQ is negative or not finite, naming it
     */
    public PointLight setKq(double kQ) {
        this.kQ = changed(this.kQ, Checks.requireNonNegative(kQ, "kQ"));
        return this;
    }

    /**
     * The spelling of {@link #setKc} some course cohorts use.
     *
     * @param kC constant attenuation, ≥ 0
     * @return this light
     */
    public PointLight setKC(double kC) {
        return setKc(kC);
    }

    /**
     * The spelling of {@link #setKl} some course cohorts use.
     *
     * @param kL linear attenuation per unit distance, ≥ 0
     * @return this light
     */
    public PointLight setKL(double kL) {
        return setKl(kL);
    }

    /**
     * The spelling of {@link #setKq} some course cohorts use.
     *
     * @param kQ quadratic attenuation per squared unit distance, ≥ 0
     * @return this light
     */
    public PointLight setKQ(double kQ) {
        return setKq(kQ);
    }

    /**
     * The lower-case-k spelling of {@link #setKc} some course cohorts use.
     *
     * @param kC constant attenuation, ≥ 0
     * @return this light
     * @throws IllegalArgumentException as {@link #setKc}, naming the bad value
     */
    public PointLight setkC(double kC) {
        return setKc(kC);
    }

    /**
     * The lower-case-k spelling of {@link #setKl} some course cohorts use.
     *
     * @param kL linear attenuation per unit distance, ≥ 0
     * @return this light
     * @throws IllegalArgumentException as {@link #setKl}, naming the bad value
     */
    public PointLight setkL(double kL) {
        return setKl(kL);
    }

    /**
     * The lower-case-k spelling of {@link #setKq} some course cohorts use.
     *
     * @param kQ quadratic attenuation per squared unit distance, ≥ 0
     * @return this light
     * @throws IllegalArgumentException as {@link #setKq}, naming the bad value
     */
    public PointLight setkQ(double kQ) {
        return setKq(kQ);
    }

    /**
     * @param radius the radius of the light's disk in scene units, ≥ 0; 0 (the default) is a point
     *               light with hard shadows
     * @return this light, for chaining
     * @throws IllegalArgumentException when the radius is negative or not finite, naming it
     */
    public PointLight setRadius(double radius) {
        this.radius = changed(this.radius, Checks.requireNonNegative(radius, "light radius"));
        return this;
    }

    @Override
    public double getRadius() {
        return radius;
    }

    @Override
    public Point getPosition() {
        return position;
    }

    /**
     * @return a fingerprint of kC, kL, kQ, the radius and how often they changed (see {@link DoublesLight#settingsStamp()})
     */
    @Override
    long settingsStamp() {
        return mix(mix(mix(mix(mix(0, kC), kL), kQ), radius), changes());
    }

    /** One step of a 64-bit multiply-and-add fingerprint over the bits of {@code value}. */
    static long mix(long stamp, double value) {
        return (stamp ^ Double.doubleToLongBits(value)) * 0x9E3779B97F4A7C15L + 0x632BE59BD9B4E019L;
    }

    /**
     * @throws IllegalArgumentException when kC, kL and kQ are all zero, naming the three
     */
    @Override
    void validate() {
        if (kC == 0 && kL == 0 && kQ == 0)
            throw new IllegalArgumentException("point light attenuation coefficients must not all be zero"
                    + " (the intensity would be infinite), got kC=" + kC + ", kL=" + kL + ", kQ=" + kQ);
    }

    /**
     * The distance attenuation factor 1 / (kC + kL·d + kQ·d²).
     *
     * @param p the shaded point; d is its distance from {@link #position}
     * @return the factor the intensity is multiplied by, &gt; 0 (+∞ when all coefficients are 0,
     *         which a render rejects before it starts)
     */
    protected double attenuation(Point p) {
        return attenuationHere(p.getX(), p.getY(), p.getZ());
    }

    /** {@link #attenuation(Point)} of the point (x, y, z): the one computation. */
    final double attenuation(double x, double y, double z) {
        if (!isLibraryLight()) return attenuation(new Point(x, y, z));
        return attenuationHere(x, y, z);
    }

    private double attenuationHere(double x, double y, double z) {
        double d2 = distanceSquared(x, y, z);
        double denominator = kC + kL * Math.sqrt(d2) + kQ * d2;
        if (!(denominator > 0))
            throw new IllegalArgumentException("point light attenuation kC + kL·d + kQ·d² must be positive, got "
                    + denominator + " (kC=" + kC + ", kL=" + kL + ", kQ=" + kQ + ") at " + new Point(x, y, z));
        return 1 / denominator;
    }

    /** The squared distance from (x, y, z) to the light, in Point.distanceSquared's order of operations. */
    private double distanceSquared(double x, double y, double z) {
        double dx = x - position.getX();
        double dy = y - position.getY();
        double dz = z - position.getZ();
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * The factor the light's intensity is multiplied by at (x, y, z): the attenuation here; a
     * spot light also weighs its beam. The one computation behind both forms of getIntensity.
     */
    double intensityFactor(double x, double y, double z) {
        return attenuation(x, y, z);
    }

    @Override
    public Color getIntensity(Point p) {
        return intensity.scale(intensityFactor(p.getX(), p.getY(), p.getZ()));
    }

    @Override
    void getIntensity(double x, double y, double z, double[] out) {
        if (!isLibraryLight()) {
            intensityOf(this, x, y, z, out);
            return;
        }
        double f = intensityFactor(x, y, z);
        out[0] = intensity.getR() * f; // Color.scale's arithmetic, without the object
        out[1] = intensity.getG() * f;
        out[2] = intensity.getB() * f;
    }

    @Override
    public Vector getL(Point p) {
        double[] l = new double[3];
        lHere(p.getX(), p.getY(), p.getZ(), l);
        return new Vector(l[0], l[1], l[2]);
    }

    @Override
    void getL(double x, double y, double z, double[] out) {
        if (!isLibraryLight()) {
            directionOf(this, x, y, z, out);
            return;
        }
        lHere(x, y, z, out);
    }

    private void lHere(double x, double y, double z, double[] out) {
        double dx = x - position.getX(), dy = y - position.getY(), dz = z - position.getZ();
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len == 0) throw atPosition(x, y, z);
        out[0] = dx / len;
        out[1] = dy / len;
        out[2] = dz / len;
    }

    /**
     * The failure of every query that needs the direction from the light to a point that is the
     * light's own position: the direction is 0/0 there.
     */
    static IllegalArgumentException atPosition(double x, double y, double z) {
        return new IllegalArgumentException("point " + new Point(x, y, z)
                + " is at the light's position: the direction from the light to it is undefined");
    }

    @Override
    public double getDistance(Point p) {
        return Math.sqrt(distanceSquared(p.getX(), p.getY(), p.getZ()));
    }

    @Override
    double getDistance(double x, double y, double z) {
        if (!isLibraryLight()) return distanceOf(this, x, y, z);
        return Math.sqrt(distanceSquared(x, y, z));
    }
}
