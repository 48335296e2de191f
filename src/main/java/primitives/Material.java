package primitives;

/**
 * Surface coefficients of the Phong model plus the Whitted tracer's reflection and transparency.
 * The public fields are the course's contract; set them with the validating fluent setters while
 * building a scene, and leave them alone during a render.
 */
public class Material {
    /**
     * Ambient reflection coefficient per channel, each ≥ 0 (the 2024–25 course's): the ambient
     * light reaching a surface is scaled by it; 1 (the default) leaves it as it is.
     */
    public Double3 kA = Double3.ONE;
    /** Diffuse reflection coefficient per channel, each ≥ 0. */
    public Double3 kD = Double3.ZERO;
    /** Specular reflection coefficient per channel, each ≥ 0. */
    public Double3 kS = Double3.ZERO;
    /** Transparency (transmission) coefficient per channel, each in [0, 1]. */
    public Double3 kT = Double3.ZERO;
    /** Mirror reflection coefficient per channel, each in [0, 1]. */
    public Double3 kR = Double3.ZERO;
    /** Phong shininess exponent, ≥ 0. */
    public int nShininess = 0;
    /**
     * Glossy reflection spread: the radius of the disk, at unit distance along the mirror
     * direction, that reflected rays aim at (the tangent of the cone half-angle). 0 is a perfect
     * mirror. Scale-independent: the same value blurs the same angle in any scene.
     */
    public double reflectionSpread = 0;
    /** Diffuse-glass spread: like {@link #reflectionSpread} around the transmitted direction. 0 is clear glass. */
    public double transmissionSpread = 0;
    /**
     * Index of refraction of the medium on the inner side of the surface (the side opposite to its
     * normal) relative to the outer side, which is taken to be air (index 1). 1, the default, keeps
     * the course's straight transmission; any other value bends transmitted rays by Snell's law,
     * turns them into reflections beyond the critical angle (total internal reflection), and, when
     * the material also reflects ({@link #kR} &gt; 0), moves the Fresnel (Schlick) share of the
     * transmitted light into the reflection. Glass is about 1.5, water 1.33, diamond 2.42.
     */
    public double ior = 1;

    /**
     * How many times a setter gave a coefficient a different value: counted, so that a change made
     * and put back during a render still shows at its end (the scene-change check; a public field
     * written directly is seen by the values only). Volatile: a setter may run on another thread.
     */
    private volatile int changes;

    /** @return how many times a setter gave a coefficient a different value */
    int changes() {
        return changes;
    }

    /** A coefficient's new value, counted as a change when it differs from the old (see {@link #changes}). */
    private Double3 changed(Double3 old, Double3 now) {
        if (!now.equals(old)) changes++;
        return now;
    }

    /** As {@link #changed(Double3, Double3)}, for a number. */
    private double changed(double old, double now) {
        if (Double.compare(old, now) != 0) changes++;
        return now;
    }

    /**
     * @param kd the diffuse coefficient of all three channels: finite and ≥ 0 (above 1 is allowed)
     * @return this material, for chaining
     * @throws IllegalArgumentException when kd is negative, NaN or infinite, naming it
     */
    public Material setKd(double kd) {
        return setKd(new Double3(kd));
    }

    /**
     * @param kd the diffuse coefficient per channel, each finite and ≥ 0
     * @return this material, for chaining
     * @throws IllegalArgumentException when a component is negative, NaN or infinite, naming the triple
     */
    public Material setKd(Double3 kd) {
        this.kD = changed(this.kD, check(kd, "kD", false));
        return this;
    }

    /**
     * @param ks the specular coefficient of all three channels: finite and ≥ 0
     * @return this material, for chaining
     * @throws IllegalArgumentException when ks is negative, NaN or infinite, naming it
     */
    public Material setKs(double ks) {
        return setKs(new Double3(ks));
    }

    /**
     * @param ks the specular coefficient per channel, each finite and ≥ 0
     * @return this material, for chaining
     * @throws IllegalArgumentException when a component is negative, NaN or infinite, naming the triple
     */
    public Material setKs(Double3 ks) {
        this.kS = changed(this.kS, check(ks, "kS", false));
        return this;
    }

    /**
     * @param kt the fraction of light transmitted through the surface, all three channels: in
     *           [0, 1], since a surface cannot pass on more light than reaches it
     * @return this material, for chaining
     * @throws IllegalArgumentException when kt is outside [0, 1] or NaN, naming it
     */
    public Material setKt(double kt) {
        return setKt(new Double3(kt));
    }

    /**
     * @param kt the fraction of light transmitted per channel, each in [0, 1]
     * @return this material, for chaining
     * @throws IllegalArgumentException when a component is outside [0, 1] or NaN, naming the triple
     */
    public Material setKt(Double3 kt) {
        this.kT = changed(this.kT, check(kt, "kT", true));
        return this;
    }

