package primitives;

/**
 * The library's checks of the numbers a user gives it (sizes, radii, coefficients): each rejects
 * a bad value with an {@link IllegalArgumentException} whose message names the value and why.
 * Apart from {@link Util}, so that a student completing {@code Util.} sees the course's helpers
 * only; the shapes, lights and renderer, in other packages, call these.
 *
 * @hidden internal: the library's argument checks; a scene test sees their messages
 */
public final class Checks {
    private Checks() {
    }

    /**
     * Rejects NaN and infinities with a message naming the value.
     *
     * @param value the value to check
     * @param name what the value is, for the message (e.g. "sphere radius")
     * @return {@code value}
     * @throws IllegalArgumentException when {@code value} is NaN or infinite
     */
    public static double requireFinite(double value, String name) {
        if (!Double.isFinite(value))
            throw new IllegalArgumentException(name + " must be a finite number, got " + value);
        return value;
    }

    /**
     * Rejects values that are not finite and strictly positive (sizes, distances, radii).
     *
     * @param value the value to check
     * @param name what the value is, for the message (e.g. "view-plane width")
     * @return {@code value}
     * @throws IllegalArgumentException when {@code value} is ≤ 0, NaN or infinite
     */
    public static double requirePositive(double value, String name) {
        if (!(value > 0) || Double.isInfinite(value))
            throw new IllegalArgumentException(name + " must be a positive finite number, got " + value);
        return value;
    }

    /**
     * Rejects values that are not finite and non-negative (spreads, radii where 0 means "off").
     *
     * @param value the value to check
     * @param name what the value is, for the message (e.g. "reflection spread")
     * @return {@code value}
     * @throws IllegalArgumentException when {@code value} is negative, NaN or infinite
     */
    public static double requireNonNegative(double value, String name) {
        if (!(value >= 0) || Double.isInfinite(value))
            throw new IllegalArgumentException(name + " must be a non-negative finite number, got " + value);
        return value;
    }

    /**
     * Rejects negative counts and exponents.
     *
     * @param value the value to check
     * @param name  what the value is, for the message (e.g. "shininess")
     * @return {@code value}
     * @throws IllegalArgumentException when {@code value} is negative
     */
    public static int requireNonNegative(int value, String name) {
        if (value < 0) throw new IllegalArgumentException(name + " must be non-negative, got " + value);
        return value;
    }
}
