package renderer.junit;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The verdict on a render against its reference, by the rules of {@code scripts/verify_images.py}:
 * OpenImageIO's {@code ImageBufAlgo.compare} figures, then the script's pass / warn / fail logic.
 *
 * @param status  the verdict
 * @param metrics the comparison's figures; null when the images could not be compared (size
 *                mismatch, unreadable or missing image)
 * @param message why it failed, the warning of a passing image, or "" for a clean pass
 */
record Comparison(Status status, Metrics metrics, String message) {

    /** The verdicts, named as the script's report names them ({@code WARN}: a PASS with a warning). */
    enum Status {
        PASS, WARN, FAIL, SIZE_MISMATCH, MISSING_REFERENCE, ERROR;

        /** @return the script's spelling: "SIZE-MISMATCH" */
        String label() {
            return name().replace('_', '-');
        }

        boolean failed() {
            return this != PASS && this != WARN;
        }
    }

    /**
     * {@code ImageBufAlgo.CompareResults}: differences are per channel, {@code |a − b|} in float,
     * accumulated in double in batches of 4096 pixels as OpenImageIO does.
     *
     * @param meanError  the mean difference over every channel of every pixel
     * @param maxError   the largest difference
     * @param maxX       its column (the first such pixel, row by row)
     * @param maxY       its row
     * @param maxChannel its channel
     * @param psnr       20·log10(peak / rmsError), peak 1 (or a larger value found); infinite for
     *                   identical images
     * @param rmsError   root-mean-square difference
     * @param failing    pixels with some channel above {@code failThreshold}
     * @param warning    pixels with some channel above {@code warnThreshold}
     * @param pixels     pixels compared
     */
    record Metrics(double meanError, double maxError, int maxX, int maxY, int maxChannel, double psnr, double rmsError,
                   long failing, long warning, long pixels) {
        private static final int BATCH = 4096;

        /** @return failing pixels as a percentage of all */
        double failPercent() {
            return pixels == 0 ? 0 : 100.0 * failing / pixels;
        }

        /** @return warning pixels as a percentage of all */
        double warnPercent() {
            return pixels == 0 ? 0 : 100.0 * warning / pixels;
        }

        /** Both pictures have the same width, height and channels. */
        static Metrics measure(Picture a, Picture b, ImageThresholds t) {
            float[] va = a.values(), vb = b.values();
            int n = a.channels(), w = a.width();
            long pixels = (long) w * a.height();
            // OpenImageIO takes the thresholds as float.
            float failThreshold = (float) t.failThreshold(), warnThreshold = (float) t.warnThreshold();
            double total = 0, totalSquares = 0, maxError = 0;
            int maxX = 0, maxY = 0, maxC = 0;
            long failing = 0, warning = 0;
            float peak = 1;
            for (int p = 0; p < pixels;) {
                double batch = 0, batchSquares = 0;
                for (int end = (int) Math.min(pixels, (long) p + BATCH); p < end; ++p) {
                    boolean failed = false, warned = false;
                    for (int c = 0, i = p * n; c < n; ++c, ++i) {
                        float x = va[i], y = vb[i];
                        peak = Math.max(peak, Math.max(Math.abs(x), Math.abs(y)));
                        double f = Math.abs(x - y);
                        batch += f;
                        batchSquares += f * f;
                        if (f > maxError) {
                            maxError = f;
                            maxX = p % w;
                            maxY = p / w;
                            maxC = c;
                        }
                        if (!warned && f > warnThreshold) {
                            ++warning;
                            warned = true;
                        }
                        if (!failed && f > failThreshold) {
                            ++failing;
                            failed = true;
                        }
                    }
                }
                total += batch;
                totalSquares += batchSquares;
            }
            long values = pixels * n;
            double rms = Math.sqrt(totalSquares / values);
            return new Metrics(total / values, maxError, maxX, maxY, maxC, 20 * Math.log10(peak / rms), rms, failing,
                    warning, pixels);
        }
    }

    /**
     * Compares {@code render} with {@code reference} under {@code t}, as the script's
     * {@code compare_pair} does once both images are read.
     *
     * @return SIZE_MISMATCH, FAIL, WARN or PASS
     */
    static Comparison of(Picture render, Picture reference, ImageThresholds t) {
        List<String> mismatch = new ArrayList<>();
        if (render.width() != reference.width() || render.height() != reference.height())
            mismatch.add("size differs: render " + render.width() + "x" + render.height() + ", reference " + reference.width()
                    + "x" + reference.height());
        if (render.channels() != reference.channels())
            mismatch.add("channel count differs: render " + render.describe() + ", reference " + reference.describe());
        if (!mismatch.isEmpty()) return new Comparison(Status.SIZE_MISMATCH, null, String.join("; ", mismatch));
        Metrics m = Metrics.measure(render, reference, t);
        List<String> reasons = new ArrayList<>();
        if (m.maxError() > t.hardFail())
            reasons.add("max error " + g(m.maxError(), 4) + " at (" + m.maxX() + "," + m.maxY() + ") channel " + m.maxChannel()
                    + " exceeds hardfail " + g(t.hardFail(), 6));
        if (m.failing() > t.failPercent() / 100.0 * m.pixels())
            reasons.add(String.format(Locale.ROOT, "%.3f%% of pixels (%d) differ by more than failthresh %s, allowed %s%%",
                    m.failPercent(), m.failing(), g(t.failThreshold(), 6), g(t.failPercent(), 6)));
        if (!reasons.isEmpty()) return new Comparison(Status.FAIL, m, String.join("; ", reasons));
        if (m.warning() > t.warnPercent() / 100.0 * m.pixels())
            return new Comparison(Status.WARN, m,
                    String.format(Locale.ROOT, "warning: %.3f%% of pixels differ by more than warnthresh %s (warnpercent %s%%)",
                            m.warnPercent(), g(t.warnThreshold(), 6), g(t.warnPercent(), 6)));
        return new Comparison(Status.PASS, m, "");
    }

    /** @return a comparison that could not look at pixels: a missing or unreadable image */
    static Comparison without(Status status, String message) {
        return new Comparison(status, null, message);
    }

    /** Python's {@code format(x, ".<digits>g")} for the plain numbers the messages show. */
    static String g(double x, int digits) {
        if (!Double.isFinite(x)) return Double.isNaN(x) ? "nan" : x > 0 ? "inf" : "-inf";
        if (x == 0) return "0";
        BigDecimal rounded = new BigDecimal(x).round(new MathContext(digits)).stripTrailingZeros();
        return rounded.toPlainString();
    }

    /** @return the PSNR in dB with one decimal, "inf" for identical images */
    static String psnr(double db) {
        return Double.isInfinite(db) ? "inf" : String.format(Locale.ROOT, "%.1f", db);
    }
}
