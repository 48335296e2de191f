package geometries;

import java.util.Arrays;

/**
 * The layout of a {@link Bvh}'s wide nodes, which the vector walk ({@code VectorWalk}) reads,
 * and the collapse that makes them from the binary tree ({@link BvhNodes}). Each wide node holds
 * up to {@link #width} children (as many as doubles fill one of the CPU's vectors: 4 with AVX2,
 * 8 with AVX-512), taken from the binary tree by opening, while there is room, the child of
 * largest surface area that is an inner node and not a lane leaf (a whole subtree of a few
 * triangles, {@link TriangleLanes}), as Embree's and pbrt's wide trees are made; the
 * children's boxes are the binary nodes' float boxes unchanged, so that a box test of the vector
 * walk computes, lane by lane, the same doubles as the scalar walk's test of that node. Children
 * keep the binary tree's left-to-right order: an any-hit walk that visits them in slot order
 * meets the primitives in the scalar walk's order.
 *
 * <p>Node {@code w}'s record is {@code 8 · width} floats (128 bytes, two cache lines, at width
 * 4) at {@link #at(int, int) at(w, width)}, structure-of-arrays so that each of the six bounds of
 * all children loads as one vector:
 * <ul>
 * <li>{@code width} floats each: min x of every child, then min y, min z, max x, max y, max z
 * ({@link #bound}); an empty child slot has every bound +∞, a box every ray misses (its entry is
 * +∞, as the scalar test's miss is);</li>
 * <li>{@code width} floats, as raw int bits: per child, an inner child's wide node, a leaf
 * child's first primitive (in the tree's leaf order);</li>
 * <li>{@code width} floats, as raw int bits: per child, a leaf's primitive count, positive for a
 * leaf in the scalar layout, negative for a leaf of triangles laid out in lanes
 * ({@link TriangleLanes}), 0 for an inner child or an empty slot.</li>
 * </ul>
 * A child is addressed by its slot ({@link #slot}), the walks' stack entries.
 */
final class WideNodes {
    /** The widest node: the walks' scratch arrays hold this many children. */
    static final int MAX_WIDTH = 8;
    /** The bounds' order in a record, as {@link #bound} takes them. */
    static final int MIN_X = 0, MIN_Y = 1, MIN_Z = 2, MAX_X = 3, MAX_Y = 4, MAX_Z = 5;
    private static final int LINK = 6, COUNT = 7;
    /** Floats before the first record: as {@link BvhNodes}'s, so that each record starts a cache line. */
    private static final int BASE = 12;

    /** The records, laid out as above. */
    final float[] node;
    /** The number of wide nodes. */
    final int count;
    /** Children per node: a power of two, 2 … {@link #MAX_WIDTH}. */
    final int width;
    /** The most wide nodes on a path from the root, the root included. */
    final int depth;

    private WideNodes(float[] node, int count, int width, int depth) {
        this.node = node;
        this.count = count;
        this.width = width;
        this.depth = depth;
    }

    /** @return the offset of wide node {@code w}'s record in a node array of {@code width}-wide records */
    static int at(int w, int width) {
        return BASE + w * 8 * width;
    }

    /** @return the offset of bound {@code b} ({@link #MIN_X} … {@link #MAX_Z}) of the children, in a record at {@code at} */
    static int bound(int at, int b, int width) {
        return at + b * width;
    }

    /**
     * @return where child {@code lane} of wide node {@code w} is in a node array of
     *         {@code width}-wide records: its slot, the walks' stack entry, which {@link #link}
     *         and {@link #count} read (the offset of its min x)
     */
    static int slot(int w, int lane, int width) {
        return at(w, width) + lane;
    }

    /** @return the link of the child at {@code slot}: an inner child's wide node, a leaf's first primitive */
    static int link(float[] nd, int slot, int width) {
        return Float.floatToRawIntBits(nd[slot + LINK * width]);
    }

    /**
     * @return the primitive count of the child at {@code slot} (as {@link #link}): &gt; 0 for a
     *         leaf in the scalar layout, −count for a leaf of triangles in lanes, 0 for an inner child
     */
    static int count(float[] nd, int slot, int width) {
        return Float.floatToRawIntBits(nd[slot + COUNT * width]);
    }

    /** @return the slot of child {@code c} of all the nodes' children, in node order ({@code c = w · width + lane}) */
    int slot(int c) {
        return slot(c / width, c % width, width);
    }

    /** @return the most children a walk's stack holds: (width − 1) per wide level, and the one being visited */
    int stackSize() {
        return (width - 1) * depth + 1;
    }

    /** @return the bytes of the records, as {@link Bvh#indexBytes()} counts them */
    long bytes() {
        return count * 8L * width * Float.BYTES;
    }

