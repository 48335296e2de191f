package primitives;

/**
 * An immutable triple of doubles: per-channel coefficients (kD, kS, kT, kR, attenuation factors).
 * {@link #equals(Object)} is tolerant: components equal within {@link Util#isZero(double)}.
 */
public final class Double3 {
    final double d1;
    final double d2;
    final double d3;

    /** (0, 0, 0) */
    public static final Double3 ZERO = new Double3(0, 0, 0);
    /** (1, 1, 1) */
    public static final Double3 ONE = new Double3(1, 1, 1);

    public Double3(double d1, double d2, double d3) {
        this.d1 = d1;
        this.d2 = d2;
        this.d3 = d3;
    }

    /** The same value in all three components. */
    public Double3(double value) {
        this(value, value, value);
    }

    public double getD1() {
        return d1;
    }

    public double getD2() {
        return d2;
    }

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

    public Double3 add(Double3 rhs) {
        return new Double3(d1 + rhs.d1, d2 + rhs.d2, d3 + rhs.d3);
    }

    public Double3 subtract(Double3 rhs) {
        return new Double3(d1 - rhs.d1, d2 - rhs.d2, d3 - rhs.d3);
    }

    public Double3 scale(double k) {
        return new Double3(d1 * k, d2 * k, d3 * k);
    }

    /** Divides every component by {@code k}. */
    public Double3 reduce(double k) {
        return new Double3(d1 / k, d2 / k, d3 / k);
    }

    /** Component-wise product. */
    public Double3 product(Double3 rhs) {
        return new Double3(d1 * rhs.d1, d2 * rhs.d2, d3 * rhs.d3);
    }

    /** @return true when all three components are below {@code k} */
    public boolean lowerThan(double k) {
        return d1 < k && d2 < k && d3 < k;
    }

    /** @return true when each component is below the matching component of {@code other} */
    public boolean lowerThan(Double3 other) {
        return d1 < other.d1 && d2 < other.d2 && d3 < other.d3;
    }

    /** @return true when every component is exactly zero (the cheap test for "no contribution") */
    public boolean isZero() {
        return d1 == 0 && d2 == 0 && d3 == 0;
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
