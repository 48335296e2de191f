package primitives;

/**
 * An immutable non-zero vector. It extends {@link Point} as in the course design, so a vector can
 * be passed where the course code passes a point.
 */
public class Vector extends Point {
    /** Unit vector along x. */
    public static final Vector AXIS_X = new Vector(1, 0, 0);
    /** Unit vector along y. */
    public static final Vector AXIS_Y = new Vector(0, 1, 0);
    /** Unit vector along z. */
    public static final Vector AXIS_Z = new Vector(0, 0, 1);
    /**
     * {@link #AXIS_X} under the 2023–24 cohorts' name (the same object). One cohort's Z pointed
     * along −z; the majority and the axis names decide: X, Y and Z are the positive axes.
     */
    public static final Vector X = AXIS_X;
    /** {@link #AXIS_Y} under the 2023–24 cohorts' name (the same object). */
    public static final Vector Y = AXIS_Y;
    /** {@link #AXIS_Z} under the 2023–24 cohorts' name (the same object): +z, not the one cohort's −z. */
    public static final Vector Z = AXIS_Z;

    /**
     * Squared lengths (and products of them) strictly between these are computed and used without
     * overflow or loss to underflow; outside, the components are scaled first.
     */
    private static final double SAFE_MIN = 0x1p-900, SAFE_MAX = 0x1p900;
    /** Operands are parallel when sin² of their angle is at most this: (2^-40)², the zero tolerance squared. */
    private static final double PARALLEL_SIN2 = 0x1p-80;

