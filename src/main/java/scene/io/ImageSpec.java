package scene.io;

import java.util.StringJoiner;

import renderer.ImageWriter;
import renderer.ImageWriters;

/**
 * The image: its name (images/&lt;name&gt;.png) and its size in pixels (stated together),
 * each checked when stated.
 *
 * <p>A part of {@link RenderSettings}: a component is null where it states nothing.
 *
 * @param name   the image's name
 * @param width  its width in pixels
 * @param height its height in pixels
 * @serial exclude
 */
public record ImageSpec(String name, Integer width, Integer height) implements java.io.Serializable {
    static final ImageSpec NONE = new ImageSpec(null, null, null);

    /**
     * @param name   the image's name
     * @param width  its width in pixels
     * @param height its height in pixels
     * @throws IllegalArgumentException for a name or a size the image writer refuses, naming it
     */
    public ImageSpec {
        if (name != null) ImageWriters.requireFileName(name);
        if ((width == null) != (height == null)) throw new IllegalArgumentException("width and height are stated together");
        if (width != null) requireSize(width, height);
    }

    ImageSpec then(ImageSpec later) {
        return new ImageSpec(Stated.or(later.name, name), later.width != null ? later.width : width,
                later.width != null ? later.height : height);
    }

    void describe(StringJoiner out) {
        if (name != null || width != null)
            out.add("image=" + (name != null ? name : "") + (width != null ? " " + width + "x" + height : ""));
    }

    /** Each side at least 1 and at most {@link ImageWriter#MAX_PIXELS} pixels in all, naming the size. */
    private static void requireSize(int width, int height) {
        if (width < 1 || height < 1)
            throw new IllegalArgumentException("image size must be at least 1x1, got " + width + "x" + height);
        long pixels = (long) width * height;
        if (pixels > ImageWriter.MAX_PIXELS)
            throw new IllegalArgumentException("image size " + width + "x" + height + " is " + pixels
                    + " pixels, more than an image can hold (" + ImageWriter.MAX_PIXELS + ")");
    }
}
