package primitives;

import java.util.SplittableRandom;

/**
 * Floating-point helpers shared by the whole library.
 *
 * <p>{@link #isZero(double)} treats every value whose binary exponent is below -40 (|x| &lt; about
 * 9e-13) as zero. That absorbs the rounding noise of a few dozen multiply-adds on world
 * coordinates of order 1..10^4 while keeping real geometric quantities distinct.
 */
public final class Util {
    /**
     * Values below this in magnitude are treated as zero: 2^-40 ≈ 9.1e-13. "Binary exponent below
     * -40" and "|x| &lt; 2^-40" are the same test for every double (NaN and ±∞ are not zero,
     * subnormals are); the comparison form stays in floating-point registers, which matters
     * because the intersection kernels call it several times per ray. Package-private for
     * {@link Ray#headOffset}, which compares with it directly.
     */
    static final double ACCURACY = 0x1p-40;

    /**
     * The generator behind {@link #random(double, double)}: fixed seed, so a program that builds
     * its scene with the same calls gets the same scene on every run. Guarded by its own lock.
     */
    private static final SplittableRandom SCENE_RANDOM = new SplittableRandom(0x5EED_5784L);

    private Util() {
    }

    /**
     * A uniformly distributed number in [min, max) for building scenes (the course's helper, e.g.
     * to scatter spheres). Unlike the course's version, which draws from the JDK's shared
     * unseeded generator, the sequence is reproducible: it starts from a fixed seed in every JVM,
     * so the n-th call of a run always returns the same number. This is the library's one piece
     * of static mutable state, which the course's static signature imposes; the renderer never
     * calls it (its sampling draws from per-pixel streams), so images never depend on it.
     *
     * @param min the smallest value, finite
     * @param max the bound, finite and not below {@code min}; {@code min == max} returns min
     * @return a number in [min, max)
     * @throws IllegalArgumentException when a bound is NaN or infinite, or {@code max < min}
     */
    public static double random(double min, double max) {
        Checks.requireFinite(min, "random minimum");
        Checks.requireFinite(max, "random maximum");
        if (max < min) throw new IllegalArgumentException("random maximum " + max + " is below the minimum " + min);
        double u;
        synchronized (SCENE_RANDOM) {
            u = SCENE_RANDOM.nextDouble();
        }
        return min + u * (max - min);
    }

    /**
     * @param number any double
     * @return true when |{@code number}| &lt; 2^-40, the library's zero tolerance (NaN is not zero)
     */
    public static boolean isZero(double number) {
        return Math.abs(number) < ACCURACY;
    }

    /**
     * @param number any double
     * @return {@code number}, or exactly 0.0 when it is within the zero tolerance, so that sign tests
     *         on the result ({@code > 0}, {@code < 0}) ignore rounding noise
     */
    public static double alignZero(double number) {
        return Math.abs(number) < ACCURACY ? 0.0 : number;
    }

    /**
     * @param n1 the first value
     * @param n2 the second value
     * @return true when both values are non-zero and have the same sign
     */
    public static boolean compareSign(double n1, double n2) {
        return (n1 < 0 && n2 < 0) || (n1 > 0 && n2 > 0);
    }
}
