package geometries;

import primitives.Ray;
import primitives.Vector;

/**
 * Haines and Greenberg's light buffer (1986) for one light of a render: the leaves of a scene's
 * tree sorted into cells by where a shadow ray toward that light can meet them. A point light's
 * cells are directions from the light: on each of the six faces of a cube around it, a
 * {@link #CELLS}² grid over the part of the face the scene covers. A directional light's are
 * columns along its direction: a {@link #CELLS}² grid over the scene seen from the light. A lit
 * point's shadow ray, most shadow rays of a scene, is then proved clear by the few leaves of its
 * cell, instead of a walk from the tree's root.
 *
 * <p>Exact: {@link #clear} answers true only when the tree's any-hit walk
 * ({@link Bvh#visitHits}) would give its visitor no hit. It runs the walk's own tests (the box
 * test, then the primitives' tests, as the walk does them) on every leaf the ray can reach, and
 * on the shapes without a box. Every other answer is false, and the caller walks the tree as
 * without the index: a cell with more than {@link #MOST_LEAVES} leaves or with a user's shape, a
 * ray that is not one of this light's shadow rays, a shape that crosses the ray. The index is
 * immutable; any number of render threads may ask it.
 *
 * @hidden internal: built per light by the renderer ({@link LeanQueries#shadowIndexFrom},
 *         {@link LeanQueries#shadowIndexAlong})
 */
public final class ShadowIndex {
    /** Cells per side of a face's grid. */
    static final int CELLS = 32;
    /**
     * The most leaves a cell holds; a fuller cell answers false. A clear ray's walk costs about six
     * box tests in the scenes measured, so a cell of more leaves would not be cheaper than it.
     */
    static final int MOST_LEAVES = 8;
    /**
     * How far a point light's shadow ray may pass from the light and stay the index's: its head is
     * moved off the surface by {@link Ray#DELTA}, so the ray ends that far from the light, not on it.
     */
    static final double REACH = 2 * Ray.DELTA;
    /** A face's edge, its coordinates' bound (1) and a margin. */
    private static final double EDGE = 1 + 1e-6;

    /** A cell's one item when it has more than {@link #MOST_LEAVES} leaves: the caller walks. */
    private static final int FULL = -1;
    /**
     * How far from the origin a shadow ray may start, in scene sizes, and stay the index's: so
     * that the rounding of its points stays far below the index's margins.
     */
    private static final double FAR = 1e4;

    private final Bvh tree;
    /** A point light's position, or null for a directional light. */
    private final double[] light;
    /** A directional light's shadow-ray direction (bit for bit) and the two unit vectors across it; null for a point light. */
    private final double[] columns;
    /** The largest coordinate a ray's head may have ({@link #FAR} scene sizes). */
    private final double far;
    /** The faces' grids (six for a point light, one for a directional light). */
    private final Grids grids;
    /** Cell c holds the leaves (node numbers) items[start[c]] to items[start[c + 1] - 1], or the one item {@link #FULL}. */
    private final int[] start;
    private final int[] items;

    private ShadowIndex(Bvh tree, double[] light, double[] columns, double far, Grids grids, int[] start, int[] items) {
        this.tree = tree;
        this.light = light;
        this.columns = columns;
        this.far = far;
        this.grids = grids;
        this.start = start;
        this.items = items;
    }

    /**
     * Per face, a {@link #CELLS}² grid over the rectangle [aLow, aHigh] × [bLow, bHigh] of the
     * face's two coordinates that the leaves reach. A coordinate maps to its cell monotonically,
     * by the same arithmetic in the build and in the query, so a leaf's range of cells holds every
     * coordinate in its range.
     */
    private static final class Grids {
        private final double[] aLow, aHigh, bLow, bHigh, aPer, bPer;

        Grids(double[] span) {
            int faces = span.length / 4;
            aLow = new double[faces];
            aHigh = new double[faces];
            bLow = new double[faces];
            bHigh = new double[faces];
            aPer = new double[faces];
            bPer = new double[faces];
            for (int f = 0; f < faces; ++f) {
                aLow[f] = span[4 * f];
                aHigh[f] = span[4 * f + 1];
                bLow[f] = span[4 * f + 2];
                bHigh[f] = span[4 * f + 3];
                // A flat span (a face the scene meets edge-on) keeps finite cells per unit.
                aPer[f] = CELLS / Math.max(aHigh[f] - aLow[f], Double.MIN_NORMAL);
                bPer[f] = CELLS / Math.max(bHigh[f] - bLow[f], Double.MIN_NORMAL);
            }
        }

