package primitives;

/**
 * Internal: the renderer's accumulator, not course API (scenes and tests use {@link Color}). Three
 * doubles changed in place (a colour on the 0..255 scale, or a per-channel coefficient such as a
 * path's product of kR and kT), so that shading a ray allocates nothing: the renderer keeps a few
 * per recursion level and per worker and reuses them for every ray.
 *
 * <p>The per-channel arithmetic lives here once, in the static kernels below, and {@link Color}
 * and {@link Double3} compute with the same kernels: an accumulation done here in place has the
 * bits the same accumulation by {@code Color} and {@code Double3} objects would have, and a change
 * of rounding (a fused multiply-add, say) is made in one place for all three. Every method applies
 * its kernel to the red, green and blue channels in turn; methods named after an operation
 * ({@code add}, {@code scale}, …) change this value and return it, for chaining.
 *
 * @hidden internal: public only for the renderer's shading in package {@code renderer}; a scene test
 *         works with {@link Color}
 */
public final class Rgb {
    private double r;
    private double g;
    private double b;

    /** Black: (0, 0, 0). */
    public Rgb() {
    }

    // The kernels: one channel each. Color, Double3 and the methods below call nothing else for
    // these operations, so their results agree bit for bit.

    /** @return a + b */
    static double sum(double a, double b) {
        return a + b;
    }

    /** @return a · b */
    static double product(double a, double b) {
        return a * b;
    }

    /** @return a / b */
    static double quotient(double a, double b) {
        return a / b;
    }

    /** @return acc + a · b, rounded twice (the product, then the sum): not a fused multiply-add */
    static double sumOfProduct(double acc, double a, double b) {
        return acc + a * b;
    }

    /** @return whether each of a, b, c is strictly below {@code bound} */
    static boolean allBelow(double a, double b, double c, double bound) {
        return a < bound && b < bound && c < bound;
    }

    /** @return whether each of a, b, c is exactly zero (either sign) */
    static boolean allZero(double a, double b, double c) {
        return a == 0 && b == 0 && c == 0;
    }

    /** @return the red channel (or a coefficient's first component) */
    public double r() {
        return r;
    }

    /** @return the green channel (or a coefficient's second component) */
    public double g() {
        return g;
    }

    /** @return the blue channel (or a coefficient's third component) */
    public double b() {
        return b;
    }

    /**
     * @param r the new red channel
     * @param g the new green channel
     * @param b the new blue channel
     * @return this value
     */
    public Rgb set(double r, double g, double b) {
        this.r = r;
        this.g = g;
        this.b = b;
        return this;
    }

    /** @return this value, set to (0, 0, 0) */
    public Rgb setZero() {
        return set(0, 0, 0);
    }

    /**
     * @param c a colour
     * @return this value, set to its channels
     */
    public Rgb set(Color c) {
        return set(c.getR(), c.getG(), c.getB());
    }

    /**
     * @param k a coefficient triple
     * @return this value, set to its components
     */
    public Rgb set(Double3 k) {
        return set(k.d1, k.d2, k.d3);
    }

    /**
     * @param a the first factor
     * @param k the second factor
     * @return this value, set to a · k per channel
     */
    public Rgb setProduct(Rgb a, Rgb k) {
        return set(product(a.r, k.r), product(a.g, k.g), product(a.b, k.b));
    }

    /**
     * @param k a coefficient triple
     * @param s the factor of every component
     * @return this value, set to k · s per channel
     */
    public Rgb setScaled(Double3 k, double s) {
        return set(product(k.d1, s), product(k.d2, s), product(k.d3, s));
    }

    /**
     * @param o the value to add
     * @return this value plus {@code o}, per channel
     */
    public Rgb add(Rgb o) {
        return set(sum(r, o.r), sum(g, o.g), sum(b, o.b));
    }

    /**
     * @param a the value to add, scaled
     * @param s its factor
     * @return this value plus a · s, per channel
     */
    public Rgb addScaled(Rgb a, double s) {
        return set(sumOfProduct(r, a.r, s), sumOfProduct(g, a.g, s), sumOfProduct(b, a.b, s));
    }

    /**
     * @param k the triple to add, scaled
     * @param s its factor
     * @return this value plus k · s, per channel
     */
    public Rgb addScaled(Double3 k, double s) {
        return set(sumOfProduct(r, k.d1, s), sumOfProduct(g, k.d2, s), sumOfProduct(b, k.d3, s));
    }

    /**
     * @param a the first factor
     * @param k the second factor
     * @return this value plus a · k, per channel
     */
    public Rgb addProduct(Rgb a, Rgb k) {
        return set(sumOfProduct(r, a.r, k.r), sumOfProduct(g, a.g, k.g), sumOfProduct(b, a.b, k.b));
    }

    /**
     * @param c a colour
     * @param k its coefficient (an ambient light's intensity and a material's kA, say)
     * @return this value plus c · k, per channel
     */
    public Rgb addProduct(Color c, Double3 k) {
        return set(sumOfProduct(r, c.getR(), k.d1), sumOfProduct(g, c.getG(), k.d2), sumOfProduct(b, c.getB(), k.d3));
    }

    /**
     * Adds a product of three factors, associated as (a · b) · c in every channel.
     *
     * @param a the first factor
     * @param k the second factor
     * @param f the third factor
     * @return this value plus (a · k) · f, per channel
     */
    public Rgb addProduct(Rgb a, Rgb k, Rgb f) {
        return set(sumOfProduct(r, product(a.r, k.r), f.r), sumOfProduct(g, product(a.g, k.g), f.g),
                sumOfProduct(b, product(a.b, k.b), f.b));
    }

    /**
     * @param s the factor of every channel
     * @return this value times {@code s}
     */
    public Rgb scale(double s) {
        return set(product(r, s), product(g, s), product(b, s));
    }

    /**
     * @param k the factor of each channel
     * @return this value times {@code k}, per channel
     */
    public Rgb scale(Double3 k) {
        return set(product(r, k.d1), product(g, k.d2), product(b, k.d3));
    }

    /**
     * @param n the divisor of every channel (the number of samples averaged)
     * @return this value divided by {@code n}
     */
    public Rgb reduce(double n) {
        return set(quotient(r, n), quotient(g, n), quotient(b, n));
    }

    /** @return whether every channel is exactly zero */
    public boolean isZero() {
        return allZero(r, g, b);
    }

    /**
     * @param bound the bound
     * @return whether every channel is strictly below {@code bound}
     */
    public boolean lowerThan(double bound) {
        return allBelow(r, g, b, bound);
    }

    /**
     * @param k     the other factor
     * @param bound the bound
     * @return whether this · k is strictly below {@code bound} in every channel
     */
    public boolean productLowerThan(Rgb k, double bound) {
        return allBelow(product(r, k.r), product(g, k.g), product(b, k.b), bound);
    }

    /**
     * @param k the other factor
     * @return whether this · k is exactly zero in every channel
     */
    public boolean productIsZero(Rgb k) {
        return allZero(product(r, k.r), product(g, k.g), product(b, k.b));
    }

    /**
     * @return this value as a colour
     * @throws IllegalArgumentException for a negative or non-finite channel, as
     *                                  {@link Color#Color(double, double, double)}
     */
    public Color toColor() {
        return new Color(r, g, b);
    }

    /** @return this colour packed as 0xRRGGBB, each channel clamped to 0..255, as {@link Color#toRgb()} */
    public int packed() {
        return Color.toRgb(r, g, b);
    }

    @Override
    public String toString() {
        return "rgb:(" + r + "," + g + "," + b + ")";
    }
}
