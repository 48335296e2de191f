package geometries;

/**
 * An immutable axis-aligned box, {@code min ≤ max} on each axis (a flat box is allowed).
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
     * 0·∞ = NaN lands on the side that {@link #enter} and {@link #exit} ignore. With −∞ the NaN
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
        double t0 = enter(0, minX, maxX, ox, invDx), t1 = exit(tMax, minX, maxX, ox, invDx);
        t0 = enter(t0, minY, maxY, oy, invDy);
        t1 = exit(t1, minY, maxY, oy, invDy);
        t0 = enter(t0, minZ, maxZ, oz, invDz);
        t1 = exit(t1, minZ, maxZ, oz, invDz);
        return t0 <= t1;
    }

    /*
     * The slab test's kernel, one axis at a time: the segment [t0, t1] of the ray that lies in
     * every slab seen so far is narrowed by the slab [min, max] of one more axis. The ray enters
     * that slab at the smaller of a = (min − o)·inv and b = (max − o)·inv and leaves it at the
     * larger. Each comparison is written so that a NaN (0·∞: the origin on a slab plane of a ray
     * parallel to it, with inv = +∞ as inverse() gives it) leaves the bound as it was: then the
     * ray grazes the face and still counts as inside. The callers, this box's intersects and a
     * tree's node test (Bvh), narrow enter and exit axis by axis; the two share a, b and the
     * comparison a > b, which the compiler computes once.
     */

    /**
     * @param t0  the entry distance so far (0 at first: the segment starts at the ray head)
     * @param min the slab's lower bound on this axis
     * @param max the slab's upper bound on this axis
     * @param o   the ray head's coordinate on this axis
     * @param inv 1 / the direction's component on this axis, +∞ for 0 ({@link #inverse})
     * @return the later of {@code t0} and the distance at which the ray enters the slab
     */
    static double enter(double t0, double min, double max, double o, double inv) {
        double a = (min - o) * inv, b = (max - o) * inv;
        double near = a > b ? b : a;
        return near > t0 ? near : t0;
    }

    /**
     * @param t1  the exit distance so far (the segment's far end, tMax, at first)
     * @param min the slab's lower bound on this axis
     * @param max the slab's upper bound on this axis
     * @param o   the ray head's coordinate on this axis
     * @param inv 1 / the direction's component on this axis, +∞ for 0 ({@link #inverse})
     * @return the earlier of {@code t1} and the distance at which the ray leaves the slab
     */
    static double exit(double t1, double min, double max, double o, double inv) {
        double a = (min - o) * inv, b = (max - o) * inv;
        double far = a > b ? a : b;
        return far < t1 ? far : t1;
    }

    @Override
    public String toString() {
        return "Box[(" + minX + "," + minY + "," + minZ + ")..(" + maxX + "," + maxY + "," + maxZ + ")]";
    }
}
