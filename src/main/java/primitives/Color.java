package primitives;

/**
 * An immutable RGB colour with non-negative components on the 0..255 scale of the course.
 * Components may exceed 255 while light accumulates; {@link #getColor()} clamps when writing.
 * Its arithmetic is {@link Rgb}'s per-channel kernels, which the renderer's in-place accumulator
 * uses too, so both give the same bits.
 * {@link #equals(Object)} is the 2025–26 course's, with a tolerance, for students' tests; the
 * library itself compares colours with {@link #distance(Color)}.
 * Serializable so that render settings can travel to the machines of a cluster.
 *
 * @serial exclude
 */
public final class Color implements java.io.Serializable {
    private static final long serialVersionUID = 1L;
    private final double r;
    private final double g;
    private final double b;

    /** Black: (0, 0, 0). */
    public static final Color BLACK = new Color(0, 0, 0, true);

    /** Internal constructor for results known to be valid (sums and non-negative scalings). */
    private Color(double r, double g, double b, boolean trusted) {
        this.r = r;
        this.g = g;
        this.b = b;
    }

    /**
     * A colour from its three channels on the 0..255 scale; values above 255 are kept (light adds up
     * before it is written) and only clamped by {@link #getColor()}.
     *
     * @param r red, finite and ≥ 0
     * @param g green, finite and ≥ 0
     * @param b blue, finite and ≥ 0
     * @throws IllegalArgumentException for a negative or non-finite component, naming all three
     */
    public Color(double r, double g, double b) {
        this(r, g, b, true);
        if (!(r >= 0) || !(g >= 0) || !(b >= 0) || Double.isInfinite(r) || Double.isInfinite(g) || Double.isInfinite(b))
            throw new IllegalArgumentException("colour components must be finite and non-negative, got (" + r + "," + g + "," + b + ")");
    }

    /** @param other an AWT colour; its 0..255 channels become this colour's channels (alpha is dropped) */
    public Color(java.awt.Color other) {
        this(other.getRed(), other.getGreen(), other.getBlue(), true);
    }

    /** @return the red channel, 0..255 scale, possibly above 255 */
    public double getR() {
        return r;
    }

    /** @return the green channel, 0..255 scale, possibly above 255 */
    public double getG() {
        return g;
    }

    /** @return the blue channel, 0..255 scale, possibly above 255 */
    public double getB() {
        return b;
    }

    /** @return the AWT colour, each channel rounded down and clamped to 0..255 */
    public java.awt.Color getColor() {
        return new java.awt.Color(clamp(r), clamp(g), clamp(b));
    }

    /** @return the colour packed as 0xRRGGBB, each channel clamped to 0..255 */
    public int toRgb() {
        return toRgb(r, g, b);
    }

    /**
     * {@link #toRgb()} of a colour kept as three doubles (a renderer's per-thread scratch), so
     * that a pixel needs no object.
     *
     * @param r the red component, 0..255 scale
     * @param g the green component
     * @param b the blue component
     * @return the colour packed as 0xRRGGBB, each channel clamped to 0..255
     */
    static int toRgb(double r, double g, double b) {
        return (clamp(r) << 16) | (clamp(g) << 8) | clamp(b);
    }

    private static int clamp(double c) {
        return c >= 255 ? 255 : (int) c;
    }

    /**
     * @param colors the colours to add; none gives this colour
     * @return the channel-wise sum of this colour and all of {@code colors}
     */
    public Color add(Color... colors) {
        double rr = r, gg = g, bb = b;
        for (Color c : colors) {
            rr = Rgb.sum(rr, c.r);
            gg = Rgb.sum(gg, c.g);
            bb = Rgb.sum(bb, c.b);
        }
        return new Color(rr, gg, bb, true);
    }

    /**
     * The sum of two colours without the varargs array: the tracer adds light contributions per ray,
     * so this form avoids an allocation on the hot path.
     *
     * @param c the colour to add
     * @return the channel-wise sum
     */
    public Color add(Color c) {
        return new Color(Rgb.sum(r, c.r), Rgb.sum(g, c.g), Rgb.sum(b, c.b), true);
    }

