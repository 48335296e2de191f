package primitives;

/**
 * An immutable triple of doubles: per-channel coefficients (kD, kS, kT, kR, attenuation factors).
 * {@link #equals(Object)} is tolerant: components equal within {@link Util#isZero(double)}.
 * Its arithmetic is {@link Rgb}'s per-channel kernels, shared with {@link Color}.
 */
public final class Double3 {
    final double d1;
    final double d2;
    final double d3;

    /** (0, 0, 0) */
    public static final Double3 ZERO = new Double3(0, 0, 0);
    /** (1, 1, 1) */
    public static final Double3 ONE = new Double3(1, 1, 1);

    /**
     * @param d1 the first component (red, for a colour coefficient)
     * @param d2 the second component (green)
     * @param d3 the third component (blue)
     */
    public Double3(double d1, double d2, double d3) {
        this.d1 = d1;
        this.d2 = d2;
        this.d3 = d3;
    }

    /** @param value the value of all three components (a grey coefficient) */
    public Double3(double value) {
        this(value, value, value);
    }

    /** @return the first component */
    public double getD1() {
        return d1;
    }

    /** @return the second component */
    public double getD2() {
        return d2;
    }

    /** @return the third component */
    public double getD3() {
        return d3;
    }

    /** @return the first component: the 2024–25 (record) spelling of {@link #getD1()} */
    public double d1() {
        return d1;
    }

    /** @return the second component: the 2024–25 (record) spelling of {@link #getD2()} */
    public double d2() {
        return d2;
    }

    /** @return the third component: the 2024–25 (record) spelling of {@link #getD3()} */
    public double d3() {
        return d3;
    }

    /** @return the first component: the 2025–26 (record) spelling of {@link #getD1()} */
    public double _d1() {
        return d1;
    }

    /** @return the second component: the 2025–26 (record) spelling of {@link #getD2()} */
    public double _d2() {
        return d2;
    }

    /** @return the third component: the 2025–26 (record) spelling of {@link #getD3()} */
    public double _d3() {
        return d3;
    }

    /**
     * @param rhs the triple to add
     * @return the component-wise sum
     */
    public Double3 add(Double3 rhs) {
        return new Double3(Rgb.sum(d1, rhs.d1), Rgb.sum(d2, rhs.d2), Rgb.sum(d3, rhs.d3));
    }

    /**
     * @param rhs the triple to subtract
     * @return the component-wise difference
     */
    public Double3 subtract(Double3 rhs) {
        return new Double3(d1 - rhs.d1, d2 - rhs.d2, d3 - rhs.d3);
    }

    /**
     * @param k the factor of all three components
     * @return this triple times {@code k}
     */
    public Double3 scale(double k) {
        return new Double3(Rgb.product(d1, k), Rgb.product(d2, k), Rgb.product(d3, k));
    }

    /**
     * @param k the divisor of all three components; 0 gives infinities or NaN, not an exception
     * @return this triple divided by {@code k}
     */
    public Double3 reduce(double k) {
        return new Double3(Rgb.quotient(d1, k), Rgb.quotient(d2, k), Rgb.quotient(d3, k));
    }

    /**
     * The component-wise product: how coefficients along a path of bounces combine (kR·kT…).
     *
     * @param rhs the other factor
     * @return (d1·rhs.d1, d2·rhs.d2, d3·rhs.d3)
     */
    public Double3 product(Double3 rhs) {
        return new Double3(Rgb.product(d1, rhs.d1), Rgb.product(d2, rhs.d2), Rgb.product(d3, rhs.d3));
    }

    /**
     * @param k the bound; the tracer passes {@code MIN_CALC_COLOR_K} to stop paths that no longer matter
     * @return true when all three components are below {@code k}
     */
    public boolean lowerThan(double k) {
        return Rgb.allBelow(d1, d2, d3, k);
    }

    /**
     * @param other the bounds, component by component
     * @return true when each component is below the matching component of {@code other}
     */
    public boolean lowerThan(Double3 other) {
        return d1 < other.d1 && d2 < other.d2 && d3 < other.d3;
    }

    /** @return true when every component is exactly zero (the cheap test for "no contribution") */
    public boolean isZero() {
        return Rgb.allZero(d1, d2, d3);
    }

    @Override
    public boolean equals(Object obj) {
        if (this == obj) return true;
        return obj instanceof Double3 other
                && Util.isZero(d1 - other.d1)
                && Util.isZero(d2 - other.d2)
                && Util.isZero(d3 - other.d3);
    }

    /** Constant: tolerant equality admits no finer hash that stays consistent with it. */
    @Override
    public int hashCode() {
        return 3;
    }

    @Override
    public String toString() {
        return "(" + d1 + "," + d2 + "," + d3 + ")";
    }
}
