package geometries;

/**
 * The BVH build's boxes, kept as six doubles in flat arrays rather than as objects (a build of
 * two million primitives would otherwise make and keep millions of them): the low corner at
 * {@link #LOW} (x, y, z), the high corner at {@link #HIGH}. The builder's bounds of a range,
 * {@link #BOUNDS} doubles, are two such boxes: the primitives' box at {@link #BOX} and their
 * centroids' box at {@link #CENTROIDS}. pbrt names the same pair {@code bounds} and
 * {@code centroidBounds}; here the names are offsets, one set for every array of the build.
 *
 * <p>An empty box has its low corner at +∞ and its high corner at −∞, so that any point grows
 * it. Unions use {@link Math#min}/{@link Math#max}, which do not branch on the data (whether a
 * bound grows mispredicts often); they differ from compare-and-branch only for NaN (no bound is
 * NaN) and by preferring −0.0 to +0.0, the same choice in every caller.
 */
final class BuildBoxes {
    /** Offset of the low corner (x, y, z) within a box. */
    static final int LOW = 0;
    /** Offset of the high corner (x, y, z) within a box. */
    static final int HIGH = 3;
    /** Doubles per box. */
    static final int BOX_SIZE = 6;
    /** Offset, within a range's bounds, of the box of its primitives. */
    static final int BOX = 0;
    /** Offset, within a range's bounds, of the box of its primitives' centroids. */
    static final int CENTROIDS = BOX_SIZE;
    /** Doubles per range's bounds: its box, then its centroids' box. */
    static final int BOUNDS = 2 * BOX_SIZE;

    private BuildBoxes() {
    }

    /** Makes the box at {@code at} empty. */
    static void empty(double[] b, int at) {
        for (int a = 0; a < 3; ++a) {
            b[at + LOW + a] = Double.POSITIVE_INFINITY;
            b[at + HIGH + a] = Double.NEGATIVE_INFINITY;
        }
    }

    /** Makes the bounds (box and centroids' box) at {@code at} empty. */
    static void emptyBounds(double[] b, int at) {
        empty(b, at + BOX);
        empty(b, at + CENTROIDS);
    }

    /** Sets the box at {@code at} to the corners (x0, y0, z0) and (x1, y1, z1). */
    static void set(double[] b, int at, double x0, double y0, double z0, double x1, double y1, double z1) {
        b[at + LOW] = x0;
        b[at + LOW + 1] = y0;
        b[at + LOW + 2] = z0;
        b[at + HIGH] = x1;
        b[at + HIGH + 1] = y1;
        b[at + HIGH + 2] = z1;
    }

    /** Grows the box at {@code at} of {@code b} to hold the box at {@code from} of {@code src}. */
    static void grow(double[] b, int at, double[] src, int from) {
        for (int a = 0; a < 3; ++a) {
            b[at + LOW + a] = Math.min(src[from + LOW + a], b[at + LOW + a]);
            b[at + HIGH + a] = Math.max(src[from + HIGH + a], b[at + HIGH + a]);
        }
    }

    /** Grows the box at {@code at} of {@code b} to hold the point (three doubles) at {@code from} of {@code src}. */
    static void growToPoint(double[] b, int at, double[] src, int from) {
        for (int a = 0; a < 3; ++a) {
            b[at + LOW + a] = Math.min(src[from + a], b[at + LOW + a]);
            b[at + HIGH + a] = Math.max(src[from + a], b[at + HIGH + a]);
        }
    }

    /** Grows the bounds at {@code at} of {@code b} to hold those at {@code from} of {@code src}. */
    static void growBounds(double[] b, int at, double[] src, int from) {
        grow(b, at + BOX, src, from + BOX);
        grow(b, at + CENTROIDS, src, from + CENTROIDS);
    }

    /** @return the box's extent along {@code axis} (0 x, 1 y, 2 z) */
    static double extent(double[] b, int at, int axis) {
        return b[at + HIGH + axis] - b[at + LOW + axis];
    }

    /** @return the {@link #halfArea(double, double, double) half area} of the box at {@code at} */
    static double halfArea(double[] b, int at) {
        return halfArea(extent(b, at, 0), extent(b, at, 1), extent(b, at, 2));
    }

    /**
     * The half area of a box of extents dx, dy, dz (the SAH only needs ratios of areas): the one
     * formula of every SAH cost, a node's own area included.
     */
    static double halfArea(double dx, double dy, double dz) {
        return dx * dy + dy * dz + dz * dx;
    }
}
