package renderer.junit;

import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.function.IntBinaryOperator;

import javax.imageio.ImageIO;

import renderer.ImageWriter;

/**
 * An image as OpenImageIO's {@code ImageBuf.read(convert=FLOAT)} holds it: {@code channels}
 * floats per pixel, row after row, each on the 0..1 scale. An 8-bit value v becomes
 * {@code v · (float) (1/255)} (OpenImageIO's conversion, bit for bit), a 16-bit one
 * {@code v · (float) (1/65535)}; a palette image is expanded to RGB (RGBA with a transparent
 * entry), as OpenImageIO's PNG reader expands it.
 *
 * @param width    columns
 * @param height   rows
 * @param channels values per pixel: 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA
 * @param values   {@code width · height · channels} values, row-major, channels innermost
 */
record Picture(int width, int height, int channels, float[] values) {
    private static final float BYTE_SCALE = (float) (1.0 / 255);

    /** Thrown by {@link #read} with a message fit for an assertion failure. */
    static final class UnreadableException extends Exception {
        private static final long serialVersionUID = 1L;

        UnreadableException(String message) {
            super(message, null, false, false);
        }
    }

    /** @return the render held by {@code image}: RGB, as its PNG would hold it */
    static Picture of(ImageWriter image) {
        return packed(image.getNx(), image.getNy(), false, image::getRgb);
    }

    /**
     * @param png  the file
     * @param role what the file is ("render", "reference"), for the message
     * @return its pixels
     * @throws UnreadableException naming the file and the reason when it is missing or is no image
     *                             javax.imageio can read
     */
    static Picture read(Path png, String role) throws UnreadableException {
        BufferedImage image;
        try (InputStream in = Files.newInputStream(png)) {
            image = ImageIO.read(in);
        } catch (NoSuchFileException e) {
            throw new UnreadableException("cannot read " + role + " " + png + ": no such file");
        } catch (IOException | RuntimeException e) {
            // javax.imageio reports a damaged file as IIOException, and some as runtime exceptions.
            throw new UnreadableException("cannot read " + role + " " + png + ": " + reason(e));
        }
        if (image == null) throw new UnreadableException("cannot read " + role + " " + png + ": not an image javax.imageio can read");
        return image.getColorModel() instanceof IndexColorModel palette && !isGreyRamp(palette) ? expand(image, palette)
                : samples(image.getRaster());
    }

    private static String reason(Throwable e) {
        String text = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        Throwable cause = e.getCause();
        return cause != null && cause.getMessage() != null && !text.contains(cause.getMessage()) ? text + " (" + cause.getMessage() + ")"
                : text;
    }

    /**
     * javax.imageio reads a 1-, 2- or 4-bit grey PNG as a palette of evenly spaced greys;
     * OpenImageIO reads it as one grey channel, scaled to 0..1 by its bit depth, as here.
     */
    private static boolean isGreyRamp(IndexColorModel palette) {
        int size = palette.getMapSize();
        if (palette.hasAlpha() || size < 2 || Integer.bitCount(size) != 1) return false;
        for (int i = 0; i < size; ++i) {
            int grey = i * 255 / (size - 1);
            if (palette.getRed(i) != grey || palette.getGreen(i) != grey || palette.getBlue(i) != grey) return false;
        }
        return true;
    }

    /**
     * Every band of the raster, scaled by its own bit depth; values of fewer than 8 bits are first
     * widened to 8 (as libpng widens them for OpenImageIO), so they convert like 8-bit ones.
     */
    private static Picture samples(Raster raster) {
        int w = raster.getWidth(), h = raster.getHeight(), n = raster.getNumBands();
        int[] bits = raster.getSampleModel().getSampleSize();
        float[] v = new float[w * h * n];
        for (int y = 0, i = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int b = 0; b < n; ++b) {
                    int sample = raster.getSample(x, y, b);
                    v[i++] = bits[b] > 8 ? sample * (float) (1.0 / ((1L << bits[b]) - 1))
                            : (bits[b] == 8 ? sample : sample * 255 / ((1 << bits[b]) - 1)) * BYTE_SCALE;
                }
        return new Picture(w, h, n, v);
    }

    private static Picture expand(BufferedImage image, IndexColorModel palette) {
        return packed(image.getWidth(), image.getHeight(), palette.hasAlpha(), image::getRGB);
    }

    /** The pixels of packed 0xAARRGGBB values, {@code argbAt(x, y)}: RGB, or RGBA with {@code alpha}. */
    private static Picture packed(int w, int h, boolean alpha, IntBinaryOperator argbAt) {
        int n = alpha ? 4 : 3;
        float[] v = new float[w * h * n];
        for (int y = 0, i = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                int argb = argbAt.applyAsInt(x, y);
                v[i++] = ((argb >> 16) & 0xFF) * BYTE_SCALE;
                v[i++] = ((argb >> 8) & 0xFF) * BYTE_SCALE;
                v[i++] = (argb & 0xFF) * BYTE_SCALE;
                if (n == 4) v[i++] = (argb >>> 24) * BYTE_SCALE;
            }
        return new Picture(w, h, n, v);
    }

    /** @return "100x80, 3 channels (RGB)" */
    String describe() {
        String layout = switch (channels) {
            case 1 -> "Y";
            case 2 -> "YA";
            case 3 -> "RGB";
            case 4 -> "RGBA";
            default -> "?";
        };
        return width + "x" + height + ", " + channels + " channel" + (channels == 1 ? "" : "s") + " (" + layout + ")";
    }
}
