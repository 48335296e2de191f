package primitives;

/**
 * The arithmetic of {@link Vector} and {@link Ray} on raw components, for the renderer and the
 * shapes, which keep their vectors in doubles (no object per ray or shaded point). Static, and
 * apart from the course classes, so that a student completing {@code Vector.} sees the course's
 * methods only; each method is the one implementation its course method also runs, so both forms
 * give the same bits, and one call, which the JIT inlines.
 *
 * @hidden internal: the engine's vector arithmetic in doubles; a scene test uses Vector and Ray
 */
public final class Kernels {
    private Kernels() {
    }

    /**
     * The arithmetic of {@link Vector#normalize()} on raw components.
     *
     * @param x   the x component of a non-zero, finite vector (not checked)
     * @param y   the y component
     * @param z   the z component
     * @param out receives the unit vector's components in {@code out[0..2]}
     * @return false when (x, y, z) already has unit length within the zero tolerance: {@code out}
     *         then holds it unchanged
     */
    public static boolean normalize(double x, double y, double z, double[] out) {
        return Vector.normalize(x, y, z, out);
    }

    /**
     * The arithmetic of {@link Vector#crossProduct(Vector)} on raw components (same checks, same bits).
     *
     * @param ax  the left operand's x component (a non-zero, finite vector; not checked)
     * @param ay  the left operand's y component
     * @param az  the left operand's z component
     * @param bx  the right operand's x component (a non-zero, finite vector; not checked)
     * @param by  the right operand's y component
     * @param bz  the right operand's z component
     * @param out receives a × b in {@code out[0..2]}
     * @throws IllegalArgumentException when the vectors are parallel, or the product is beyond the
     *                                  range of a double
     */
    public static void crossProduct(double ax, double ay, double az, double bx, double by, double bz, double[] out) {
        Vector.crossProduct(ax, ay, az, bx, by, bz, out);
    }

    /**
     * How far a secondary ray's head moves along the surface normal, as
     * {@link Ray#Ray(Point, Vector, Vector)} moves it: a tracer that keeps rays in doubles moves each
     * head coordinate {@code h} to {@code h + normal·offset} when the offset is not 0.
     *
     * @param nx the unit surface normal's x component
     * @param ny its y component
     * @param nz its z component
     * @param dx the ray's unit direction's x component (already normalized)
     * @param dy its y component
     * @param dz its z component
     * @return {@link Ray#DELTA} when the direction leaves on the normal's side, −{@code DELTA} when
     *         it enters the surface, 0 when it is tangent (within the zero tolerance)
     */
    public static double headOffset(double nx, double ny, double nz, double dx, double dy, double dz) {
        return Ray.headOffset(nx, ny, nz, dx, dy, dz);
    }
}