    /**
     * @param kr the fraction of light mirrored by the surface, all three channels: in [0, 1]
     * @return this material, for chaining
     * @throws IllegalArgumentException when kr is outside [0, 1] or NaN, naming it
     */
    public Material setKr(double kr) {
        return setKr(new Double3(kr));
    }

    /**
     * @param kr the fraction of light mirrored per channel, each in [0, 1]
     * @return this material, for chaining
     * @throws IllegalArgumentException when a component is outside [0, 1] or NaN, naming the triple
     */
    public Material setKr(Double3 kr) {
        this.kR = changed(this.kR, check(kr, "kR", true));
        return this;
    }

    /**
     * @param ka the ambient coefficient of all three channels: finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException when ka is negative, NaN or infinite, naming it
     */
    public Material setKA(double ka) {
        return setKA(new Double3(ka));
    }

    /**
     * @param ka the ambient coefficient per channel, each finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException when a component is negative, NaN or infinite, naming the triple
     */
    public Material setKA(Double3 ka) {
        this.kA = changed(this.kA, check(ka, "kA", false));
        return this;
    }

    /**
     * The 2024–25 spelling of {@link #setKd(double)}.
     *
     * @param kd the diffuse coefficient of all three channels
     * @return this material
     */
    public Material setKD(double kd) {
        return setKd(kd);
    }

    /**
     * The 2024–25 spelling of {@link #setKd(Double3)}.
     *
     * @param kd the diffuse coefficient per channel
     * @return this material
     */
    public Material setKD(Double3 kd) {
        return setKd(kd);
    }

    /**
     * The 2024–25 spelling of {@link #setKs(double)}.
     *
     * @param ks the specular coefficient of all three channels
     * @return this material
     */
    public Material setKS(double ks) {
        return setKs(ks);
    }

    /**
     * The 2024–25 spelling of {@link #setKs(Double3)}.
     *
     * @param ks the specular coefficient per channel
     * @return this material
     */
    public Material setKS(Double3 ks) {
        return setKs(ks);
    }

    /**
     * The 2024–25 spelling of {@link #setKt(double)}.
     *
     * @param kt the transmitted fraction of all three channels, in [0, 1]
     * @return this material
     */
    public Material setKT(double kt) {
        return setKt(kt);
    }

    /**
     * The 2024–25 spelling of {@link #setKt(Double3)}.
     *
     * @param kt the transmitted fraction per channel, each in [0, 1]
     * @return this material
     */
    public Material setKT(Double3 kt) {
        return setKt(kt);
    }

    /**
     * The 2024–25 spelling of {@link #setKr(double)}.
     *
     * @param kr the mirrored fraction of all three channels, in [0, 1]
     * @return this material
     */
    public Material setKR(double kr) {
        return setKr(kr);
    }

    /**
     * The 2024–25 spelling of {@link #setKr(Double3)}.
     *
     * @param kr the mirrored fraction per channel, each in [0, 1]
     * @return this material
     */
    public Material setKR(Double3 kr) {
        return setKr(kr);
    }

    /**
     * The spelling of {@link #setKA(double)} many cohorts use.
     *
     * @param ka the ambient coefficient of all three channels, finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKA(double)}, naming the bad value
     */
    public Material setKa(double ka) {
        return setKA(ka);
    }

    /**
     * The spelling of {@link #setKA(Double3)} many cohorts use.
     *
     * @param ka the ambient coefficient per channel, each finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKA(Double3)}, naming the bad value
     */
    public Material setKa(Double3 ka) {
        return setKA(ka);
    }

    /**
     * The lower-case-k spelling of {@link #setKA(double)} some cohorts use.
     *
     * @param ka the ambient coefficient of all three channels, finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKA(double)}, naming the bad value
     */
    public Material setkA(double ka) {
        return setKA(ka);
    }

    /**
     * The lower-case-k spelling of {@link #setKA(Double3)} some cohorts use.
     *
     * @param ka the ambient coefficient per channel, each finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKA(Double3)}, naming the bad value
     */
    public Material setkA(Double3 ka) {
        return setKA(ka);
    }

    /**
     * The lower-case-k spelling of {@link #setKd(double)} some cohorts use.
     *
     * @param kd the diffuse coefficient of all three channels, finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKd(double)}, naming the bad value
     */
    public Material setkD(double kd) {
        return setKd(kd);
    }

    /**
     * The lower-case-k spelling of {@link #setKd(Double3)} some cohorts use.
     *
     * @param kd the diffuse coefficient per channel, each finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKd(Double3)}, naming the bad value
     */
    public Material setkD(Double3 kd) {
        return setKd(kd);
    }

    /**
     * The lower-case-k spelling of {@link #setKs(double)} some cohorts use.
     *
     * @param ks the specular coefficient of all three channels, finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKs(double)}, naming the bad value
     */
    public Material setkS(double ks) {
        return setKs(ks);
    }

