package primitives;

import java.util.Objects;

/**
 * An immutable point in 3D space. Coordinates are stored as three doubles (no wrapper object)
 * because every intersection kernel reads them.
 */
public class Point {
    final double x;
    final double y;
    final double z;
    /**
     * The coordinates as the course's {@link Double3}, for course tests in package
     * {@code primitives} that read the field. The library computes with the three doubles; this
     * is one small object more per point, made when the point is.
     */
    protected final Double3 xyz;
    /** {@link #xyz} under the 2025–26 course's name: the same object, so one copy serves both years. */
    protected final Double3 _xyz;

    /** The origin. */
    public static final Point ZERO = new Point(0, 0, 0);

    /**
     * @param x the x coordinate, in scene units, finite
     * @param y the y coordinate, in scene units, finite
     * @param z the z coordinate, in scene units, finite
     * @throws IllegalArgumentException for a NaN or infinite coordinate, naming the point
     */
    public Point(double x, double y, double z) {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)))
            throw new IllegalArgumentException("point coordinates must be finite, got (" + x + "," + y + "," + z + ")");
        this.x = x;
        this.y = y;
        this.z = z;
        this.xyz = new Double3(x, y, z);
        this._xyz = xyz;
    }

    /**
     * A point from a {@link Double3} (course compatibility).
     *
     * @param xyz the three coordinates, in scene units, finite
     * @throws NullPointerException     naming {@code xyz} when it is null
     * @throws IllegalArgumentException for a NaN or infinite coordinate
     */
    public Point(Double3 xyz) {
        this(Objects.requireNonNull(xyz, "point coordinates xyz").d1, xyz.d2, xyz.d3);
    }

    /** @return the x coordinate, in scene units */
    public double getX() {
        return x;
    }

    /** @return the y coordinate, in scene units */
    public double getY() {
        return y;
    }

    /** @return the z coordinate, in scene units */
    public double getZ() {
        return z;
    }

    /** @return the x coordinate, in scene units: the record-style spelling of {@link #getX()} some 2025–26 projects use */
    public double x() {
        return x;
    }

    /** @return the y coordinate, in scene units: the record-style spelling of {@link #getY()} */
    public double y() {
        return y;
    }

    /** @return the z coordinate, in scene units: the record-style spelling of {@link #getZ()} */
    public double z() {
        return z;
    }

    /**
     * @param other the point the vector starts from
     * @return the vector from {@code other} to this point
     * @throws IllegalArgumentException when the two points coincide (the zero vector)
     */
    public Vector subtract(Point other) {
        return new Vector(x - other.x, y - other.y, z - other.z);
    }

    /**
     * @param v the displacement
     * @return this point moved by {@code v}
     */
    public Point add(Vector v) {
        return new Point(x + v.x, y + v.y, z + v.z);
    }

    /**
     * The squared distance: what the closest-point searches compare, without a square root.
     *
     * @param other the other point
     * @return the squared Euclidean distance, in scene units squared
     */
    public double distanceSquared(Point other) {
        double dx = x - other.x;
        double dy = y - other.y;
        double dz = z - other.z;
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * @param other the other point
     * @return the Euclidean distance, in scene units
     */
    public double distance(Point other) {
        return Math.sqrt(distanceSquared(other));
    }

    @Override
    public boolean equals(Object obj) {
        if (this == obj) return true;
        return obj instanceof Point other
                && Util.isZero(x - other.x) && Util.isZero(y - other.y) && Util.isZero(z - other.z);
    }

    /** Constant: tolerant equality admits no finer hash that stays consistent with it. */
    @Override
    public int hashCode() {
        return 7;
    }

    @Override
    public String toString() {
        return "(" + x + "," + y + "," + z + ")";
    }
}