    /**
     * @param x the x component
     * @param y the y component
     * @param z the z component
     * @throws IllegalArgumentException for the zero vector (all components within the zero tolerance)
     *         or a non-finite component
     */
    public Vector(double x, double y, double z) {
        super(x, y, z);
        if (Util.isZero(x) && Util.isZero(y) && Util.isZero(z))
            throw new IllegalArgumentException("a vector cannot be the zero vector, got " + this);
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z))
            throw new IllegalArgumentException("vector components must be finite, got " + this);
    }

    /** For results known to be non-zero and finite (a normalized or checked vector): skips the checks. */
    Vector(double x, double y, double z, boolean trusted) {
        super(x, y, z);
    }

    /**
     * @param xyz the three components (course compatibility)
     * @throws IllegalArgumentException for the zero vector or a non-finite component
     */
    public Vector(Double3 xyz) {
        this(xyz.d1, xyz.d2, xyz.d3);
    }

    /** @return the sum, which must not be the zero vector */
    public Vector add(Vector v) {
        return new Vector(x + v.x, y + v.y, z + v.z);
    }

    /**
     * @param v the vector to subtract
     * @return the difference, which must not be the zero vector
     * @throws IllegalArgumentException when the vectors are equal (the zero vector)
     */
    public Vector subtract(Vector v) {
        return new Vector(x - v.x, y - v.y, z - v.z);
    }

    /**
     * @param k the factor; negative reverses the direction
     * @return this vector times {@code k}
     * @throws IllegalArgumentException when {@code k} is zero (the result would be the zero vector)
     */
    public Vector scale(double k) {
        return new Vector(x * k, y * k, z * k);
    }

    /**
     * @param v the other vector
     * @return the scalar product: |this|·|v|·cos of the angle between them
     */
    public double dotProduct(Vector v) {
        return x * v.x + y * v.y + z * v.z;
    }

    /**
     * The cross product, rejected when the operands are parallel: when the sine of their angle is
     * at most 2^-40 (the library's zero tolerance, as a relative measure, so the test does not
     * depend on the operands' lengths: two orthogonal vectors of length 1e-7 are not parallel).
     * The result is not checked against the absolute zero tolerance: it may be shorter.
     *
     * @param v the right-hand operand
     * @return this × v, orthogonal to both, following the right-hand rule
     * @throws IllegalArgumentException when the vectors are parallel, or the product is beyond the
     *                                  range of a double
     */
    public Vector crossProduct(Vector v) {
        double[] c = new double[3]; // scalar-replaced by the JIT once crossProduct is inlined
        crossProduct(x, y, z, v.x, v.y, v.z, c);
        return new Vector(c[0], c[1], c[2], true);
    }

    /**
     * The arithmetic of {@link #crossProduct(Vector)} on raw components (same checks, same bits),
     * for a tracer that keeps its vectors in doubles ({@link Kernels#crossProduct}).
     *
     * @param ax  the left operand's x component (a non-zero, finite vector; not checked)
     * @param ay  the left operand's y component
     * @param az  the left operand's z component
     * @param bx  the right operand's x component (a non-zero, finite vector; not checked)
     * @param by  the right operand's y component
     * @param bz  the right operand's z component
     * @param out receives a × b in {@code out[0..2]}
     * @throws IllegalArgumentException when the vectors are parallel, or the product is beyond the
     *                                  range of a double
     */
    static void crossProduct(double ax, double ay, double az, double bx, double by, double bz, double[] out) {
        double cx = ay * bz - az * by;
        double cy = az * bx - ax * bz;
        double cz = ax * by - ay * bx;
        double ab2 = (ax * ax + ay * ay + az * az) * (bx * bx + by * by + bz * bz);
        // |a × b|² ≤ |a|²|b|², so in this range no square below overflows or underflows.
        if (ab2 > SAFE_MIN && ab2 < SAFE_MAX) {
            if (cx * cx + cy * cy + cz * cz <= PARALLEL_SIN2 * ab2) throw parallel(ax, ay, az, bx, by, bz);
            out[0] = cx;
            out[1] = cy;
            out[2] = cz;
            return;
        }
        // Huge or tiny operands: decide on copies scaled to a largest component of 1, then scale back.
        double ma = maxAbs(ax, ay, az), mb = maxAbs(bx, by, bz);
        double sax = ax / ma, say = ay / ma, saz = az / ma, sbx = bx / mb, sby = by / mb, sbz = bz / mb;
        double sx = say * sbz - saz * sby, sy = saz * sbx - sax * sbz, sz = sax * sby - say * sbx;
        if (sx * sx + sy * sy + sz * sz
                <= PARALLEL_SIN2 * (sax * sax + say * say + saz * saz) * (sbx * sbx + sby * sby + sbz * sbz))
            throw parallel(ax, ay, az, bx, by, bz);
        cx = sx * ma * mb;
        cy = sy * ma * mb;
        cz = sz * ma * mb;
        if (!Double.isFinite(cx) || !Double.isFinite(cy) || !Double.isFinite(cz) || cx == 0 && cy == 0 && cz == 0)
            throw new IllegalArgumentException("cross product of " + new Vector(ax, ay, az, true) + " and "
                    + new Vector(bx, by, bz, true) + " is beyond the range of a double");
        out[0] = cx;
        out[1] = cy;
        out[2] = cz;
    }

    private static IllegalArgumentException parallel(double ax, double ay, double az, double bx, double by, double bz) {
        return new IllegalArgumentException("cross product of parallel vectors " + new Vector(ax, ay, az, true) + " and "
                + new Vector(bx, by, bz, true));
    }

    /** The largest absolute component: positive for a non-zero vector. */
    private static double maxAbs(double x, double y, double z) {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /** @return the squared length: what comparisons need, without a square root */
    public double lengthSquared() {
        return x * x + y * y + z * z;
    }

    /** @return the Euclidean length, &gt; 0 */
    public double length() {
        return Math.sqrt(lengthSquared());
    }

    /**
     * @return the unit vector with this direction: this vector itself when its length is already 1
     *         within the zero tolerance (so re-normalizing a unit vector allocates nothing). Vectors
     *         whose squared length would overflow (components beyond about 1e154) or underflow
     *         are divided by their largest component first.
     */
    public Vector normalize() {
        double[] unit = new double[3]; // scalar-replaced by the JIT once normalize is inlined
        return normalize(x, y, z, unit) ? new Vector(unit[0], unit[1], unit[2], true) : this;
    }

    /**
     * The arithmetic of {@link #normalize()} on raw components, for a tracer that keeps its
     * vectors in doubles ({@link Kernels#normalize}): the one implementation of normalization, so both forms give the same
     * bits.
     *
     * @param x   the x component of a non-zero, finite vector (not checked)
     * @param y   the y component
     * @param z   the z component
     * @param out receives the unit vector's components in {@code out[0..2]}
     * @return false when (x, y, z) already has unit length within the zero tolerance: {@code out}
     *         then holds it unchanged
     */
    static boolean normalize(double x, double y, double z, double[] out) {
        double len2 = x * x + y * y + z * z;
        if (Util.isZero(len2 - 1)) {
            out[0] = x;
            out[1] = y;
            out[2] = z;
            return false;
        }
        if (len2 > SAFE_MIN && len2 < SAFE_MAX) {
            double inv = 1.0 / Math.sqrt(len2);
            out[0] = x * inv;
            out[1] = y * inv;
            out[2] = z * inv;
            return true;
        }
        double m = maxAbs(x, y, z);
        double sx = x / m, sy = y / m, sz = z / m; // the largest is ±1: the squares are safe
        double inv = 1.0 / Math.sqrt(sx * sx + sy * sy + sz * sz);
        out[0] = sx * inv;
        out[1] = sy * inv;
        out[2] = sz * inv;
        return true;
    }

    /** @return this vector scaled by −1 (never zero, so unchecked) */
    public Vector negate() {
        return new Vector(-x, -y, -z, true);
    }

    // equals/hashCode are Point's: a vector equals a point of the same coordinates, in both
    // directions (a Vector-only override made Point.equals(Vector) true but Vector.equals(Point) false).

    @Override
    public String toString() {
        return "->" + super.toString();
    }
}