    /**
     * @param k the factor applied to all three channels, finite and ≥ 0 (light attenuation, weights)
     * @return this colour times {@code k}
     * @throws IllegalArgumentException for a negative or non-finite factor, naming it
     */
    public Color scale(double k) {
        if (!(k >= 0) || Double.isInfinite(k))
            throw new IllegalArgumentException("colour scale factor must be finite and non-negative, got " + k);
        return new Color(Rgb.product(r, k), Rgb.product(g, k), Rgb.product(b, k), true);
    }

    /**
     * Per-channel scaling: how a coefficient such as kD or kT filters light colour by colour.
     *
     * @param k the factor of each channel, each finite and ≥ 0
     * @return (r·k1, g·k2, b·k3)
     * @throws IllegalArgumentException for a negative or non-finite factor, naming the triple
     */
    public Color scale(Double3 k) {
        if (!(k.d1 >= 0) || !(k.d2 >= 0) || !(k.d3 >= 0)
                || Double.isInfinite(k.d1) || Double.isInfinite(k.d2) || Double.isInfinite(k.d3))
            throw new IllegalArgumentException("colour scale factors must be finite and non-negative, got " + k);
        return new Color(Rgb.product(r, k.d1), Rgb.product(g, k.d2), Rgb.product(b, k.d3), true);
    }

    /**
     * @param k the divisor of all three channels, &gt; 0 (the number of samples averaged)
     * @return this colour divided by {@code k}
     * @throws IllegalArgumentException when {@code k} is not positive, naming it
     */
    public Color reduce(int k) {
        if (k <= 0) throw new IllegalArgumentException("colour reduce factor must be positive, got " + k);
        return new Color(Rgb.quotient(r, k), Rgb.quotient(g, k), Rgb.quotient(b, k), true);
    }

    /**
     * Divides every channel by a positive real: the average of a weighted sum.
     *
     * @param k the divisor, finite and &gt; 0
     * @return this colour divided by {@code k}
     * @throws IllegalArgumentException when {@code k} is not a positive finite number, naming it
     */
    public Color reduce(double k) {
        if (!(k > 0) || Double.isInfinite(k))
            throw new IllegalArgumentException("colour reduce factor must be a positive finite number, got " + k);
        return new Color(Rgb.quotient(r, k), Rgb.quotient(g, k), Rgb.quotient(b, k), true);
    }

    /**
     * The largest per-channel absolute difference, on the 0..255 scale: the measure adaptive
     * anti-aliasing compares against its threshold.
     *
     * @param other the colour to compare with
     * @return max(|Δr|, |Δg|, |Δb|), ≥ 0; 0 for equal colours
     */
    public double distance(Color other) {
        return Math.max(Math.abs(r - other.r), Math.max(Math.abs(g - other.g), Math.abs(b - other.b)));
    }

    /**
     * The 2025–26 course's equality, kept for students' tests ({@code assertEquals} of colours):
     * each channel equal within the library's zero tolerance ({@link Util#isZero(double)}, about
     * 9e-13), as the course compares its colours' {@code Double3}. A tolerance makes it not
     * transitive (a ≈ b and b ≈ c do not give a ≈ c), so the library never relies on it: it
     * compares colours with {@link #distance(Color)}.
     *
     * @param obj the object to compare with
     * @return true for a colour whose three channels are each within the tolerance of this one's
     */
    @Override
    public boolean equals(Object obj) {
        if (this == obj) return true;
        return obj instanceof Color other && Util.isZero(r - other.r) && Util.isZero(g - other.g) && Util.isZero(b - other.b);
    }

    /**
     * Constant, as {@link Point#hashCode()} and {@link Double3#hashCode()}: the only hash
     * consistent with a tolerant {@link #equals(Object)} for every pair of colours (any finer one,
     * a rounded channel say, splits two equal colours on either side of a rounding step). Hashed
     * collections of colours work, slowly; nothing in the library hashes colours.
     *
     * @return the same number for every colour
     */
    @Override
    public int hashCode() {
        return 11;
    }

    @Override
    public String toString() {
        return "rgb:(" + r + "," + g + "," + b + ")";
    }
}
