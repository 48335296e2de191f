package renderer.effects;

import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;

/**
 * Measurements on rendered images: brightness profiles across an edge (averaged along the edge
 * to beat sampling noise) and their 10 %–90 % width; and the top-down camera most of these
 * tests look through.
 */
final class Profiles {
    /** Pixels per scene unit on the floor y = 0 seen by {@link #topDown()}. */
    static final double PIXELS_PER_UNIT = 5;
    /** The side of the square image {@link #topDown()} is meant for. */
    static final int SIZE = 200;

    private Profiles() {
    }

    /**
     * A camera 100 units above the origin looking straight down (−y), with −z up in the image and
     * +x to the right, seeing the square x, z ∈ [−20, 20] of the floor y = 0 in a 200 × 200 image:
     * column = 5·(x + 20), row = 5·(z + 20).
     */
    static Camera.Builder topDown() {
        return Camera.getBuilder().setLocation(new Point(0, 100, 0))
                .setDirection(new Vector(0, -1, 0), new Vector(0, 0, -1))
                .setVpSize(40, 40).setVpDistance(100).setSummary(false);
    }

    /** @return the floor's x (or z) coordinate of the centre of column (or row) {@code pixel} of {@link #topDown()} */
    static double floorCoordinate(int pixel) {
        return (pixel + 0.5) / PIXELS_PER_UNIT - 20;
    }

    /** @return the mean of the three channels of pixel (x, y), 0..255 */
    static double luma(ImageWriter image, int x, int y) {
        int rgb = image.getRgb(x, y);
        return (((rgb >> 16) & 0xFF) + ((rgb >> 8) & 0xFF) + (rgb & 0xFF)) / 3.0;
    }

    /** The brightness along a row direction: for each column, the mean over rows [y0, y1). */
    static double[] alongX(ImageWriter image, int y0, int y1) {
        double[] profile = new double[image.getNx()];
        for (int x = 0; x < profile.length; ++x) {
            double sum = 0;
            for (int y = y0; y < y1; ++y) sum += luma(image, x, y);
            profile[x] = sum / (y1 - y0);
        }
        return profile;
    }

    /** The brightness down a column direction: for each row, the mean over columns [x0, x1). */
    static double[] alongY(ImageWriter image, int x0, int x1) {
        double[] profile = new double[image.getNy()];
        for (int y = 0; y < profile.length; ++y) {
            double sum = 0;
            for (int x = x0; x < x1; ++x) sum += luma(image, x, y);
            profile[y] = sum / (x1 - x0);
        }
        return profile;
    }

    /**
     * The 10 %–90 % width of the one edge in {@code profile}, in samples: the number of samples
     * whose value lies between 10 % and 90 % of the way from the low plateau to the high one
     * (each plateau the mean of the 5 samples at that end). Counting instead of locating
     * crossings keeps the measure stable when noise makes the profile not quite monotonic; for
     * a monotonic profile it is the distance between the crossings, rounded.
     */
    static int edgeWidth(double[] profile) {
        double first = mean(profile, 0, 5), last = mean(profile, profile.length - 5, profile.length);
        double low = Math.min(first, last), high = Math.max(first, last);
        double l10 = low + 0.1 * (high - low), l90 = low + 0.9 * (high - low);
        int count = 0;
        for (double v : profile)
            if (v >= l10 && v < l90) ++count;
        return count;
    }

    /** @return the mean of {@code values[from, to)} */
    static double mean(double[] values, int from, int to) {
        double sum = 0;
        for (int i = from; i < to; ++i) sum += values[i];
        return sum / (to - from);
    }

    /** @return every pixel of the image, row-major, as 0xRRGGBB */
    static int[] pixels(ImageWriter image) {
        int[] all = new int[image.getNx() * image.getNy()];
        for (int y = 0; y < image.getNy(); ++y)
            for (int x = 0; x < image.getNx(); ++x) all[y * image.getNx() + x] = image.getRgb(x, y);
        return all;
    }
}
