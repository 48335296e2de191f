package renderer.junit;

import java.nio.file.Path;

import renderer.ImageWriter;
import renderer.ImageWriters;

/**
 * The two pictures of a failed comparison, drawn as {@code scripts/verify_images.py} draws them:
 * <ul>
 * <li>the diff: the absolute difference × 20 (one or two 8-bit steps become visible), alpha
 * left out;
 * <li>the heat map: the worst channel's difference per pixel, black (none) → blue
 * ({@code failThreshold}) → red ({@code hardFail}) → yellow (0.25) → white (1.0).
 * </ul>
 */
final class DiffImages {
    /** The diff image's gain. */
    static final float DIFF_GAIN = 20;
    private static final double[][] HEAT_COLOURS = { { 0, 0, 0 }, { 0, 0, 1 }, { 1, 0, 0 }, { 1, 1, 0 }, { 1, 1, 1 } };
    private static final double HEAT_YELLOW = 0.25, HEAT_WHITE = 1.0;

    private DiffImages() {
    }

    /**
     * Writes both pictures (atomically, creating folders) for two pictures of one shape.
     *
     * @throws java.io.UncheckedIOException naming the file that cannot be written
     */
    static void write(Picture render, Picture reference, ImageThresholds t, Path diff, Path heat) {
        int w = render.width(), h = render.height(), n = render.channels();
        boolean alpha = n == 2 || n == 4;
        int colours = alpha ? n - 1 : n;
        double[] stops = heatStops(t);
        int[] diffRgb = new int[w * h], heatRgb = new int[w * h];
        float[] a = render.values(), b = reference.values();
        for (int p = 0; p < w * h; ++p) {
            int[] rgb = new int[3];
            float worst = 0;
            for (int c = 0; c < n; ++c) {
                float d = Math.abs(a[p * n + c] - b[p * n + c]);
                worst = Math.max(worst, d);
                if (c < colours) rgb[Math.min(c, 2)] = toByte(Math.min(1f, d * DIFF_GAIN));
            }
            if (colours == 1) rgb[1] = rgb[2] = rgb[0];
            diffRgb[p] = rgb[0] << 16 | rgb[1] << 8 | rgb[2];
            int heatPixel = 0;
            for (int k = 0; k < 3; ++k) heatPixel = heatPixel << 8 | toByte((float) interpolate(worst, stops, k));
            heatRgb[p] = heatPixel;
        }
        writePng(w, h, diffRgb, diff);
        writePng(w, h, heatRgb, heat);
    }

    private static void writePng(int w, int h, int[] rgb, Path file) {
        ImageWriter image = new ImageWriter(w, h);
        ImageWriters.writeTile(image, 0, 0, w, h, rgb);
        image.writeToImage(file);
    }

    /** OpenImageIO's float to 8-bit conversion: round half up, clamped. */
    private static int toByte(float v) {
        return (int) Math.max(0, Math.min(255, v * 255 + 0.5f));
    }

    /** The ramp's stops, strictly increasing even when loose limits put hardFail past 0.25. */
    static double[] heatStops(ImageThresholds t) {
        double[] x = { 0, t.failThreshold(), t.hardFail(), HEAT_YELLOW, HEAT_WHITE };
        for (int i = 1; i < x.length; ++i) x[i] = Math.max(x[i], x[i - 1] + 1e-6);
        return x;
    }

    /** numpy's {@code interp}: linear between stops, the end colours beyond them. */
    private static double interpolate(double error, double[] stops, int channel) {
        if (error <= stops[0]) return HEAT_COLOURS[0][channel];
        for (int i = 1; i < stops.length; ++i)
            if (error <= stops[i]) {
                double s = (error - stops[i - 1]) / (stops[i] - stops[i - 1]);
                return HEAT_COLOURS[i - 1][channel] + s * (HEAT_COLOURS[i][channel] - HEAT_COLOURS[i - 1][channel]);
            }
        return HEAT_COLOURS[stops.length - 1][channel];
    }
}
