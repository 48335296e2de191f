package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import org.assertj.core.api.SoftAssertions;

/**
 * Reading and comparing rendered pixels in tests. Pixels are 0xRRGGBB ints as {@link ImageWriter}
 * stores them; channels are on the 0..255 scale.
 */
final class Pixels {
    private Pixels() {
    }

    static int red(int rgb) {
        return (rgb >> 16) & 0xFF;
    }

    static int green(int rgb) {
        return (rgb >> 8) & 0xFF;
    }

    static int blue(int rgb) {
        return rgb & 0xFF;
    }

    /** @return every pixel, row-major (index y·nX + x) */
    static int[] of(ImageWriter image) {
        int nX = image.getNx(), nY = image.getNy();
        int[] p = new int[nX * nY];
        for (int y = 0; y < nY; ++y)
            for (int x = 0; x < nX; ++x) p[y * nX + x] = image.getRgb(x, y);
        return p;
    }

    /** Root-mean-square difference over every channel of every pixel, on the 0..255 scale. */
    static double rmse(ImageWriter a, ImageWriter b) {
        int[] pa = of(a), pb = of(b);
        assertThat(pa).hasSameSizeAs(pb);
        double sum = 0;
        for (int i = 0; i < pa.length; ++i) {
            double dr = red(pa[i]) - red(pb[i]), dg = green(pa[i]) - green(pb[i]), db = blue(pa[i]) - blue(pb[i]);
            sum += dr * dr + dg * dg + db * db;
        }
        return Math.sqrt(sum / (3.0 * pa.length));
    }

    /**
     * Asserts that pixel (x, y) holds the colour (r, g, b) worked out by hand. The image stores
     * each channel clamped to 255 and truncated to an integer; the exact value is allowed a
     * rounding error of 1e-6, so that 127.9999999 (a hand-computed 128) may land on 127.
     */
    static void assertPixel(ImageWriter image, int x, int y, double r, double g, double b) {
        int rgb = image.getRgb(x, y);
        String where = "pixel (" + x + "," + y + ") = #" + String.format("%06x", rgb) + " expected ("
                + r + ", " + g + ", " + b + ")";
        SoftAssertions soft = new SoftAssertions();
        soft.assertThat(red(rgb)).as(where + ": red").isBetween(stored(r - EPS), stored(r + EPS));
        soft.assertThat(green(rgb)).as(where + ": green").isBetween(stored(g - EPS), stored(g + EPS));
        soft.assertThat(blue(rgb)).as(where + ": blue").isBetween(stored(b - EPS), stored(b + EPS));
        soft.assertAll();
    }

    private static final double EPS = 1e-6;

    /** How the image stores an exact channel value. */
    private static int stored(double c) {
        return c >= 255 ? 255 : c <= 0 ? 0 : (int) c;
    }
}
