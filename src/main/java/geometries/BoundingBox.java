package geometries;

/**
 * An immutable axis-aligned box, {@code min ≤ max} on each axis (a flat box is allowed).
 */
public final class BoundingBox {
    final double minX, minY, minZ, maxX, maxY, maxZ;

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

    /** @return the smallest box enclosing both; each axis taken separately */
    public BoundingBox union(BoundingBox o) {
        return new BoundingBox(Math.min(minX, o.minX), Math.min(minY, o.minY), Math.min(minZ, o.minZ),
                Math.max(maxX, o.maxX), Math.max(maxY, o.maxY), Math.max(maxZ, o.maxZ));
    }

    public double getMinX() { return minX; }
    public double getMinY() { return minY; }
    public double getMinZ() { return minZ; }
    public double getMaxX() { return maxX; }
    public double getMaxY() { return maxY; }
    public double getMaxZ() { return maxZ; }

    /** Half the surface area (the SAH cost only needs ratios). */
    double halfArea() {
        double dx = maxX - minX, dy = maxY - minY, dz = maxZ - minZ;
        return dx * dy + dy * dz + dz * dx;
    }

    /**
     * The slab test. Works for axis-parallel rays (1/0 = ±∞; a 0·∞ NaN is ignored by the min/max
     * order used) and rays starting inside.
     *
     * @return true when the ray segment [0, tMax] touches the box
     */
    public boolean intersects(double ox, double oy, double oz, double invDx, double invDy, double invDz, double tMax) {
        double t0 = 0, t1 = tMax;
        double a = (minX - ox) * invDx, b = (maxX - ox) * invDx;
        if (a > b) { double s = a; a = b; b = s; }
        // Comparisons written so that NaN (origin on a slab plane of a parallel ray) keeps the interval.
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (minY - oy) * invDy;
        b = (maxY - oy) * invDy;
        if (a > b) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (minZ - oz) * invDz;
        b = (maxZ - oz) * invDz;
        if (a > b) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        return t0 <= t1;
    }

    @Override
    public String toString() {
        return "Box[(" + minX + "," + minY + "," + minZ + ")..(" + maxX + "," + maxY + "," + maxZ + ")]";
    }
}
