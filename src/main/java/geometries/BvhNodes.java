package geometries;

/**
 * The layout of a {@link Bvh}'s flat node array, and the only code that knows it: the builder
 * writes records through {@link #writeLeaf}, {@link #writeInner} and {@link #writeBox}, the walks
 * read them through the accessors. All static, over the array the caller holds in a local, so
 * that each accessor inlines to the one array load it names (a walk's loads are its cost).
 *
 * <p>Node {@code n}'s record is {@value #NODE} floats = 32 bytes at {@link #at(int) at(n)},
 * depth-first (an inner node's left child is the next node):
 * <ul>
 * <li>floats 0–5: the box, min x, y, z then max x, y, z, rounded outward from the exact double
 * box, so that it contains it and a slab test against it loses no hit;</li>
 * <li>float 6, as raw int bits: a leaf's first primitive (in the tree's leaf order), an inner
 * node's right child;</li>
 * <li>float 7, as raw int bits: a leaf's primitive count (&gt; 0), an inner node's
 * {@code INNER | skip}, skip being the first node after its subtree (where the any-hit walk goes
 * when the box is missed; a leaf's is the next node).</li>
 * </ul>
 * Floats halve the bytes a walk touches, and the skip link in the record spares the any-hit walk a
 * second array, which is what a ray costs in a scene far larger than the caches. Two records
 * share a cache line (a node and its left child often share one).
 */
final class BvhNodes {
    /** Floats per node record. */
    private static final int NODE = 8;
    /**
     * Floats before node 0's record. The data of a large array starts 16 bytes (its header) past
     * a 64-byte boundary (G1 places a humongous array at the start of a region); 48 bytes more
     * put each 32-byte record inside one cache line, two to a line, where otherwise every other
     * record would straddle two lines. (About 4 % off a camera ray at 2×10⁶ primitives.) A small
     * array is only 8-byte aligned, but its tree stays in the caches anyway.
     */
    private static final int BASE = 12;
    /**
     * Marks an inner node's last field (a negative int; with fewer than 0x7F800000 nodes the bits
     * of either link field are never a NaN pattern, so they survive the round trip through float).
     */
    private static final int INNER = Integer.MIN_VALUE;
    /** The axes, as {@link #min} and {@link #max} take them. */
    static final int X = 0, Y = 1, Z = 2;

    private BvhNodes() {
    }

    /** @return a zeroed node array for {@code nodes} records */
    static float[] allocate(int nodes) {
        return new float[BASE + nodes * NODE];
    }

    /** @return the bytes of {@code nodes} records, as {@link Bvh#indexBytes()} counts them */
    static long bytes(int nodes) {
        return nodes * (long) NODE * Float.BYTES;
    }

    /** @return the offset of node {@code n}'s record in the array: what every other accessor takes */
    static int at(int n) {
        return BASE + n * NODE;
    }

    /** @return the lower bound on {@code axis} ({@link #X}, {@link #Y}, {@link #Z}) of the record at {@code at} */
    static float min(float[] nd, int at, int axis) {
        return nd[at + axis];
    }

    /** @return the upper bound on {@code axis} of the record at {@code at} */
    static float max(float[] nd, int at, int axis) {
        return nd[at + 3 + axis];
    }

    /**
     * @return for a leaf its primitive count, always &gt; 0; for an inner node a negative number
     *         (its skip link, marked), to be decoded only by {@link #skip}
     */
    static int count(float[] nd, int at) {
        return Float.floatToRawIntBits(nd[at + 7]);
    }

    /** @return a leaf's first primitive, in the tree's leaf order */
    static int first(float[] nd, int at) {
        return Float.floatToRawIntBits(nd[at + 6]);
    }

    /** @return an inner node's right child (its left child is the next node) */
    static int right(float[] nd, int at) {
        return Float.floatToRawIntBits(nd[at + 6]);
    }

    /**
     * @param count node {@code n}'s {@link #count}, as the walk already read it
     * @return the first node after node {@code n}'s subtree: the next node for a leaf
     */
    static int skip(int count, int n) {
        return count > 0 ? n + 1 : count & ~INNER;
    }

    /** The largest float not above {@code d} (−∞ below the float range): a box's lower bound rounded outward. */
    static float floatBelow(double d) {
        float f = (float) d;
        return f > d ? Math.nextDown(f) : f;
    }

    /** The smallest float not below {@code d} (+∞ above the float range): a box's upper bound rounded outward. */
    static float floatAbove(double d) {
        float f = (float) d;
        return f < d ? Math.nextUp(f) : f;
    }

    /** Writes the box {@code box[from..from + 6)} (min xyz, max xyz, already rounded outward) into the record at {@code at}. */
    static void writeBox(float[] nd, int at, float[] box, int from) {
        System.arraycopy(box, from, nd, at, 6);
    }

    /** Makes the record at {@code at} a leaf of {@code count} (&gt; 0) primitives from {@code first} on. */
    static void writeLeaf(float[] nd, int at, int first, int count) {
        nd[at + 6] = Float.intBitsToFloat(first);
        nd[at + 7] = Float.intBitsToFloat(count);
    }

    /** Makes the record at {@code at} an inner node whose right child is {@code right} and whose subtree ends before {@code skip}. */
    static void writeInner(float[] nd, int at, int right, int skip) {
        nd[at + 6] = Float.intBitsToFloat(right);
        nd[at + 7] = Float.intBitsToFloat(INNER | skip);
    }
}