    /**
     * Collapses the binary tree {@code binary} of {@code nodes} records (root at 0, not a leaf)
     * into nodes of {@code width} children (a power of two, 2 … {@link #MAX_WIDTH}); the binary
     * root's box stays the walks' first test. A subtree of triangles that {@link TriangleLanes#fits}
     * in {@code leafLanes} becomes one leaf with a negative count, which the tree lays out in lanes
     * ({@link TriangleLanes#arrange}), and is not opened; with {@code kind} null none does.
     */
    static WideNodes collapse(float[] binary, int nodes, int width, byte[] kind, int leafLanes) {
        if (width < 2 || width > MAX_WIDTH || Integer.bitCount(width) != 1)
            throw new IllegalArgumentException("a wide node holds 2, 4 or 8 children, not " + width);
        // At most one wide node per inner binary node: the count bounds the records.
        float[] out = new float[at(nodes / 2 + 1, width)];
        int[] open = new int[width];
        // Per binary node: its subtree's first primitive, and how many when it is a lane leaf (else 0).
        int[] first = new int[nodes], lanes = new int[nodes];
        laneLeaves(binary, nodes, kind, leafLanes, first, lanes);
        // Depth-first, an explicit stack of (binary node, wide node to write, its depth).
        int[] stack = new int[3 * (nodes + 1)];
        int top = 0, made = 1, deepest = 1;
        stack[top++] = 0;
        stack[top++] = 0;
        stack[top++] = 1;
        while (top > 0) {
            int level = stack[--top], w = stack[--top], b = stack[--top];
            deepest = Math.max(deepest, level);
            int children = open(binary, b, open, lanes);
            int at = at(w, width);
            for (int j = 0; j < width; ++j) {
                if (j >= children) {
                    for (int bound = MIN_X; bound <= MAX_Z; ++bound) out[bound(at, bound, width) + j] = Float.POSITIVE_INFINITY;
                    continue;
                }
                int c = open[j], rec = BvhNodes.at(c);
                for (int axis = BvhNodes.X; axis <= BvhNodes.Z; ++axis) {
                    out[bound(at, MIN_X + axis, width) + j] = BvhNodes.min(binary, rec, axis);
                    out[bound(at, MAX_X + axis, width) + j] = BvhNodes.max(binary, rec, axis);
                }
                int count = BvhNodes.count(binary, rec);
                if (lanes[c] > 0) {
                    out[at + LINK * width + j] = Float.intBitsToFloat(first[c]);
                    out[at + COUNT * width + j] = Float.intBitsToFloat(-lanes[c]);
                } else if (count > 0) {
                    out[at + LINK * width + j] = Float.intBitsToFloat(BvhNodes.first(binary, rec));
                    out[at + COUNT * width + j] = Float.intBitsToFloat(count);
                } else {
                    int child = made++;
                    out[at + LINK * width + j] = Float.intBitsToFloat(child);
                    stack[top++] = c;
                    stack[top++] = child;
                    stack[top++] = level + 1;
                }
            }
        }
        return new WideNodes(Arrays.copyOf(out, at(made, width)), made, width, deepest);
    }

    /**
     * The children of a wide node over inner binary node {@code b}, in left-to-right order, into
     * {@code out}: its two children, then, while fewer than {@code out.length}, the inner one of
     * largest surface area replaced by its own two (the first of equal areas).
     *
     * @return how many children {@code out} holds (2 … out.length)
     */
    private static int open(float[] binary, int b, int[] out, int[] lanes) {
        int rec = BvhNodes.at(b);
        out[0] = b + 1;
        out[1] = BvhNodes.right(binary, rec);
        int n = 2;
        while (n < out.length) {
            int best = -1;
            double bestArea = -1;
            for (int j = 0; j < n; ++j) {
                int r = BvhNodes.at(out[j]);
                if (BvhNodes.count(binary, r) > 0 || lanes[out[j]] > 0) continue;
                double area = halfArea(binary, r);
                if (area > bestArea) {
                    bestArea = area;
                    best = j;
                }
            }
            if (best < 0) break;
            int inner = out[best], r = BvhNodes.at(inner);
            System.arraycopy(out, best + 1, out, best + 2, n - best - 1);
            out[best] = inner + 1;
            out[best + 1] = BvhNodes.right(binary, r);
            ++n;
        }
        return n;
    }

    /**
     * Which binary nodes become lane leaves: those whose whole subtree {@link TriangleLanes#fits}
     * in {@code leafLanes} (none with {@code kind} null). A subtree's primitives are contiguous in
     * leaf order (the build partitions in place and lays the nodes out depth first), so such a
     * node's leaves become one lane leaf of the same primitives in the same order. Why whole
     * subtrees: a leaf test of four or eight triangles costs what one of a single triangle costs,
     * and the builder's leaves hold two on average, so the wide walk tests fewer nodes and leaves.
     *
     * @param first out: per binary node, its subtree's first primitive
     * @param lanes out: per binary node, its subtree's primitive count when it is a lane leaf, else 0
     */
    private static void laneLeaves(float[] binary, int nodes, byte[] kind, int leafLanes, int[] first, int[] lanes) {
        int[] end = new int[nodes];
        // Children come after their parent: a backward pass sees them first.
        for (int n = nodes - 1; n >= 0; --n) {
            int rec = BvhNodes.at(n), count = BvhNodes.count(binary, rec);
            if (count > 0) {
                first[n] = BvhNodes.first(binary, rec);
                end[n] = first[n] + count;
            } else {
                first[n] = first[n + 1];
                end[n] = end[BvhNodes.right(binary, rec)];
            }
            int size = end[n] - first[n];
            if (kind != null && TriangleLanes.fits(kind, first[n], size, leafLanes)) lanes[n] = size;
        }
    }

    /** @return half the surface area of the binary record at {@code rec}'s box */
    private static double halfArea(float[] binary, int rec) {
        double x = (double) BvhNodes.max(binary, rec, BvhNodes.X) - BvhNodes.min(binary, rec, BvhNodes.X);
        double y = (double) BvhNodes.max(binary, rec, BvhNodes.Y) - BvhNodes.min(binary, rec, BvhNodes.Y);
        double z = (double) BvhNodes.max(binary, rec, BvhNodes.Z) - BvhNodes.min(binary, rec, BvhNodes.Z);
        return x * y + y * z + z * x;
    }
}
