package geometries;

/**
 * An immutable axis-aligned box, {@code min ≤ max} on each axis (a flat box is allowed).
 *
 * @hidden internal: the bounding volume hierarchy's box, public for the renderer's packages
 */
public final class BoundingBox {
    final double minX, minY, minZ, maxX, maxY, maxZ;

    /**
     * @param minX the smallest x, in scene units (−∞ allowed for an unbounded side)
     * @param minY the smallest y
     * @param minZ the smallest z
     * @param maxX the largest x, ≥ {@code minX}
     * @param maxY the largest y, ≥ {@code minY}
     * @param maxZ the largest z, ≥ {@code minZ}
     * @throws IllegalArgumentException when min &gt; max on some axis or a bound is NaN, naming
     *                                  both corners
     */
    public BoundingBox(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
        if (!(minX <= maxX) || !(minY <= maxY) || !(minZ <= maxZ))
            throw new IllegalArgumentException("bounding box needs min <= max on every axis, got min ("
                    + minX + "," + minY + "," + minZ + ") max (" + maxX + "," + maxY + "," + maxZ + ")");
        this.minX = minX;
        this.minY = minY;
        this.minZ = minZ;
        this.maxX = maxX;
        this.maxY = maxY;
        this.maxZ = maxZ;
    }

    /**
     * @param o the other box
     * @return the smallest box enclosing both; each axis taken separately
     */
    public BoundingBox union(BoundingBox o) {
        return new BoundingBox(Math.min(minX, o.minX), Math.min(minY, o.minY), Math.min(minZ, o.minZ),
                Math.max(maxX, o.maxX), Math.max(maxY, o.maxY), Math.max(maxZ, o.maxZ));
    }

    /** @return the smallest x of the box, in scene units */
    public double getMinX() { return minX; }
    /** @return the smallest y of the box, in scene units */
    public double getMinY() { return minY; }
    /** @return the smallest z of the box, in scene units */
    public double getMinZ() { return minZ; }
    /** @return the largest x of the box, in scene units */
    public double getMaxX() { return maxX; }
    /** @return the largest y of the box, in scene units */
    public double getMaxY() { return maxY; }
    /** @return the largest z of the box, in scene units */
    public double getMaxZ() { return maxZ; }

    /**
     * This box widened on every side by 1e-9 of its largest coordinate magnitude (plus 1e-9), so
     * that rounding in a slab test never culls a hit that the primitive's own test accepts (flat
     * boxes of axis-aligned triangles included). The one padding of the BVH's primitive boxes and
     * of a mesh's early-out box: they must agree, or the two paths would disagree at the edges.
     */
    BoundingBox padded() {
        double eps = padding();
        return new BoundingBox(minX - eps, minY - eps, minZ - eps, maxX + eps, maxY + eps, maxZ + eps);
    }

    /** The margin {@link #padded()} adds on every side, in scene units. */
    double padding() {
        return padding(minX, minY, minZ, maxX, maxY, maxZ);
    }

    /** {@link #padding()} of the box (minX, minY, minZ)–(maxX, maxY, maxZ), for builders that keep boxes as doubles. */
    static double padding(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
        return 1e-9 * (1 + Math.max(Math.max(Math.abs(minX), Math.abs(maxX)),
                Math.max(Math.max(Math.abs(minY), Math.abs(maxY)), Math.max(Math.abs(minZ), Math.abs(maxZ)))));
    }

    /**
     * The inverse of a direction component for the slab test: 1/d, except that a negative zero
     * (which {@code scale(-1)} of an axis-parallel vector produces) or a negative component too
     * small to invert gives +∞ rather than −∞. The slab test relies on it; see there.
     */
    static double inverse(double d) {
        double inv = 1 / d;
        return inv == Double.NEGATIVE_INFINITY ? Double.POSITIVE_INFINITY : inv;
    }

