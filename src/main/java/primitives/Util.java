package primitives;

/**
 * Floating-point helpers shared by the whole library.
 *
 * <p>{@link #isZero(double)} treats every value whose binary exponent is below -40 (|x| &lt; about
 * 9e-13) as zero. That absorbs the rounding noise of a few dozen multiply-adds on world
 * coordinates of order 1..10^4 while keeping real geometric quantities distinct.
 */
public final class Util {
    /** Values with a binary exponent below this are treated as zero (2^-40 ≈ 9.1e-13). */
    private static final int ACCURACY = -40;

    private Util() {
    }

    /** The unbiased binary exponent of {@code num}, read directly from its IEEE-754 bits. */
    private static int getExp(double num) {
        return (int) ((Double.doubleToRawLongBits(num) & 0x7FF0_0000_0000_0000L) >> 52) - 1023;
    }

    /** @return true when {@code number} is within the library's zero tolerance */
    public static boolean isZero(double number) {
        return getExp(number) < ACCURACY;
    }

    /** @return {@code number}, or exactly 0.0 when it is within the zero tolerance */
    public static double alignZero(double number) {
        return getExp(number) < ACCURACY ? 0.0 : number;
    }

    /** @return true when both values are non-zero and have the same sign */
    public static boolean compareSign(double n1, double n2) {
        return (n1 < 0 && n2 < 0) || (n1 > 0 && n2 > 0);
    }

    /**
     * Rejects NaN and infinities with a message naming the value.
     *
     * @param name what the value is, for the message (e.g. "sphere radius")
     * @return {@code value}
     */
    public static double requireFinite(double value, String name) {
        if (!Double.isFinite(value))
            throw new IllegalArgumentException(name + " must be a finite number, got " + value);
        return value;
    }

    /** Rejects values that are not finite and strictly positive. */
    public static double requirePositive(double value, String name) {
        if (!(value > 0) || Double.isInfinite(value))
            throw new IllegalArgumentException(name + " must be a positive finite number, got " + value);
        return value;
    }

    /** Rejects values that are not finite and non-negative. */
    public static double requireNonNegative(double value, String name) {
        if (!(value >= 0) || Double.isInfinite(value))
            throw new IllegalArgumentException(name + " must be a non-negative finite number, got " + value);
        return value;
    }
}
