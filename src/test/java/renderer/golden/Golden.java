package renderer.golden;

import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;

/**
 * Shared plumbing of the golden render suite: where its images go, the view of a test, and
 * probes that read pixels back.
 *
 * <p>Golden images are written to {@code target/test-run/images/golden/golden-<what>.png}, a folder of their
 * own: {@code scripts/verify_images.py --renders target/test-run/images/golden} then compares exactly this suite
 * with {@code images/reference/}, whatever other tests write into {@code images/}.
 */
final class Golden {
    /** The sub-folder of images/ the suite writes into (see the class comment). */
    static final String FOLDER = "golden/";

    private Golden() {
    }

    /** @return an image writer for target/test-run/images/golden/golden-&lt;what&gt;.png */
    static ImageWriter image(String what, int nX, int nY) {
        return new ImageWriter(FOLDER + "golden-" + what, nX, nY);
    }

    /** @return 0..255 red channel of a packed 0xRRGGBB pixel */
    static int red(int rgb) {
        return (rgb >> 16) & 0xFF;
    }

    static int green(int rgb) {
        return (rgb >> 8) & 0xFF;
    }

    static int blue(int rgb) {
        return rgb & 0xFF;
    }

    /** @return the mean of the three channels, 0..255 */
    static double luma(int rgb) {
        return (red(rgb) + green(rgb) + blue(rgb)) / 3.0;
    }

    /** @return the mean of the three channels of the pixel at (column, row) {@code at}, 0..255 */
    static double lumaAt(ImageWriter image, int[] at) {
        return luma(image.getRgb(at[0], at[1]));
    }

    /** @return the pixel as "(r,g,b)", for failure messages */
    static String rgb(int rgb) {
        return "(" + red(rgb) + "," + green(rgb) + "," + blue(rgb) + ")";
    }

    /**
     * Asserts that pixel {@code at} (column, row) is (r, g, b), each channel within
     * {@code tolerance} (0..255 steps).
     */
    static void assertPixel(ImageWriter image, int[] at, int r, int g, int b, int tolerance, String what) {
        int actual = image.getRgb(at[0], at[1]);
        boolean close = Math.abs(red(actual) - r) <= tolerance && Math.abs(green(actual) - g) <= tolerance
                && Math.abs(blue(actual) - b) <= tolerance;
        if (!close)
            throw new AssertionError(what + ": pixel (" + at[0] + "," + at[1] + ") of " + image.getImageName() + " is "
                    + rgb(actual) + ", expected (" + r + "," + g + "," + b + ") within " + tolerance);
    }

    /** @return every pixel of the image, row-major, as 0xRRGGBB */
    static int[] pixels(ImageWriter image) {
        int[] all = new int[image.getNx() * image.getNy()];
        for (int y = 0; y < image.getNy(); ++y)
            for (int x = 0; x < image.getNx(); ++x) all[y * image.getNx() + x] = image.getRgb(x, y);
        return all;
    }

    /**
     * A camera standing at {@code location}, looking at {@code target} with +y up, through a
     * square view plane of side {@code vpSize} at {@code vpDistance}. It knows where a scene
     * point lands in the image by plain projection (computed here, not by the camera), so tests
     * can probe the pixel that shows a given point.
     */
    record View(Point location, Point target, double vpSize, double vpDistance) {
        /** @return a builder with this view and the summary line off (tests stay quiet) */
        Camera.Builder builder() {
            return Camera.getBuilder().setLocation(location).setDirection(target, Vector.AXIS_Y)
                    .setVpSize(vpSize, vpSize).setVpDistance(vpDistance).setSummary(false);
        }

        /**
         * The pixel (column, row) of an {@code n × n} image whose area contains the projection of
         * {@code p}: the view direction {@code to}, {@code right = to × up}, the image's up
         * {@code right × to}; the point's offsets on the view plane, scaled by {@code vpDistance}
         * over its depth, measured in pixels from the image centre.
         */
        int[] pixelOf(Point p, int n) {
            Vector to = target.subtract(location).normalize();
            Vector right = to.crossProduct(Vector.AXIS_Y).normalize();
            Vector up = right.crossProduct(to).normalize();
            Vector d = p.subtract(location);
            double scale = vpDistance / d.dotProduct(to);
            double pixel = vpSize / n;
            int column = (int) Math.floor(d.dotProduct(right) * scale / pixel + n / 2.0);
            int row = (int) Math.floor(-d.dotProduct(up) * scale / pixel + n / 2.0);
            if (column < 0 || column >= n || row < 0 || row >= n)
                throw new IllegalArgumentException(p + " projects to pixel (" + column + "," + row
                        + ") outside the " + n + "x" + n + " image: fix the test's scene or view");
            return new int[] { column, row };
        }
    }

    /** Where the line from a light at {@code light} through {@code p} meets the floor y = 0. */
    static Point onFloor(Point light, Point p) {
        Vector d = p.subtract(light);
        return light.add(d.scale(light.getY() / -d.getY()));
    }

    /**
     * The number of pixels strictly inside the 10 %–90 % part of the brightness transition along
     * row {@code row} from column {@code from} (one side of an edge) to column {@code to} (the
     * other side): 0 or 1 for a sharp edge, more for a blurred one.
     */
    static int transitionWidth(ImageWriter image, int row, int from, int to) {
        double a = luma(image.getRgb(from, row)), b = luma(image.getRgb(to, row));
        double low = Math.min(a, b) + 0.1 * Math.abs(b - a), high = Math.max(a, b) - 0.1 * Math.abs(b - a);
        int step = from < to ? 1 : -1, count = 0;
        for (int x = from; x != to + step; x += step) {
            double v = luma(image.getRgb(x, row));
            if (v > low && v < high) ++count;
        }
        return count;
    }
}
