package geometries;

import java.util.Arrays;

/**
 * The layout of a {@link Bvh}'s wide nodes, which the vector walk ({@link VectorWalk}) reads,
 * and the collapse that makes them from the binary tree ({@link BvhNodes}). Each wide node holds
 * up to {@value #WIDTH} children, taken from the binary tree by opening, while there is room,
 * the child of largest surface area that is an inner node (as Embree's and pbrt's wide trees are
 * made); the children's boxes are the binary nodes' float boxes unchanged, so that a box test of
 * the vector walk computes, lane by lane, the same doubles as the scalar walk's test of that
 * node. Children keep the binary tree's left-to-right order: an any-hit walk that visits them in
 * slot order meets the primitives in the scalar walk's order.
 *
 * <p>Node {@code w}'s record is {@value #NODE} floats = 128 bytes (two cache lines) at
 * {@link #at(int) at(w)}, structure-of-arrays so that each of the six bounds of all children
 * loads as one vector:
 * <ul>
 * <li>floats 0–23: min x of children 0–3, min y ×4, min z ×4, max x ×4, max y ×4, max z ×4
 * ({@link #MIN_X} …); an empty child slot has every bound +∞, a box every ray misses (its
 * entry is +∞, as the scalar test's miss is);</li>
 * <li>floats 24–27, as raw int bits: per child, an inner child's wide node, a leaf child's first
 * primitive (in the tree's leaf order);</li>
 * <li>floats 28–31, as raw int bits: per child, a leaf's primitive count (&gt; 0), 0 for an
 * inner child or an empty slot.</li>
 * </ul>
 * A child is addressed as {@code w · WIDTH + lane}, the walks' stack entries.
 */
final class WideNodes {
    /** Children per wide node: four doubles fill one 256-bit vector (AVX2). */
    static final int WIDTH = 4;
    /** Floats per record. */
    static final int NODE = 8 * WIDTH;
    /** The offsets of the six bounds in a record, each followed by one float per child. */
    static final int MIN_X = 0, MIN_Y = WIDTH, MIN_Z = 2 * WIDTH, MAX_X = 3 * WIDTH, MAX_Y = 4 * WIDTH,
            MAX_Z = 5 * WIDTH;
    private static final int LINK = 6 * WIDTH, COUNT = 7 * WIDTH;
    /** Floats before the first record: as {@link BvhNodes}'s, so that each record starts a cache line. */
    private static final int BASE = 12;

    /** The records, laid out as above. */
    final float[] node;
    /** The number of wide nodes. */
    final int count;
    /** The most wide nodes on a path from the root, the root included. */
    final int depth;

    private WideNodes(float[] node, int count, int depth) {
        this.node = node;
        this.count = count;
        this.depth = depth;
    }

    /** @return the offset of wide node {@code w}'s record in {@link #node} */
    static int at(int w) {
        return BASE + w * NODE;
    }

    /** @return child {@code item}'s ({@code w · WIDTH + lane}) link: an inner child's wide node, a leaf's first primitive */
    static int link(float[] nd, int item) {
        return Float.floatToRawIntBits(nd[BASE + (item / WIDTH) * NODE + LINK + item % WIDTH]);
    }

    /** @return child {@code item}'s primitive count: &gt; 0 for a leaf, 0 for an inner child */
    static int count(float[] nd, int item) {
        return Float.floatToRawIntBits(nd[BASE + (item / WIDTH) * NODE + COUNT + item % WIDTH]);
    }

    /** @return the bytes of the records, as {@link Bvh#indexBytes()} counts them */
    long bytes() {
        return count * (long) NODE * Float.BYTES;
    }

    /**
     * Collapses the binary tree {@code binary} of {@code nodes} records (root at 0, not a leaf)
     * into wide nodes; the binary root's box stays the walks' first test.
     */
    static WideNodes collapse(float[] binary, int nodes) {
        // At most one wide node per inner binary node: the count bounds the records.
        float[] out = new float[BASE + (nodes / 2 + 1) * NODE];
        int[] open = new int[WIDTH];
        // Depth-first, an explicit stack of (binary node, wide node to write, its depth).
        int[] stack = new int[3 * (nodes + 1)];
        int top = 0, made = 1, deepest = 1;
        stack[top++] = 0;
        stack[top++] = 0;
        stack[top++] = 1;
        while (top > 0) {
            int level = stack[--top], w = stack[--top], b = stack[--top];
            deepest = Math.max(deepest, level);
            int children = open(binary, b, open);
            int at = at(w);
            for (int j = 0; j < WIDTH; ++j) {
                if (j >= children) {
                    for (int bound = 0; bound < 6; ++bound) out[at + bound * WIDTH + j] = Float.POSITIVE_INFINITY;
                    continue;
                }
                int c = open[j], rec = BvhNodes.at(c);
                out[at + MIN_X + j] = BvhNodes.min(binary, rec, BvhNodes.X);
                out[at + MIN_Y + j] = BvhNodes.min(binary, rec, BvhNodes.Y);
                out[at + MIN_Z + j] = BvhNodes.min(binary, rec, BvhNodes.Z);
                out[at + MAX_X + j] = BvhNodes.max(binary, rec, BvhNodes.X);
                out[at + MAX_Y + j] = BvhNodes.max(binary, rec, BvhNodes.Y);
                out[at + MAX_Z + j] = BvhNodes.max(binary, rec, BvhNodes.Z);
                int count = BvhNodes.count(binary, rec);
                if (count > 0) {
                    out[at + LINK + j] = Float.intBitsToFloat(BvhNodes.first(binary, rec));
                    out[at + COUNT + j] = Float.intBitsToFloat(count);
                } else {
                    int child = made++;
                    out[at + LINK + j] = Float.intBitsToFloat(child);
                    stack[top++] = c;
                    stack[top++] = child;
                    stack[top++] = level + 1;
                }
            }
        }
        return new WideNodes(Arrays.copyOf(out, BASE + made * NODE), made, deepest);
    }

    /**
     * The children of a wide node over inner binary node {@code b}, in left-to-right order, into
     * {@code out}: its two children, then, while fewer than {@link #WIDTH}, the inner one of
     * largest surface area replaced by its own two (the first of equal areas).
     *
     * @return how many children {@code out} holds (2 … WIDTH)
     */
    private static int open(float[] binary, int b, int[] out) {
        int rec = BvhNodes.at(b);
        out[0] = b + 1;
        out[1] = BvhNodes.right(binary, rec);
        int n = 2;
        while (n < WIDTH) {
            int best = -1;
            double bestArea = -1;
            for (int j = 0; j < n; ++j) {
                int r = BvhNodes.at(out[j]);
                if (BvhNodes.count(binary, r) > 0) continue;
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

    /** @return half the surface area of the binary record at {@code rec}'s box */
    private static double halfArea(float[] binary, int rec) {
        double x = (double) BvhNodes.max(binary, rec, BvhNodes.X) - BvhNodes.min(binary, rec, BvhNodes.X);
        double y = (double) BvhNodes.max(binary, rec, BvhNodes.Y) - BvhNodes.min(binary, rec, BvhNodes.Y);
        double z = (double) BvhNodes.max(binary, rec, BvhNodes.Z) - BvhNodes.min(binary, rec, BvhNodes.Z);
        return x * y + y * z + z * x;
    }
}
