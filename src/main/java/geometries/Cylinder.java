package geometries;

import primitives.Checks;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * A finite cylinder with both caps: the tube's shell between the axis head (the bottom cap's
 * centre) and {@code height} along the axis direction. A ray through the rim hits the cap. The
 * intersection is the tube's, cut at the height; a closest hit records which surface
 * it is on, so its normal never depends on tolerances.
 */
public class Cylinder extends Tube {
    private final double height;

    /**
     * A finite cylinder with both caps: the tube around {@code axis} from its head to
     * {@code height} along its direction. Some cohorts write (height, axis, radius): those are
     * the same types in the same places, so such a call builds this cylinder, radius first.
     *
     * @param radius the radius, in scene units, positive and finite
     * @param axis   the axis: its head is the centre of the bottom cap, its direction points to the top
     * @param height the distance between the caps, in scene units, positive and finite
     * @throws IllegalArgumentException when the radius or height is not a positive finite number
     */
    public Cylinder(double radius, Ray axis, double height) {
        super(radius, axis);
        this.height = Checks.requirePositive(height, "cylinder height");
    }

    /**
     * {@link #Cylinder(double, Ray, double)} with the axis first, as several cohorts write it.
     *
     * @param axis   the axis: its head is the centre of the bottom cap, its direction points to the top
     * @param radius the radius, in scene units, positive and finite
     * @param height the distance between the caps, in scene units, positive and finite
     * @throws IllegalArgumentException when the radius or height is not a positive finite number, naming it
     */
    public Cylinder(Ray axis, double radius, double height) {
        this(radius, axis, height);
    }

    /**
     * {@link #Cylinder(double, Ray, double)} in the order (height, radius, axis) some cohorts use.
     *
     * @param height the distance between the caps, in scene units, positive and finite
     * @param radius the radius, in scene units, positive and finite
     * @param axis   the axis: its head is the centre of the bottom cap, its direction points to the top
     * @throws IllegalArgumentException when the radius or height is not a positive finite number, naming it
     */
    public Cylinder(double height, double radius, Ray axis) {
        this(radius, axis, height);
    }

    /** @return the distance between the caps, in scene units */
    public double getHeight() {
        return height;
    }

    /**
     * Outward normal: −axis on the bottom cap, +axis on the top cap, radial on the shell. The point
     * is given without the surface it was found on, so the nearest surface decides: its distance
     * to the cap planes (|s| and |s − height| along the axis) against its distance to the shell
     * (|ρ − r|, ρ its distance from the axis). An absolute tolerance on s would not do: far from
     * the origin the rounding of a cap point's s exceeds any fixed tolerance. Near a rim both
     * answers are right; at a cap centre only the cap's exists.
     */
    @Override
    public Vector getNormal(Point point) {
        double s = axial(point);
        double qx = point.getX() - (px + vx * s), qy = point.getY() - (py + vy * s), qz = point.getZ() - (pz + vz * s);
        double toShell = Math.abs(Math.sqrt(qx * qx + qy * qy + qz * qz) - radius);
        double toBottom = Math.abs(s), toTop = Math.abs(s - height);
        if (toShell < Math.min(toBottom, toTop)) return radialNormal(point);
        return toBottom <= toTop ? axis.getDirection().negate() : axis.getDirection();
    }

    @Override
    double height() {
        return height;
    }

    @Override
    BoundingBox getBoundingBox() {
        double ex = radius * Math.sqrt(Math.max(0, 1 - vx * vx));
        double ey = radius * Math.sqrt(Math.max(0, 1 - vy * vy));
        double ez = radius * Math.sqrt(Math.max(0, 1 - vz * vz));
        double tx = px + vx * height, ty = py + vy * height, tz = pz + vz * height;
        return new BoundingBox(Math.min(px, tx) - ex, Math.min(py, ty) - ey, Math.min(pz, tz) - ez,
                Math.max(px, tx) + ex, Math.max(py, ty) + ey, Math.max(pz, tz) + ez);
    }
}
