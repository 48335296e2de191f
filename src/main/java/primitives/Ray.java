package primitives;

import java.util.List;
import java.util.Objects;

import geometries.Intersectable.GeoPoint;
import geometries.Intersectable.Intersection;

/**
 * An immutable half-line: a head point and a unit direction. Points on it are
 * {@code head + t·direction} for {@code t ≥ 0}, so {@code t} is a distance.
 */
public final class Ray {
    /**
     * How far (in scene units) a secondary ray's head is pushed off its surface along the normal,
     * so that it does not hit the surface it leaves (the course's value).
     */
    public static final double DELTA = 0.1;

    private final Point head;
    private final Vector direction;

    /**
     * @param head where the ray starts ({@code t = 0})
     * @param direction any non-zero vector; it is normalized, so {@code t} measures distance
     */
    public Ray(Point head, Vector direction) {
        this.head = Objects.requireNonNull(head, "ray head");
        this.direction = Objects.requireNonNull(direction, "ray direction").normalize();
    }

    /**
     * A secondary ray leaving a surface: the head is moved by {@link #DELTA} along {@code normal},
     * to the side {@code direction} goes (against the normal when the direction enters the surface).
     * A direction tangent to the surface keeps the head in place.
     *
     * @param head the point on the surface
     * @param direction where the ray goes; it is normalized
     * @param normal the surface normal at {@code head}, unit length (either orientation)
     */
    public Ray(Point head, Vector direction, Vector normal) {
        Objects.requireNonNull(head, "ray head");
        Objects.requireNonNull(normal, "surface normal");
        this.direction = Objects.requireNonNull(direction, "ray direction").normalize();
        Vector d = this.direction;
        double delta = headOffset(normal.x, normal.y, normal.z, d.x, d.y, d.z);
        this.head = delta == 0 ? head
                : new Point(head.x + normal.x * delta, head.y + normal.y * delta, head.z + normal.z * delta);
    }

    /**
     * How far a secondary ray's head moves along the surface normal (see
     * {@link #Ray(Point, Vector, Vector)}): the one rule, shared by that constructor and by tracers
     * that keep rays in doubles, which move each head coordinate {@code h} to
     * {@code h + normal·offset} when the offset is not 0.
     *
     * @param nx the unit surface normal's x component
     * @param ny its y component
     * @param nz its z component
     * @param dx the ray's unit direction's x component (already normalized)
     * @param dy its y component
     * @param dz its z component
     * @return {@link #DELTA} when the direction leaves on the normal's side, −{@code DELTA} when it
     *         enters the surface, 0 when it is tangent (within the zero tolerance)
     */
    static double headOffset(double nx, double ny, double nz, double dx, double dy, double dz) {
        double nd = nx * dx + ny * dy + nz * dz;
        // alignZero(nd) == 0 ? 0 : alignZero(nd) > 0 ? DELTA : -DELTA, NaN (-DELTA) included, as
        // two comparisons with the tolerance: the quick compiler (C1) built the two comparisons
        // with 0 as one three-way result tested twice (BENCHMARKS.md, issue 50, eleventh session)
        return nd >= Util.ACCURACY ? DELTA : nd > -Util.ACCURACY ? 0 : -DELTA;
    }

    /** @return the point the ray starts from ({@code t = 0}) */
    public Point getHead() {
        return head;
    }

    /** @return the unit direction */
    public Vector getDirection() {
        return direction;
    }

    /** @return the head: the 2025–26 spelling of {@link #getHead()} */
    public Point origin() {
        return head;
    }

    /** @return the unit direction: the 2025–26 spelling of {@link #getDirection()} */
    public Vector direction() {
        return direction;
    }

    /**
     * @param t the distance along the ray, in scene units
     * @return {@code head + t·direction}; {@code t = 0} (within tolerance) gives the head itself
     */
    public Point getPoint(double t) {
        if (Util.isZero(t)) return head;
        return new Point(head.x + direction.x * t, head.y + direction.y * t, head.z + direction.z * t);
    }

    /**
     * @param points candidate points, for example a ray's intersections; may be null
     * @return the point of {@code points} closest to the head, or null for a null or empty list
     */
    public Point findClosestPoint(List<Point> points) {
        if (points == null || points.isEmpty()) return null;
        Point closest = null;
        double best = Double.POSITIVE_INFINITY;
        for (Point p : points) {
            double d = p.distanceSquared(head);
            if (d < best) {
                best = d;
                closest = p;
            }
        }
        return closest;
    }

    /**
     * @param points hit records, typically a geometry's {@code findGeoIntersections}
     * @return the intersection closest to the head, or null for a null or empty list
     */
    public GeoPoint findClosestGeoPoint(List<GeoPoint> points) {
        return closest(points);
    }

    /**
     * The 2024–25 and 2025–26 spelling of {@link #findClosestGeoPoint}.
     *
     * @param intersections hit records, typically a geometry's {@code calculateIntersections}
     * @return the intersection closest to the head, or null for a null or empty list
     */
    public Intersection findClosestIntersection(List<Intersection> intersections) {
        return closest(intersections);
    }

    private <T extends GeoPoint> T closest(List<T> points) {
        if (points == null || points.isEmpty()) return null;
        T closest = null;
        double best = Double.POSITIVE_INFINITY;
        for (T gp : points) {
            double d = gp.point.distanceSquared(head);
            if (d < best) {
                best = d;
                closest = gp;
            }
        }
        return closest;
    }

    @Override
    public boolean equals(Object obj) {
        if (this == obj) return true;
        return obj instanceof Ray other && head.equals(other.head) && direction.equals(other.direction);
    }

    @Override
    public int hashCode() {
        return 11;
    }

    @Override
    public String toString() {
        return "Ray{" + head + " " + direction + "}";
    }
}
