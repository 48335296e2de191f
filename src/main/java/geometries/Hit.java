package geometries;

import primitives.Kernels;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * The mutable record of a query: the ray asked about, kept as six doubles, and what the query
 * found. Reused by one thread for many rays so that the hot path allocates nothing; never
 * shared between threads. {@link #getT()} doubles as a closest-hit query's upper bound: reset
 * it with {@link #reset(double)} before each query.
 *
 * <p>The ray is set with {@link #setRay(double, double, double, double, double, double)} or
 * {@link #setRay(double, double, double, double, double, double, double, double, double)}, the
 * doubles of {@code new Ray(head, direction)} and {@code new Ray(head, direction, normal)} (the
 * same arithmetic, so the same bits); {@link LeanQueries#closestHit(Intersectable, Hit)} and
 * {@link LeanQueries#visitHits(Intersectable, Hit, double, HitVisitor)} then query it without any
 * {@link Ray} object. Those two setters are protected: the renderer reaches them through its
 * own subclass ({@code renderer.RayHit}), so that code holding a {@code Hit} (a shape's query,
 * a student's code completion) reads a record and never sees how a ray is put into one. Every
 * other method is final: the subclass only adds the setters' names.
 *
 * @hidden internal: the renderer's hit record, public for package renderer; a scene test uses GeoPoint
 */
public class Hit {
    private static final int[] NO_STACK = new int[0];
    private static final double[] NO_STACK_T = new double[0];

    double t = Double.POSITIVE_INFINITY;
    Geometry geometry;
    /**
     * Which part of the geometry was hit, for {@code Geometry.normalAt}: a mesh's triangle index,
     * a tube's or cylinder's surface; 0 for simple shapes.
     */
    int primitive;
    /** The query ray's head. */
    double ox, oy, oz;
    /** The query ray's unit direction. */
    double dx, dy, dz;
    /** Scratch for the normalization of a direction. */
    private final double[] unit = new double[3];
    /** The hit point, set by {@link #computeSurface()}. */
    double px, py, pz;
    /** The unit surface normal at the hit point, set by {@link #computeSurface()}. */
    final double[] normal = new double[3];
    /**
     * The BVH walk's node stack, owned by the thread that owns this record; grown by the first
     * walk that needs it (records used only for shadow queries never need one).
     */
    int[] stack = NO_STACK;
    /** The entry distance of each node on {@link #stack}, to skip it when a nearer hit was found. */
    double[] stackT = NO_STACK_T;
    /**
     * Whether a BVH walk is in progress on this record: a shape met by one walk may answer by
     * walking a tree of its own with the same record (a user's group that overrides
     * {@code closestHit(Hit)}), and that inner walk must not overwrite the outer one's
     * {@link #stack}.
     */
    boolean walking;
    /**
     * The leaf-order index, in the tree being walked, of the primitive {@link #geometry} is; −1
     * when the hit was found before the walk (it then wins every tie): what a tree's tie rule
     * compares ({@code Bvh.closestHit}).
     */
    int order = -1;
    /**
     * The boxes and the primitives a tree's walk tested for this record, counted only in a JVM
     * run with {@code -Draytracer.walkCounts=true} ({@link Bvh#COUNTING}): for the benchmark's
     * counts ({@code geometries.WalkCounts}). Otherwise never written.
     */
    long boxTests, primitiveTests;
    /** The vector walk's scratch: the entry distances of a wide node's children, or a lane leaf's hit distances. */
    final double[] lanes = new double[WideNodes.MAX_WIDTH];

    /**
     * Clears the record and sets the query's upper bound on the distance; the ray stays.
     *
     * @param tMax hits farther than this along the ray are ignored; +∞ for no bound
     * @return this record, for a query call in the same expression
     */
    public final Hit reset(double tMax) {
        t = tMax;
        geometry = null;
        primitive = 0;
        order = -1;
        return this;
    }

    /**
     * Sets the query ray to the one {@code new Ray(new Point(ox, oy, oz), new Vector(dx, dy, dz))}
     * would be: the direction normalized by {@link Kernels#normalize(double, double, double, double[])}.
     *
     * @param ox the head's x coordinate
     * @param oy the head's y coordinate
     * @param oz the head's z coordinate
     * @param dx the direction's x component (any non-zero, finite vector; not checked)
     * @param dy the direction's y component
     * @param dz the direction's z component
     * @return this record
     */
    protected final Hit setRay(double ox, double oy, double oz, double dx, double dy, double dz) {
        Kernels.normalize(dx, dy, dz, unit);
        this.ox = ox;
        this.oy = oy;
        this.oz = oz;
        this.dx = unit[0];
        this.dy = unit[1];
        this.dz = unit[2];
        return this;
    }

    /**
     * Sets the query ray to the secondary ray {@code new Ray(p, direction, normal)} would be: the
     * direction normalized, the head moved off the surface by {@link Kernels#headOffset}.
     *
     * @param px the surface point's x coordinate
     * @param py the surface point's y coordinate
     * @param pz the surface point's z coordinate
     * @param dx the direction's x component (any non-zero, finite vector; not checked)
     * @param dy the direction's y component
     * @param dz the direction's z component
     * @param nx the unit surface normal's x component
     * @param ny the unit surface normal's y component
     * @param nz the unit surface normal's z component
     * @return this record
     */
    protected final Hit setRay(double px, double py, double pz, double dx, double dy, double dz, double nx,
                               double ny, double nz) {
        Kernels.normalize(dx, dy, dz, unit);
        double ux = unit[0], uy = unit[1], uz = unit[2];
        double delta = Kernels.headOffset(nx, ny, nz, ux, uy, uz);
        if (delta == 0) {
            ox = px;
            oy = py;
            oz = pz;
        } else {
            ox = px + nx * delta;
            oy = py + ny * delta;
            oz = pz + nz * delta;
        }
        this.dx = ux;
        this.dy = uy;
        this.dz = uz;
        return this;
    }

    /** Sets the query ray to {@code ray}'s head and (already unit) direction. */
    Hit setRay(Ray ray) {
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        ox = h.getX();
        oy = h.getY();
        oz = h.getZ();
        dx = d.getX();
        dy = d.getY();
        dz = d.getZ();
        return this;
    }

    /**
     * @return a new record holding only {@code ray}, for the object forms of the queries
     */
    static Hit of(Ray ray) {
        return new Hit().setRay(ray);
    }

    /**
     * The query ray as an object, for geometries that answer only the course's {@link Ray}-based
     * methods (users' own shapes): the only place the query path allocates a ray.
     */
    Ray ray() {
        return new Ray(new Point(ox, oy, oz), new Vector(dx, dy, dz));
    }

    void set(double t, Geometry geometry, int primitive) {
        this.t = t;
        this.geometry = geometry;
        this.primitive = primitive;
    }

    /** @return true when the last query found something */
    public final boolean found() {
        return geometry != null;
    }

    /** @return the hit distance along the (unit) ray direction, or the bound when nothing was hit */
    public final double getT() {
        return t;
    }

    /** @return the geometry hit, or null */
    public final Geometry getGeometry() {
        return geometry;
    }

    /** @return the x coordinate of the query ray's head */
    public final double headX() {
        return ox;
    }

    /** @return the y coordinate of the query ray's head */
    public final double headY() {
        return oy;
    }

    /** @return the z coordinate of the query ray's head */
    public final double headZ() {
        return oz;
    }

    /** @return the x component of the query ray's unit direction */
    public final double directionX() {
        return dx;
    }

    /** @return the y component of the query ray's unit direction */
    public final double directionY() {
        return dy;
    }

    /** @return the z component of the query ray's unit direction */
    public final double directionZ() {
        return dz;
    }

    /**
     * Computes the hit point on the query ray (the doubles {@code ray.getPoint(getT())} would
     * hold) and the unit surface normal there, for {@link #pointX()} … {@link #normalZ()}: the
     * shading inputs, without objects. Call it after a query that found something.
     *
     * @return this record
     */
    public final Hit computeSurface() {
        if (Util.isZero(t)) { // Ray.getPoint's rule: t ≈ 0 is the head itself
            px = ox;
            py = oy;
            pz = oz;
        } else {
            px = ox + dx * t;
            py = oy + dy * t;
            pz = oz + dz * t;
        }
        geometry.surfaceNormal(this);
        return this;
    }

    /** @return the x coordinate of the hit point, from {@link #computeSurface()} */
    public final double pointX() {
        return px;
    }

    /** @return the y coordinate of the hit point, from {@link #computeSurface()} */
    public final double pointY() {
        return py;
    }

    /** @return the z coordinate of the hit point, from {@link #computeSurface()} */
    public final double pointZ() {
        return pz;
    }

    /** @return the x component of the unit surface normal, from {@link #computeSurface()} */
    public final double normalX() {
        return normal[0];
    }

    /** @return the y component of the unit surface normal, from {@link #computeSurface()} */
    public final double normalY() {
        return normal[1];
    }

    /** @return the z component of the unit surface normal, from {@link #computeSurface()} */
    public final double normalZ() {
        return normal[2];
    }

    /**
     * @param ray the ray the query was made with (the record keeps only its distance)
     * @return the hit point on {@code ray}
     */
    public final Point point(Ray ray) {
        return ray.getPoint(t);
    }

    /**
     * @param point the hit point of this record, from {@link #point(Ray)}
     * @return the unit surface normal at {@code point}; a mesh's smooth normal when it has vertex normals
     */
    public final Vector normal(Point point) {
        px = point.getX();
        py = point.getY();
        pz = point.getZ();
        geometry.surfaceNormal(this);
        return new Vector(normal[0], normal[1], normal[2]);
    }
}