    /**
     * The slab test. Works for axis-parallel rays and rays starting inside. For an axis the ray
     * is parallel to, the inverse must be +∞ (use {@link #inverse}; a −∞ is turned into +∞
     * here): then a = (min − o)·∞ ≤ b = (max − o)·∞, and when the origin lies on a slab plane the
     * 0·∞ = NaN lands on the side that the kernel ({@link #entry}) ignores. With −∞ the NaN
     * would land in a while b = −∞ empties the interval: a ray grazing a face would miss.
     *
     * The ray is passed as doubles, precomputed once per ray, because the BVH walk tests many
     * boxes against the same ray (with the same kernel, on its float nodes).
     *
     * @param ox    the ray head's x
     * @param oy    the ray head's y
     * @param oz    the ray head's z
     * @param invDx 1 / the direction's x component (+∞ for 0)
     * @param invDy 1 / the direction's y component (+∞ for 0)
     * @param invDz 1 / the direction's z component (+∞ for 0)
     * @param tMax  the far end of the segment, in distance along the unit direction
     * @return true when the ray segment [0, tMax] touches the box
     */
    public boolean intersects(double ox, double oy, double oz, double invDx, double invDy, double invDz, double tMax) {
        if (invDx == Double.NEGATIVE_INFINITY) invDx = Double.POSITIVE_INFINITY; // 1/-0.0 from a caller
        if (invDy == Double.NEGATIVE_INFINITY) invDy = Double.POSITIVE_INFINITY;
        if (invDz == Double.NEGATIVE_INFINITY) invDz = Double.POSITIVE_INFINITY;
        return entry(minX, minY, minZ, maxX, maxY, maxZ, ox, oy, oz, invDx, invDy, invDz, tMax) != Double.POSITIVE_INFINITY;
    }

    /**
     * The slab test's kernel, for this class and a tree's node test ({@code Bvh}), one axis at a
     * time: the segment [t0, t1] of the ray that lies in every slab seen so far starts as
     * [0, tMax] and is narrowed by the slab [min, max] of each axis. The ray enters that slab at
     * the smaller of a = (min − o)·inv and b = (max − o)·inv and leaves it at the larger. Each
     * comparison is written so that a NaN (0·∞: the origin on a slab plane of a ray parallel to
     * it, with inv = +∞ as {@link #inverse} gives it) leaves the bound as it was: then the ray
     * grazes the face and still counts as inside.
     *
     * <p>One method with the box and the ray as thirteen doubles, not an array or an object, and
     * the three axes written out rather than through a per-axis helper: a walk calls it for every
     * box it tests, and with the quick compiler only (the launcher's and a test JVM's
     * {@code -XX:TieredStopAtLevel=1}), which inlines methods of up to 35 bytes, each call left in
     * the walk costs; six calls of per-axis halves cost the one-sample render of the 137-primitive
     * scene several per cent (BENCHMARKS.md, "One call per box"). The full compiler inlines it
     * either way.
     *
     * <p>Each axis orders its two distances with one comparison and a swap. The quick compiler
     * turns every conditional expression into a compare-and-branch of its own, and for
     * {@code near = a > b ? b : a, far = a > b ? a : b} it also built the three-way result of the
     * shared comparison, never used: 16 comparisons and 42 jumps per box, against 10 and 27 now.
     * The full compiler makes the same machine code of both forms. The result is the same double,
     * NaN cases included (BENCHMARKS.md, issue 50, eleventh session).
     *
     * @return the distance at which the ray segment [0, tMax] enters the box [x0, x1] × [y0, y1]
     *         × [z0, z1] (0 when its head is inside), or +∞ when it misses it
     */
    static double entry(double x0, double y0, double z0, double x1, double y1, double z1, double ox, double oy,
                        double oz, double ix, double iy, double iz, double tMax) {
        double t0 = 0, t1 = tMax;
        double a = (x0 - ox) * ix, b = (x1 - ox) * ix;
        if (a > b) { // the nearer plane first: one test, where a > b ? b : a and a > b ? a : b made two
            double swap = a;
            a = b;
            b = swap;
        }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (y0 - oy) * iy;
        b = (y1 - oy) * iy;
        if (a > b) {
            double swap = a;
            a = b;
            b = swap;
        }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (z0 - oz) * iz;
        b = (z1 - oz) * iz;
        if (a > b) {
            double swap = a;
            a = b;
            b = swap;
        }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    @Override
    public String toString() {
        return "Box[(" + minX + "," + minY + "," + minZ + ")..(" + maxX + "," + maxY + "," + maxZ + ")]";
    }
}