        /** @return the cell of coordinates (a, b) on face {@code face}, or -1 outside its span (no leaf there) */
        int cell(int face, double a, double b) {
            if (a < aLow[face] || a > aHigh[face] || b < bLow[face] || b > bHigh[face]) return -1;
            return (face * CELLS + aCell(face, a)) * CELLS + bCell(face, b);
        }

        int aCell(int face, double a) {
            return clamp((int) ((a - aLow[face]) * aPer[face]));
        }

        int bCell(int face, double b) {
            return clamp((int) ((b - bLow[face]) * bPer[face]));
        }

        private static int clamp(int cell) {
            return cell < 0 ? 0 : Math.min(cell, CELLS - 1);
        }
    }

    /**
     * The index of a point light at (x, y, z) (its radius 0: every shadow ray ends at it).
     *
     * @return the index, or null when it would not pay: a tree with no bounded leaf, a user's
     *         shape without a box (every ray would walk), or cells mostly full
     */
    static ShadowIndex fromPoint(Bvh tree, double x, double y, double z) {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z))) return null;
        double[][] boxes = leafBoxes(tree, 6);
        if (boxes == null) return null;
        double scale = scale(boxes, x, y, z);
        // Each box padded by the reach, relative to the light; then, per face, the ranges of the
        // directions toward it.
        double pad = REACH + 1e-6 * (1 + scale);
        double[][] ranges = new double[boxes.length][];
        for (int i = 0; i < boxes.length; ++i) {
            double[] b = boxes[i];
            b[0] -= x + pad;
            b[1] -= y + pad;
            b[2] -= z + pad;
            b[3] += pad - x;
            b[4] += pad - y;
            b[5] += pad - z;
            ranges[i] = faceRanges(b);
        }
        return sort(tree, new double[] { x, y, z }, null, FAR * (1 + scale), boxes, ranges, 6);
    }

    /**
     * The index of a directional light whose shadow rays go along the unit vector (x, y, z), those
     * very components: a ray along any other direction is not the index's.
     *
     * @return the index, or null as {@link #fromPoint}
     */
    static ShadowIndex along(Bvh tree, double x, double y, double z) {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) || x == 0 && y == 0 && z == 0) return null;
        double[][] boxes = leafBoxes(tree, 1);
        if (boxes == null) return null;
        double scale = scale(boxes, x, y, z), margin = 1e-9 * (1 + scale);
        // Two unit vectors across the direction: u = d × (the axis least along d), v = d × u.
        double ax = Math.abs(x), ay = Math.abs(y), az = Math.abs(z);
        Vector d = new Vector(x, y, z);
        Vector u = d.crossProduct(ax <= ay && ax <= az ? Vector.AXIS_X : ay <= az ? Vector.AXIS_Y : Vector.AXIS_Z).normalize();
        Vector v = d.crossProduct(u).normalize();
        // Each box seen along the direction: its interval on u and on v, widened by the margin.
        double[][] ranges = new double[boxes.length][];
        for (int i = 0; i < boxes.length; ++i)
            ranges[i] = new double[] { project(u, boxes[i], false) - margin, project(u, boxes[i], true) + margin,
                    project(v, boxes[i], false) - margin, project(v, boxes[i], true) + margin };
        double[] columns = { x, y, z, u.getX(), u.getY(), u.getZ(), v.getX(), v.getY(), v.getZ() };
        return sort(tree, null, columns, FAR * (1 + scale), boxes, ranges, 1);
    }

    /**
     * @return the boxes (min x, y, z, max x, y, z, then the node number) of the tree's leaves, or
     *         null when the index cannot take them, or more than four a cell ({@code faces} grids)
     */
    private static double[][] leafBoxes(Bvh tree, int faces) {
        // More leaves than that would fill most cells (a mesh): not worth their sorting.
        int[] leaves = tree.shadowIndexLeaves(4 * faces * CELLS * CELLS);
        if (leaves == null) return null;
        double[][] boxes = new double[leaves.length][7];
        float[] box = new float[6];
        for (int i = 0; i < leaves.length; ++i) {
            tree.leafBox(leaves[i] < 0 ? -1 - leaves[i] : leaves[i], box);
            for (int k = 0; k < 6; ++k)
                boxes[i][k] = box[k];
            boxes[i][6] = leaves[i]; // exact in a double; negative for a leaf with a user's shape
        }
        return boxes;
    }

    /** @return the largest magnitude among the boxes' and the light's coordinates: the scene's size, for the margins */
    private static double scale(double[][] boxes, double x, double y, double z) {
        double scale = Math.max(Math.max(Math.abs(x), Math.abs(y)), Math.abs(z));
        for (double[] b : boxes)
            for (int k = 0; k < 6; ++k)
                scale = Math.max(scale, Math.abs(b[k]));
        return scale;
    }

    /**
     * The directions from the light toward the padded box {@code b} (relative to the light), per
     * cube face: face f looks along axis f / 2, forwards for even f; its coordinates are the other
     * two axes (in increasing order) over that one, in [-1, 1] (up to {@link #EDGE}).
     *
     * @return per face, the ranges of its two coordinates (a low, a high, b low, b high), with a
     *         margin; NaN where the box is not seen through the face
     */
    private static double[] faceRanges(double[] b) {
        double[] r = new double[24];
        for (int face = 0; face < 6; ++face) {
            int k = face / 2, i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
            boolean forwards = face % 2 == 0;
            double hi = forwards ? b[3 + k] : -b[k];
            double lo = Math.max(forwards ? b[k] : -b[3 + k], 0);
            double iLow = lowRatio(b[i], lo, hi), iHigh = highRatio(b[3 + i], lo, hi);
            double jLow = lowRatio(b[j], lo, hi), jHigh = highRatio(b[3 + j], lo, hi);
            // The ranges are cut a hair outside [-1, 1], the bound of a query's coordinates
            // (|a| · (1 / m) ≤ m · (1 / m) ≤ 1 when rounded): no query on the face's edge falls out.
            boolean seen = hi > 0 && iLow <= EDGE && iHigh >= -EDGE && jLow <= EDGE && jHigh >= -EDGE;
            r[4 * face] = seen ? Math.max(iLow, -EDGE) : Double.NaN;
            r[4 * face + 1] = seen ? Math.min(iHigh, EDGE) : Double.NaN;
            r[4 * face + 2] = seen ? Math.max(jLow, -EDGE) : Double.NaN;
            r[4 * face + 3] = seen ? Math.min(jHigh, EDGE) : Double.NaN;
        }
        return r;
    }

    /** The least of a / w over a in [low, ...) and w in [lo, hi], lo ≥ 0 < hi, less a margin. */
    private static double lowRatio(double low, double lo, double hi) {
        double r = low >= 0 ? low / hi : lo > 0 ? low / lo : Double.NEGATIVE_INFINITY;
        return r - 1e-9;
    }

    /** The greatest of a / w over a in (..., high] and w in [lo, hi], lo ≥ 0 < hi, plus a margin. */
    private static double highRatio(double high, double lo, double hi) {
        double r = high <= 0 ? high / hi : lo > 0 ? high / lo : Double.POSITIVE_INFINITY;
        return r + 1e-9;
    }

    /** @return the minimum of e · p over the box b (its maximum when {@code high}) */
    private static double project(Vector e, double[] b, boolean high) {
        double ex = e.getX(), ey = e.getY(), ez = e.getZ();
        return (ex >= 0 == high ? ex * b[3] : ex * b[0]) + (ey >= 0 == high ? ey * b[4] : ey * b[1])
                + (ez >= 0 == high ? ez * b[5] : ez * b[2]);
    }

    /**
     * Sorts the leaves into the cells of their ranges ({@code ranges[i]}: per face, a low, a high,
     * b low, b high; NaN where not seen), each face's grid spanning its leaves' ranges.
     *
     * @return the index, or null when most cells are full
     */
    private static ShadowIndex sort(Bvh tree, double[] light, double[] columns, double far, double[][] boxes,
                                    double[][] ranges, int faces) {
        double[] span = new double[4 * faces];
        for (int f = 0; f < faces; ++f) {
            span[4 * f] = span[4 * f + 2] = Double.POSITIVE_INFINITY;
            span[4 * f + 1] = span[4 * f + 3] = Double.NEGATIVE_INFINITY;
        }
        for (double[] r : ranges)
            for (int f = 0; f < faces; ++f) {
                if (Double.isNaN(r[4 * f])) continue;
                span[4 * f] = Math.min(span[4 * f], r[4 * f]);
                span[4 * f + 1] = Math.max(span[4 * f + 1], r[4 * f + 1]);
                span[4 * f + 2] = Math.min(span[4 * f + 2], r[4 * f + 2]);
                span[4 * f + 3] = Math.max(span[4 * f + 3], r[4 * f + 3]);
            }
        Grids grids = new Grids(span); // a face no leaf is seen through spans nothing: every query there is outside
        int cells = faces * CELLS * CELLS;
        int[] count = new int[cells];
        // A leaf with a user's shape counts as a full cell's worth: its cells are left to the walk.
        for (int i = 0; i < boxes.length; ++i)
            cover(grids, ranges[i], faces, count, null, null, boxes[i][6] < 0 ? MOST_LEAVES + 1 : 1);
        int full = 0;
        for (int c = 0; c < cells; ++c)
            if (count[c] > MOST_LEAVES) ++full;
        // A light whose cells are mostly full would cost every shadow ray a useless look-up.
        if (full * 2 > cells) return null;
        int[] start = new int[cells + 1];
        // Where the next leaf of cell c goes; -1 for a full cell, which holds the one item FULL.
        int[] next = new int[cells];
        for (int c = 0; c < cells; ++c) {
            boolean isFull = count[c] > MOST_LEAVES;
            next[c] = isFull ? -1 : start[c];
            start[c + 1] = start[c] + (isFull ? 1 : count[c]);
        }
        int[] items = new int[start[cells]];
        for (int c = 0; c < cells; ++c)
            if (next[c] < 0) items[start[c]] = FULL;
        for (int i = 0; i < boxes.length; ++i)
            cover(grids, ranges[i], faces, null, next, items, (int) boxes[i][6]);
        return new ShadowIndex(tree, light, columns, far, grids, start, items);
    }

    /**
     * The cells of ranges {@code r}: {@code value} (a leaf's weight) added to their {@code count}s,
     * or, when {@code count} is null, {@code value} (the leaf's node) written at {@code next} into
     * {@code items} (not into a full cell).
     */
    private static void cover(Grids grids, double[] r, int faces, int[] count, int[] next, int[] items, int value) {
        for (int f = 0; f < faces; ++f) {
            if (Double.isNaN(r[4 * f])) continue;
            int a0 = grids.aCell(f, r[4 * f]), a1 = grids.aCell(f, r[4 * f + 1]);
            int b0 = grids.bCell(f, r[4 * f + 2]), b1 = grids.bCell(f, r[4 * f + 3]);
            for (int a = a0; a <= a1; ++a)
                for (int b = b0; b <= b1; ++b) {
                    int c = (f * CELLS + a) * CELLS + b;
                    if (count != null) count[c] += value;
                    else if (next[c] >= 0) items[next[c]++] = value;
                }
        }
    }

    /**
     * Whether the tree's any-hit walk would find nothing along {@code query} within
     * {@code maxDistance}, proved from the leaves of the ray's cell.
     *
     * @param query       a shadow ray toward this index's light
     * @param maxDistance how far along it a hit counts (the light's distance; +∞ for a directional light)
     * @return true only when the walk ({@code LeanQueries.visitHits(tree, query, maxDistance, visitor)})
     *         would call its visitor for no hit; false when some shape crosses the ray or the
     *         index cannot tell (then walk)
     */
    public boolean clear(Hit query, double maxDistance) {
        double ox = query.ox, oy = query.oy, oz = query.oz, dx = query.dx, dy = query.dy, dz = query.dz;
        if (!(Math.abs(ox) <= far && Math.abs(oy) <= far && Math.abs(oz) <= far)) return false;
        int cell;
        double[] at = light;
        if (at != null) {
            // The ray must end at the light, within its head's move off the surface; every point of
            // it is then within that of the ray from the light along -d, whose cell this is.
            double ex = ox + maxDistance * dx - at[0], ey = oy + maxDistance * dy - at[1], ez = oz + maxDistance * dz - at[2];
            if (!(ex * ex + ey * ey + ez * ez <= REACH * REACH)) return false;
            cell = pointCell(-dx, -dy, -dz);
        } else {
            double[] c = columns;
            if (dx != c[0] || dy != c[1] || dz != c[2]) return false;
            cell = grids.cell(0, ox * c[3] + oy * c[4] + oz * c[5], ox * c[6] + oy * c[7] + oz * c[8]);
        }
        // Outside every leaf's cells (cell -1) only the shapes without a box remain to be asked.
        int from = 0, to = 0;
        if (cell >= 0) {
            from = start[cell];
            to = start[cell + 1];
            if (to - from == 1 && items[from] == FULL) return false;
        }
        return tree.clearOf(items, from, to, query, maxDistance);
    }

    /** @return the cell of the unit direction (wx, wy, wz) from a point light, as {@link #faceRanges} numbers the faces; -1 where no leaf is */
    private int pointCell(double wx, double wy, double wz) {
        double ax = Math.abs(wx), ay = Math.abs(wy), az = Math.abs(wz);
        int face;
        double m, a, b;
        if (ax >= ay && ax >= az) {
            face = wx >= 0 ? 0 : 1;
            m = ax;
            a = wy;
            b = wz;
        } else if (ay >= az) {
            face = wy >= 0 ? 2 : 3;
            m = ay;
            a = wx;
            b = wz;
        } else {
            face = wz >= 0 ? 4 : 5;
            m = az;
            a = wx;
            b = wy;
        }
        // One division: the ratios differ from a / m and b / m by an ulp, far inside the build's margin.
        double inverse = 1 / m;
        return grids.cell(face, a * inverse, b * inverse);
    }
}
