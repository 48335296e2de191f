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
     * @throws IllegalArgumentException for the zero vector or a non-finite component
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

    /** A vector from a {@link Double3} (course compatibility). */
    public Vector(Double3 xyz) {
        this(xyz.d1, xyz.d2, xyz.d3);
    }

    /** @return the sum, which must not be the zero vector */
    public Vector add(Vector v) {
        return new Vector(x + v.x, y + v.y, z + v.z);
    }

    /** @return the difference, which must not be the zero vector */
    public Vector subtract(Vector v) {
        return new Vector(x - v.x, y - v.y, z - v.z);
    }

    /** @throws IllegalArgumentException when {@code k} is zero (the result would be the zero vector) */
    public Vector scale(double k) {
        return new Vector(x * k, y * k, z * k);
    }

    public double dotProduct(Vector v) {
        return x * v.x + y * v.y + z * v.z;
    }

    /** @throws IllegalArgumentException when the vectors are parallel (the product is zero) */
    public Vector crossProduct(Vector v) {
        double cx = y * v.z - z * v.y;
        double cy = z * v.x - x * v.z;
        double cz = x * v.y - y * v.x;
        if (Util.isZero(cx) && Util.isZero(cy) && Util.isZero(cz))
            throw new IllegalArgumentException("cross product of parallel vectors " + this + " and " + v);
        return new Vector(cx, cy, cz, true);
    }

    public double lengthSquared() {
        return x * x + y * y + z * z;
    }

    public double length() {
        return Math.sqrt(lengthSquared());
    }

    /**
     * @return the unit vector with this direction: this vector itself when its length is already 1
     *         within the zero tolerance (so re-normalizing a unit vector allocates nothing)
     */
    public Vector normalize() {
        double len2 = lengthSquared();
        if (Util.isZero(len2 - 1)) return this;
        double inv = 1.0 / Math.sqrt(len2);
        return new Vector(x * inv, y * inv, z * inv, true);
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
