package geometries;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The mutable record of a closest-hit query: reused by one thread for many rays so that the hot
 * path allocates nothing. {@link #getT()} doubles as the query's upper bound: reset it with
 * {@link #reset(double)} before each query.
 */
public final class Hit {
    double t = Double.POSITIVE_INFINITY;
    Geometry geometry;
    /** Which primitive of the geometry was hit (a mesh's triangle index), 0 for simple shapes. */
    int primitive;
    /** Barycentric coordinates of the hit inside a mesh triangle (for normal interpolation). */
    double u;
    double v;
    /** The BVH walk's node stack, owned by the thread that owns this record; grown on demand. */
    int[] stack = new int[64];
    /** The entry distance of each node on {@link #stack}, to skip it when a nearer hit was found. */
    double[] stackT = new double[64];

    /** Clears the record and sets the query's upper bound on the distance. */
    public Hit reset(double tMax) {
        t = tMax;
        geometry = null;
        primitive = 0;
        u = 0;
        v = 0;
        return this;
    }

    void set(double t, Geometry geometry, int primitive, double u, double v) {
        this.t = t;
        this.geometry = geometry;
        this.primitive = primitive;
        this.u = u;
        this.v = v;
    }

    /** @return true when the last query found something */
    public boolean found() {
        return geometry != null;
    }

    /** @return the hit distance along the (unit) ray direction, or the bound when nothing was hit */
    public double getT() {
        return t;
    }

    /** @return the geometry hit, or null */
    public Geometry getGeometry() {
        return geometry;
    }

    /** @return the hit point on {@code ray} (the ray the query was made with) */
    public Point point(Ray ray) {
        return ray.getPoint(t);
    }

    /** @return the unit surface normal at {@code point}, the hit point of this record */
    public Vector normal(Point point) {
        return geometry.normalAt(point, this);
    }
}
