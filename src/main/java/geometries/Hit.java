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
    /**
     * Which part of the geometry was hit, for {@link Geometry#normalAt}: a mesh's triangle index,
     * a tube's or cylinder's surface; 0 for simple shapes.
     */
    int primitive;
    /** The BVH walk's node stack, owned by the thread that owns this record; grown on demand. */
    int[] stack = new int[64];
    /** The entry distance of each node on {@link #stack}, to skip it when a nearer hit was found. */
    double[] stackT = new double[64];

    /**
     * Clears the record and sets the query's upper bound on the distance.
     *
     * @param tMax hits farther than this along the ray are ignored; +∞ for no bound
     * @return this record, for a query call in the same expression
     */
    public Hit reset(double tMax) {
        t = tMax;
        geometry = null;
        primitive = 0;
        return this;
    }

    void set(double t, Geometry geometry, int primitive) {
        this.t = t;
        this.geometry = geometry;
        this.primitive = primitive;
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

    /**
     * @param ray the ray the query was made with (the record keeps only its distance)
     * @return the hit point on {@code ray}
     */
    public Point point(Ray ray) {
        return ray.getPoint(t);
    }

    /**
     * @param point the hit point of this record, from {@link #point(Ray)}
     * @return the unit surface normal at {@code point}; a mesh's smooth normal when it has vertex normals
     */
    public Vector normal(Point point) {
        return geometry.normalAt(point, this);
    }
}
