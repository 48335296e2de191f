package renderer.junit;

/**
 * How far a render may stray from its reference, on the 0..1 scale of a channel (one 8-bit step
 * is 1/255 ≈ 0.0039): the limits of {@code scripts/verify_images.py} and of OpenImageIO's
 * {@code idiff}, under the same names as its {@code thresholds.json} keys.
 * <ul>
 * <li>A pixel <em>fails</em> when some channel differs by more than {@code failThreshold}; the
 * image fails when more than {@code failPercent} % of its pixels fail, or when any channel of any
 * pixel differs by more than {@code hardFail}.
 * <li>A pixel <em>warns</em> above {@code warnThreshold}; more than {@code warnPercent} % of
 * warning pixels give a passing image a warning, nothing more.
 * </ul>
 *
 * @param failThreshold a pixel fails above this difference ({@code failthresh}), default 0.004
 * @param failPercent   the image fails when more than this percentage of its pixels fail
 *                      ({@code failpercent}), default 0.02
 * @param hardFail      the image fails when any difference exceeds this ({@code hardfail}), default
 *                      0.012
 * @param warnThreshold a pixel warns above this difference ({@code warnthresh}), default 0.008
 * @param warnPercent   a passing image gets a warning when more than this percentage of its pixels
 *                      warn ({@code warnpercent}), default 0.02
 */
public record ImageThresholds(double failThreshold, double failPercent, double hardFail, double warnThreshold,
                              double warnPercent) {
    /** The defaults of {@code images/reference/thresholds.json}: OpenImageIO's own test suite's. */
    public static final ImageThresholds DEFAULTS = new ImageThresholds(0.004, 0.02, 0.012, 0.008, 0.02);

    /**
     * Checks every limit, as the verification script checks its thresholds file.
     *
     * @param failThreshold a pixel fails above this difference
     * @param failPercent   the image fails when more than this percentage of its pixels fail, 0..100
     * @param hardFail      the image fails when any difference exceeds this
     * @param warnThreshold a pixel warns above this difference
     * @param warnPercent   a passing image warns when more than this percentage of its pixels warn, 0..100
     * @throws IllegalArgumentException naming the limit when it is negative or not finite, or when a
     *                                  percentage exceeds 100
     */
    public ImageThresholds {
        check("failThreshold", failThreshold, false);
        check("failPercent", failPercent, true);
        check("hardFail", hardFail, false);
        check("warnThreshold", warnThreshold, false);
        check("warnPercent", warnPercent, true);
    }

    private static void check(String name, double value, boolean percent) {
        if (!Double.isFinite(value) || value < 0)
            throw new IllegalArgumentException(name + " must be a finite number >= 0, got " + value);
        if (percent && value > 100) throw new IllegalArgumentException(name + " is a percentage (0..100), got " + value);
    }

    /**
     * @param value the new {@code failThreshold}
     * @return these limits with that one changed
     * @throws IllegalArgumentException when it is negative or not finite
     */
    public ImageThresholds withFailThreshold(double value) {
        return new ImageThresholds(value, failPercent, hardFail, warnThreshold, warnPercent);
    }

    /**
     * @param value the new {@code failPercent}, 0..100
     * @return these limits with that one changed
     * @throws IllegalArgumentException when it is outside 0..100
     */
    public ImageThresholds withFailPercent(double value) {
        return new ImageThresholds(failThreshold, value, hardFail, warnThreshold, warnPercent);
    }

    /**
     * @param value the new {@code hardFail}
     * @return these limits with that one changed
     * @throws IllegalArgumentException when it is negative or not finite
     */
    public ImageThresholds withHardFail(double value) {
        return new ImageThresholds(failThreshold, failPercent, value, warnThreshold, warnPercent);
    }

    /**
     * @param value the new {@code warnThreshold}
     * @return these limits with that one changed
     * @throws IllegalArgumentException when it is negative or not finite
     */
    public ImageThresholds withWarnThreshold(double value) {
        return new ImageThresholds(failThreshold, failPercent, hardFail, value, warnPercent);
    }

    /**
     * @param value the new {@code warnPercent}, 0..100
     * @return these limits with that one changed
     * @throws IllegalArgumentException when it is outside 0..100
     */
    public ImageThresholds withWarnPercent(double value) {
        return new ImageThresholds(failThreshold, failPercent, hardFail, warnThreshold, value);
    }
}
