package renderer;

/**
 * Stratified 2-D sample points: the first two dimensions of the Sobol sequence, shuffled and
 * Owen-scrambled by a seed (Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020; the
 * scheme of pbrt-v4's {@code PaddedSobolSampler}). A sampler that takes n samples of a pixel
 * asks for points 0 … n−1 under the pixel's own seed, and gets:
 * <ul>
 * <li>stratification at every power of two: the first 2^k points put exactly one point in every
 * cell of every 2^a × 2^b grid of the unit square with a + b = k (a (0, k, 2)-net), so 16 points
 * are a jittered 4×4 grid, and also one per 16×1 column and 1×16 row; between powers of two the
 * points fill the cells left empty, so any count is well spread;</li>
 * <li>independence between seeds: another seed scrambles and shuffles the digits anew (Owen's
 * nested uniform scrambling, approximated by a hash), so neighbouring pixels do not repeat one
 * pattern, and two pairs of dimensions of the same sample (a film point and a lens point) drawn
 * under two seeds are not correlated.</li>
 * </ul>
 * Pure integer arithmetic on its arguments: no state, no allocation, the same point on any
 * thread. Coordinates have 32 bits of resolution (steps of 2⁻³²).
 */
final class SobolPoints {
    private SobolPoints() {
    }

    /**
     * Sample {@code index}'s point under {@code seed}, first coordinate.
     *
     * @param index the sample's number within its pixel, ≥ 0 (the net properties hold for the
     *              first 2^k indices)
     * @param seed  the scramble: the pixel's (and the pair of dimensions')
     * @return a number in [0, 1)
     */
    static double x(int index, int seed) {
        return unit(scramble(Integer.reverse(shuffle(index, seed)), mix(seed, 1)));
    }

    /** Sample {@code index}'s point under {@code seed}, second coordinate (see {@link #x}): in [0, 1). */
    static double y(int index, int seed) {
        return unit(scramble(sobolSecond(shuffle(index, seed)), mix(seed, 2)));
    }

    /**
     * Sobol's second dimension, 32 bits: the XOR of the direction numbers of the index's set bits,
     * v₀ = 2³¹ and v_k = v_{k−1} ⊕ (v_{k−1} ≫ 1) (primitive polynomial x + 1). The first is the
     * bit reversal of the index, and the two together make a (0, 2)-sequence in base 2.
     */
    private static int sobolSecond(int index) {
        int result = 0;
        for (int v = 1 << 31; index != 0; index >>>= 1, v ^= v >>> 1)
            if ((index & 1) != 0) result ^= v;
        return result;
    }

    /**
     * Permutes the sample indices so that every power-of-two prefix is still a whole net: the
     * index scrambled as {@link #scramble} scrambles a fraction, so that each bit is flipped by a
     * hash of the bits above it. The first 2^k indices (all bits from k up zero) thus map onto the
     * 2^k indices of one aligned block (the same bits from k up), and every aligned block of 2^k
     * points of a (0, 2)-sequence is a (0, k, 2)-net.
     */
    private static int shuffle(int index, int seed) {
        return scramble(index, mix(seed, 0));
    }

    /**
     * Nested uniform scrambling of a 32-bit fraction (its most significant bit the first binary
     * digit): each digit is flipped or not by a hash of the digits before it. Laine and Karras's
     * hash on the reversed bits, with Burley's constants: {@code x ^= x * even} changes each bit
     * only by the bits below it, which after the reversal are the digits above it.
     */
    private static int scramble(int x, int seed) {
        x = Integer.reverse(x);
        x += seed;
        x ^= x * 0x6c50b47c;
        x ^= x * 0xb82f1e52;
        x ^= x * 0xc7afe638;
        x ^= x * 0x8d22f6e6;
        return Integer.reverse(x);
    }

    /** A seed of its own for each use of one seed (shuffle, first, second), by a 32-bit finaliser (MurmurHash3's). */
    private static int mix(int seed, int use) {
        int h = seed + use * 0x9e3779b9;
        h ^= h >>> 16;
        h *= 0x85ebca6b;
        h ^= h >>> 13;
        h *= 0xc2b2ae35;
        return h ^ (h >>> 16);
    }

    /** The 32-bit fraction as a double in [0, 1). */
    private static double unit(int bits) {
        return (bits & 0xFFFF_FFFFL) * 0x1p-32;
    }
}
