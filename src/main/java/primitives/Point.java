package primitives;

/**
 * An immutable point in 3D space. Coordinates are stored as three doubles (no wrapper object)
 * because every intersection kernel reads them.
 */
public class Point {
    final double x;
    final double y;
    final double z;

    /** The origin. */
    public static final Point ZERO = new Point(0, 0, 0);

    public Point(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    /** A point from a {@link Double3} (course compatibility). */
    public Point(Double3 xyz) {
        this(xyz.d1, xyz.d2, xyz.d3);
    }

    public double getX() {
        return x;
    }

    public double getY() {
        return y;
    }

    public double getZ() {
        return z;
    }

    /**
     * @return the vector from {@code other} to this point
     * @throws IllegalArgumentException when the two points coincide (the zero vector)
     */
    public Vector subtract(Point other) {
        return new Vector(x - other.x, y - other.y, z - other.z);
    }

    /** @return this point moved by {@code v} */
    public Point add(Vector v) {
        return new Point(x + v.x, y + v.y, z + v.z);
    }

    public double distanceSquared(Point other) {
        double dx = x - other.x;
        double dy = y - other.y;
        double dz = z - other.z;
        return dx * dx + dy * dy + dz * dz;
    }

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