    /**
     * The lower-case-k spelling of {@link #setKs(Double3)} some cohorts use.
     *
     * @param ks the specular coefficient per channel, each finite and ≥ 0
     * @return this material
     * @throws IllegalArgumentException as {@link #setKs(Double3)}, naming the bad value
     */
    public Material setkS(Double3 ks) {
        return setKs(ks);
    }

    /**
     * The lower-case-k spelling of {@link #setKt(double)} some cohorts use.
     *
     * @param kt the transmitted fraction of all three channels, in [0, 1]
     * @return this material
     * @throws IllegalArgumentException as {@link #setKt(double)}, naming the bad value
     */
    public Material setkT(double kt) {
        return setKt(kt);
    }

    /**
     * The lower-case-k spelling of {@link #setKt(Double3)} some cohorts use.
     *
     * @param kt the transmitted fraction per channel, each in [0, 1]
     * @return this material
     * @throws IllegalArgumentException as {@link #setKt(Double3)}, naming the bad value
     */
    public Material setkT(Double3 kt) {
        return setKt(kt);
    }

    /**
     * The lower-case-k spelling of {@link #setKr(double)} some cohorts use.
     *
     * @param kr the mirrored fraction of all three channels, in [0, 1]
     * @return this material
     * @throws IllegalArgumentException as {@link #setKr(double)}, naming the bad value
     */
    public Material setkR(double kr) {
        return setKr(kr);
    }

    /**
     * The lower-case-k spelling of {@link #setKr(Double3)} some cohorts use.
     *
     * @param kr the mirrored fraction per channel, each in [0, 1]
     * @return this material
     * @throws IllegalArgumentException as {@link #setKr(Double3)}, naming the bad value
     */
    public Material setkR(Double3 kr) {
        return setKr(kr);
    }

    /**
     * @param nShininess the Phong exponent, ≥ 0: the larger, the smaller and sharper the highlight
     * @return this material, for chaining
     * @throws IllegalArgumentException when it is negative, naming it
     */
    public Material setShininess(int nShininess) {
        this.nShininess = (int) changed(this.nShininess, Checks.requireNonNegative(nShininess, "shininess"));
        return this;
    }

    /**
     * The spelling of {@link #setShininess(int)} after the field {@code nShininess}, as some
     * cohorts write it.
     *
     * @param nShininess the Phong exponent, ≥ 0
     * @return this material, for chaining
     * @throws IllegalArgumentException as {@link #setShininess(int)}, naming the value
     */
    public Material setnShininess(int nShininess) {
        return setShininess(nShininess);
    }

    /**
     * The spelling of {@link #setShininess(int)} with a capital N, as some cohorts write it.
     *
     * @param nShininess the Phong exponent, ≥ 0
     * @return this material, for chaining
     * @throws IllegalArgumentException as {@link #setShininess(int)}, naming the value
     */
    public Material setNShininess(int nShininess) {
        return setShininess(nShininess);
    }

    /**
     * @param spread the glossy spread, finite and ≥ 0; see {@link #reflectionSpread}
     * @return this material, for chaining
     * @throws IllegalArgumentException when it is negative, NaN or infinite, naming it
     */
    public Material setReflectionSpread(double spread) {
        this.reflectionSpread = changed(this.reflectionSpread, Checks.requireNonNegative(spread, "reflection spread"));
        return this;
    }

    /**
     * @param spread the diffuse-glass spread, finite and ≥ 0; see {@link #transmissionSpread}
     * @return this material, for chaining
     * @throws IllegalArgumentException when it is negative, NaN or infinite, naming it
     */
    public Material setTransmissionSpread(double spread) {
        this.transmissionSpread = changed(this.transmissionSpread, Checks.requireNonNegative(spread, "transmission spread"));
        return this;
    }

    /**
     * @param ior the index of refraction, see {@link #ior}: finite and &gt; 0 (below 1 is allowed:
     *            a bubble of air in water is 0.75)
     * @return this material, for chaining
     * @throws IllegalArgumentException when it is not above 0, NaN or infinite, naming it
     */
    public Material setIor(double ior) {
        if (!(ior > 0) || Double.isInfinite(ior))
            throw new IllegalArgumentException("index of refraction must be finite and positive, got " + ior);
        this.ior = changed(this.ior, ior);
        return this;
    }

    private static Double3 check(Double3 k, String name, boolean atMostOne) {
        checkComponent(k.d1, k, name, atMostOne);
        checkComponent(k.d2, k, name, atMostOne);
        checkComponent(k.d3, k, name, atMostOne);
        return k;
    }

    private static void checkComponent(double c, Double3 k, String name, boolean atMostOne) {
        if (!(c >= 0) || Double.isInfinite(c) || (atMostOne && c > 1))
            throw new IllegalArgumentException(name + " components must be " + (atMostOne ? "in [0, 1]" : "finite and non-negative") + ", got " + k);
    }
}
