package geometries;

import primitives.Ray;
import primitives.Vector;

/**
 * Haines and Greenberg's light buffer (1986) for one light of a render: the leaves of a scene's
 * tree sorted into cells by where a shadow ray toward that light can meet them. A point light's
 * cells are the directions from the light (the six faces of a cube around it, {@link #CELLS}²
 * each); a directional light's are columns along its direction (a {@link #CELLS}² grid over the
 * scene seen from the light). A lit point's shadow ray, most shadow rays of a scene, is then
 * proved clear by the few leaves of its cell, instead of a walk from the tree's root.
 *
 * <p>Exact: {@link #clear} answers true only when the tree's any-hit walk
 * ({@link Bvh#visitHits}) would give its visitor no hit. It runs the walk's own tests (the box
 * test, then the primitives' tests, as the walk does them) on every leaf the ray can reach, and
 * on the shapes without a box. Every other answer is false, and the caller walks the tree as
 * without the index: a cell with more than {@link #MOST_LEAVES} leaves, a ray that is not one of
 * this light's shadow rays, a shape that crosses the ray. The index is immutable; any number of
 * render threads may ask it.
 *
 * @hidden internal: built per light by the renderer ({@link LeanQueries#shadowIndexFrom},
 *         {@link LeanQueries#shadowIndexAlong})
 */
public final class ShadowIndex {
    /** Cells per side: of each cube face (a point light), of the grid (a directional light). */
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
    /** A cell answer: more leaves than {@link #MOST_LEAVES}, so the caller walks. */
    private static final int FULL = -1;
    /**
     * How far from the origin a shadow ray may start, in scene sizes, and stay the index's: so
     * that the rounding of its points stays far below the index's margins.
     */
    private static final double FAR = 1e4;

    private final Bvh tree;
    /** A point light's position, or null for a directional light. */
    private final double[] light;
    /** A directional light's columns, or null for a point light. */
    private final Columns columns;
    /** The largest coordinate a ray's head may have ({@link #FAR} scene sizes). */
    private final double far;
    /** Cell c holds the leaves (node numbers) items[start[c]] to items[start[c + 1] - 1], or the one item {@link #FULL}. */
    private final int[] start;
    private final int[] items;

    private ShadowIndex(Bvh tree, double[] light, Columns columns, double far, int[] start, int[] items) {
        this.tree = tree;
        this.light = light;
        this.columns = columns;
        this.far = far;
        this.start = start;
        this.items = items;
    }

    /**
     * A directional light's cells: the scene seen along the shadow rays' direction
     * (dx, dy, dz), on two unit vectors u and v across it, as a {@link #CELLS}² grid over
     * [u0, u1] × [v0, v1].
     */
    private static final class Columns {
        final double dx, dy, dz, ux, uy, uz, vx, vy, vz, u0, u1, v0, v1;
        /** Cells per unit of u and of v. */
        private final double perU, perV;

        Columns(Vector d, Vector u, Vector v, double u0, double u1, double v0, double v1) {
            dx = d.getX();
            dy = d.getY();
            dz = d.getZ();
            ux = u.getX();
            uy = u.getY();
            uz = u.getZ();
            vx = v.getX();
            vy = v.getY();
            vz = v.getZ();
            this.u0 = u0;
            this.u1 = u1;
            this.v0 = v0;
            this.v1 = v1;
            // A flat grid (a scene seen edge-on) keeps finite cells per unit: its one row is cell 0.
            perU = CELLS / Math.max(u1 - u0, Double.MIN_NORMAL);
            perV = CELLS / Math.max(v1 - v0, Double.MIN_NORMAL);
        }

        /** @return the column of a ray from (x, y, z), or -1 outside the grid (no leaf there) */
        int cellOf(double x, double y, double z) {
            double u = x * ux + y * uy + z * uz, v = x * vx + y * vy + z * vz;
            return u < u0 || u > u1 || v < v0 || v > v1 ? -1 : uCell(u) * CELLS + vCell(v);
        }

        /** @return the grid's column of u (monotone in u, clamped to the grid: a box's interval covers each u it holds) */
        int uCell(double u) {
            return clamp((int) ((u - u0) * perU));
        }

