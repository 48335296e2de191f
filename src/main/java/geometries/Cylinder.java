package geometries;

import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * A finite cylinder with both caps: the tube's shell between the axis head (the bottom cap's
 * centre) and {@code height} along the axis direction. A ray through the rim hits the cap.
 */
public class Cylinder extends Tube {
    private final double height;

    /** @throws IllegalArgumentException when the radius or height is not a positive finite number */
    public Cylinder(double radius, Ray axis, double height) {
        super(radius, axis);
        this.height = Util.requirePositive(height, "cylinder height");
    }

    public double getHeight() {
        return height;
    }

    /** Outward normal: −axis on the bottom cap, +axis on the top cap, radial on the shell. */
    @Override
    public Vector getNormal(Point point) {
        double s = axial(point);
        Vector v = axis.getDirection();
        if (Util.isZero(s)) return v.scale(-1);
        if (Util.isZero(s - height)) return v;
        return super.getNormal(point);
    }

    @Override
    double keepShell(Ray ray, double t) {
        if (Double.isNaN(t)) return t;
        double s = axialAt(ray, t);
        return Util.alignZero(s) > 0 && Util.alignZero(s - height) < 0 ? t : Double.NaN;
    }

    /** The axial coordinate of the ray point at distance t. */
    private double axialAt(Ray ray, double t) {
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        return (h.getX() + d.getX() * t - px) * vx + (h.getY() + d.getY() * t - py) * vy + (h.getZ() + d.getZ() * t - pz) * vz;
    }

    @Override
    double cap(Ray ray, boolean top) {
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        double dv = Util.alignZero(d.getX() * vx + d.getY() * vy + d.getZ() * vz);
        if (dv == 0) return Double.NaN;
        double hs = axial(h);
        double t = ((top ? height : 0) - hs) / dv;
        // Radial distance of the hit from the axis, squared; the rim (= r) belongs to the cap.
        double qx = h.getX() + d.getX() * t - px, qy = h.getY() + d.getY() * t - py, qz = h.getZ() + d.getZ() * t - pz;
        double s = qx * vx + qy * vy + qz * vz;
        qx -= s * vx;
        qy -= s * vy;
        qz -= s * vz;
        return Util.alignZero(qx * qx + qy * qy + qz * qz - radius * radius) <= 0 ? t : Double.NaN;
    }

    @Override
    public BoundingBox getBoundingBox() {
        double ex = radius * Math.sqrt(Math.max(0, 1 - vx * vx));
        double ey = radius * Math.sqrt(Math.max(0, 1 - vy * vy));
        double ez = radius * Math.sqrt(Math.max(0, 1 - vz * vz));
        double tx = px + vx * height, ty = py + vy * height, tz = pz + vz * height;
        return new BoundingBox(Math.min(px, tx) - ex, Math.min(py, ty) - ey, Math.min(pz, tz) - ez,
                Math.max(px, tx) + ex, Math.max(py, ty) + ey, Math.max(pz, tz) + ez);
    }
}
