package renderer;

/**
 * A deterministic stream of uniform random numbers for one camera sample. It is reset from
 * (render seed, pixel x, pixel y, sample index), so every number a sample draws (its position in
 * the pixel, its lens point, its glossy and shadow rays at every bounce) depends on nothing but
 * those four values: not on threads, timing or the order pixels are rendered in.
 *
 * <p>A SplitMix64 generator (Steele, Lea and Flood, 2014): one long of state, reseeded in place,
 * so a worker reuses one instance for every sample instead of allocating a generator per sample
 * as {@link java.util.SplittableRandom} would require.
 */
final class SampleStream {
    private static final long GOLDEN = 0x9E37_79B9_7F4A_7C15L;
    private long state;
    // The key of the last reset; hashed into the state only when a number is first drawn, since
    // most samples of a plain render (no lens, no glossy surface, no area light) draw none.
    private long seed;
    private int x, y, index;
    private boolean pending;

    /** Positions the stream at the start of the numbers of sample {@code index} of pixel (x, y). */
    SampleStream reset(long seed, int x, int y, int index) {
        this.seed = seed;
        this.x = x;
        this.y = y;
        this.index = index;
        pending = true;
        return this;
    }

    /** @return a uniform double in [0, 1) */
    double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }

    long nextLong() {
        if (pending) {
            long h = mix(seed + GOLDEN);
            h = mix(h ^ (x * 0xD1B5_4A32_D192_ED03L));
            h = mix(h ^ (y * 0xABC9_8388_FB8F_AC03L));
            state = mix(h ^ (index * 0x8CB9_2BA7_2F3D_8DD7L));
            pending = false;
        }
        state += GOLDEN;
        return mix(state);
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58_476D_1CE4_E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D0_49BB_1331_11EBL;
        return z ^ (z >>> 31);
    }
}