        /** @return the grid's row of v, as {@link #uCell} */
        int vCell(double v) {
            return clamp((int) ((v - v0) * perV));
        }
    }

    /**
     * The index of a point light at (x, y, z) (its radius 0: every shadow ray ends at it).
     *
     * @return the index, or null when it would not pay: a tree with no bounded leaf, a leaf the
     *         index may not test twice (a user's shape), or cells too full
     */
    static ShadowIndex fromPoint(Bvh tree, double x, double y, double z) {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z))) return null;
        int cells = 6 * CELLS * CELLS;
        double[][] boxes = leafBoxes(tree, cells);
        if (boxes == null) return null;
        double scale = scale(boxes, x, y, z);
        // Each box padded by the reach, relative to the light.
        double pad = REACH + 1e-6 * (1 + scale);
        for (double[] b : boxes) {
            b[0] -= x + pad;
            b[1] -= y + pad;
            b[2] -= z + pad;
            b[3] += pad - x;
            b[4] += pad - y;
            b[5] += pad - z;
        }
        return sort(tree, new double[] { x, y, z }, null, FAR * (1 + scale), boxes, cells);
    }

    /**
     * The index of a directional light whose shadow rays go along the unit vector (x, y, z), those
     * very components: a ray along any other direction is not the index's.
     *
     * @return the index, or null as {@link #fromPoint}
     */
    static ShadowIndex along(Bvh tree, double x, double y, double z) {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) || x == 0 && y == 0 && z == 0) return null;
        int cells = CELLS * CELLS;
        double[][] boxes = leafBoxes(tree, cells);
        if (boxes == null) return null;
        double scale = scale(boxes, x, y, z), margin = 1e-9 * (1 + scale);
        // Two unit vectors across the direction: u = d × (the axis least along d), v = d × u.
        double ax = Math.abs(x), ay = Math.abs(y), az = Math.abs(z);
        Vector d = new Vector(x, y, z);
        Vector u = d.crossProduct(ax <= ay && ax <= az ? Vector.AXIS_X : ay <= az ? Vector.AXIS_Y : Vector.AXIS_Z).normalize();
        Vector v = d.crossProduct(u).normalize();
        // Each box seen along the direction: its interval on u and on v, widened by the margin;
        // the grid spans them all.
        double uLow = Double.POSITIVE_INFINITY, uHigh = Double.NEGATIVE_INFINITY;
        double vLow = Double.POSITIVE_INFINITY, vHigh = Double.NEGATIVE_INFINITY;
        for (double[] b : boxes) {
            double ul = project(u, b, false) - margin, uh = project(u, b, true) + margin;
            double vl = project(v, b, false) - margin, vh = project(v, b, true) + margin;
            b[0] = ul;
            b[1] = uh;
            b[2] = vl;
            b[3] = vh;
            uLow = Math.min(uLow, ul);
            uHigh = Math.max(uHigh, uh);
            vLow = Math.min(vLow, vl);
            vHigh = Math.max(vHigh, vh);
        }
        return sort(tree, null, new Columns(d, u, v, uLow, uHigh, vLow, vHigh), FAR * (1 + scale), boxes, cells);
    }

    /** @return the boxes (min x, y, z, max x, y, z) of the tree's leaves, or null when the index cannot take them or more than 4 a cell */
    private static double[][] leafBoxes(Bvh tree, int cells) {
        // More leaves than that would fill most cells (a mesh): not worth their sorting.
        int[] leaves = tree.shadowIndexLeaves(4 * cells);
        if (leaves == null) return null;
        double[][] boxes = new double[leaves.length][7];
        float[] box = new float[6];
        for (int i = 0; i < leaves.length; ++i) {
            tree.leafBox(leaves[i], box);
            for (int k = 0; k < 6; ++k)
                boxes[i][k] = box[k];
            boxes[i][6] = leaves[i]; // the node number, exact in a double
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

    /** Sorts the leaves into the cells their boxes {@code b} reach (see {@link #cover}): the index, or null when most cells are full. */
    private static ShadowIndex sort(Bvh tree, double[] light, Columns columns, double far, double[][] boxes, int cells) {
        int[] count = new int[cells];
        int[] range = new int[4];
        for (double[] b : boxes)
            cover(columns, b, range, count, null, null);
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
        for (double[] b : boxes)
            cover(columns, b, range, null, next, items);
        return new ShadowIndex(tree, light, columns, far, start, items);
    }

    /**
     * The cells leaf box {@code b} reaches: counted into {@code count}, or, when {@code count} is
     * null, its leaf ({@code b[6]}) written at {@code next} into {@code items} (not into a full cell).
     * A point light's {@code b} is the padded box relative to the light; a directional light's
     * ({@code columns} not null), its intervals on the grid's two axes.
     */
    private static void cover(Columns columns, double[] b, int[] range, int[] count, int[] next, int[] items) {
        int leaf = (int) b[6];
        if (columns != null) {
            range[0] = columns.uCell(b[0]);
            range[1] = columns.uCell(b[1]);
            range[2] = columns.vCell(b[2]);
            range[3] = columns.vCell(b[3]);
            add(0, range, count, next, items, leaf);
            return;
        }
        // Face f looks along axis f / 2, forwards for even f; its cell coordinates are the other
        // two axes (in increasing order) over that one.
        for (int face = 0; face < 6; ++face) {
            int k = face / 2, i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
            boolean forwards = face % 2 == 0;
            double hi = forwards ? b[3 + k] : -b[k];
            if (!(hi > 0)) continue;
            double lo = Math.max(forwards ? b[k] : -b[3 + k], 0);
            double iLow = lowRatio(b[i], lo, hi), iHigh = highRatio(b[3 + i], lo, hi);
            double jLow = lowRatio(b[j], lo, hi), jHigh = highRatio(b[3 + j], lo, hi);
            if (iLow > 1 || iHigh < -1 || jLow > 1 || jHigh < -1) continue;
            range[0] = faceCell(iLow);
            range[1] = faceCell(iHigh);
            range[2] = faceCell(jLow);
            range[3] = faceCell(jHigh);
            add(face * CELLS * CELLS, range, count, next, items, leaf);
        }
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

    private static void add(int base, int[] range, int[] count, int[] next, int[] items, int leaf) {
        for (int i = range[0]; i <= range[1]; ++i)
            for (int j = range[2]; j <= range[3]; ++j) {
                int c = base + i * CELLS + j;
                if (count != null) ++count[c];
                else if (next[c] >= 0) items[next[c]++] = leaf;
            }
    }

    /** @return the minimum of e · p over the box b (its maximum when {@code high}) */
    private static double project(Vector e, double[] b, boolean high) {
        double ex = e.getX(), ey = e.getY(), ez = e.getZ();
        return (ex >= 0 == high ? ex * b[3] : ex * b[0]) + (ey >= 0 == high ? ey * b[4] : ey * b[1])
                + (ez >= 0 == high ? ez * b[5] : ez * b[2]);
    }

    /** @return the cell of a face coordinate in [-1, 1] (monotone in it), clamped to the face */
    private static int faceCell(double r) {
        return clamp((int) ((r + 1) * (CELLS / 2.0)));
    }

    private static int clamp(int cell) {
        return cell < 0 ? 0 : Math.min(cell, CELLS - 1);
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
            Columns c = columns;
            if (dx != c.dx || dy != c.dy || dz != c.dz) return false;
            // Outside the grid the ray's column meets no leaf: only the shapes without a box remain.
            cell = c.cellOf(ox, oy, oz);
        }
        int from = 0, to = 0;
        if (cell >= 0) {
            from = start[cell];
            to = start[cell + 1];
            if (to - from == 1 && items[from] == FULL) return false;
        }
        return tree.clearOf(items, from, to, query, maxDistance);
    }

    /** @return the cell of the unit direction (wx, wy, wz) from a point light, as {@link #cover} numbers them */
    private static int pointCell(double wx, double wy, double wz) {
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
        return (face * CELLS + faceCell(a / m)) * CELLS + faceCell(b / m);
    }
}
