package scene.io;

import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;

import primitives.Color;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayBudget;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * How a scene file asks to be rendered: the image, the sampling, the tracer's extensions and the
 * execution. The defaults (see {@link #defaults(String)}) are the plain course render on all
 * cores. A command line overrides values with the {@code with…} methods and then
 * {@linkplain #applyTo(Camera.Builder, Scene, ImageWriter) applies} the result to a camera
 * builder. The image size is checked here, so that settings that exist can be rendered as far as
 * the pixel count goes: the image itself is allocated only when asked for.
 *
 * <p>Serializable (through the canonical constructor, so a deserialized copy is validated
 * again): a cluster's driver sends the settings it resolved to its executors.
 *
 * @serial exclude
 * @param imageName        the image's name: images/&lt;name&gt;.png unless told otherwise; a name,
 *                         not a path (see {@link #requireImageName(String)})
 * @param width            image width in pixels, at least 1
 * @param height           image height in pixels, at least 1; width × height at most
 *                         {@link #MAX_PIXELS}
 * @param gridInterval     a grid line every this many pixels over the image (the course's
 *                         {@code printGrid}); 0: no grid
 * @param gridColor        the grid lines' colour
 * @param antiAliasing     how pixels are sampled
 * @param aaColumns        RANDOM: jittered grid columns per pixel
 * @param aaRows           RANDOM: jittered grid rows per pixel
 * @param adaptiveDepth    ADAPTIVE: maximum subdivision depth (sub-pixels of 1/2^depth)
 * @param adaptiveThreshold ADAPTIVE: the colour difference (0..255 scale) that subdivides
 * @param focalDistance    depth of field: distance of the sharp plane along the view
 *                         direction; 0: pinhole camera (no depth of field)
 * @param aperture         depth of field: lens radius in scene units
 * @param dofSamples       depth of field: lens samples per pixel without anti-aliasing
 * @param threads          0: calling thread; n &gt; 0: n workers; -2: all cores
 * @param seed             the seed of every random number of the render
 * @param bvh              whether the tracer uses the bounding volume hierarchy
 * @param beamSize         rays per glossy or diffuse-glass beam
 * @param shadowSamples    shadow rays toward a light with a radius
 */
public record RenderSettings(String imageName, int width, int height, int gridInterval, Color gridColor,
                             AntiAliasing antiAliasing, int aaColumns, int aaRows, int adaptiveDepth,
                             double adaptiveThreshold, double focalDistance, double aperture, int dofSamples,
                             int threads, long seed, boolean bvh, int beamSize, int shadowSamples)
        implements java.io.Serializable {
    /** The default image side in pixels, when a file names no resolution. */
    public static final int DEFAULT_SIZE = 500;
    /** The course's grid colour (java.awt.Color.YELLOW). */
    public static final Color DEFAULT_GRID_COLOR = new Color(255, 255, 0);
    /**
     * The most pixels an image can have: {@link ImageWriter} keeps them in one {@code int} array,
     * and JVMs allocate arrays of at most {@code Integer.MAX_VALUE - 8} elements (ImageWriter's own
     * limit, checked here without allocating).
     */
    public static final long MAX_PIXELS = Integer.MAX_VALUE - 8;
    /**
     * The ray budget of one pixel: {@link #samplesPerPixel()} × beam size × shadow samples at most
     * this; the library's own limit, {@link RayBudget#MAX_RAYS_PER_PIXEL}, which the camera holds
     * the Java API to as well.
     */
    public static final long MAX_RAYS_PER_PIXEL = RayBudget.MAX_RAYS_PER_PIXEL;
    /** The longest image name, in characters (file names have at most 255 bytes). */
    public static final int MAX_IMAGE_NAME_LENGTH = 200;

    /**
     * Checks what can be checked without a camera: the names and colours are present and the image
     * size can be allocated. The sampling values are checked by the camera when the settings are
     * {@linkplain #applyTo(Camera.Builder, Scene) applied}.
     *
     * @param imageName        the image's name: images/&lt;name&gt;.png unless told otherwise
     * @param width            image width in pixels, at least 1
     * @param height           image height in pixels, at least 1; width × height at most
     *                         {@link #MAX_PIXELS}
     * @param gridInterval     a grid line every this many pixels over the image (the course's
     *                         {@code printGrid}); 0: no grid
     * @param gridColor        the grid lines' colour
     * @param antiAliasing     how pixels are sampled
     * @param aaColumns        RANDOM: jittered grid columns per pixel
     * @param aaRows           RANDOM: jittered grid rows per pixel
     * @param adaptiveDepth    ADAPTIVE: maximum subdivision depth (sub-pixels of 1/2^depth)
     * @param adaptiveThreshold ADAPTIVE: the colour difference (0..255 scale) that subdivides
     * @param focalDistance    depth of field: distance of the sharp plane along the view
     *                         direction; 0: pinhole camera (no depth of field)
     * @param aperture         depth of field: lens radius in scene units
     * @param dofSamples       depth of field: lens samples per pixel without anti-aliasing
     * @param threads          0: calling thread; n &gt; 0: n workers; -2: all cores
     * @param seed             the seed of every random number of the render
     * @param bvh              whether the tracer uses the bounding volume hierarchy
     * @param beamSize         rays per glossy or diffuse-glass beam
     * @param shadowSamples    shadow rays toward a light with a radius
     * @throws NullPointerException     when the image name, grid colour or anti-aliasing mode is null
     * @throws IllegalArgumentException for a side below 1 pixel or more than {@link #MAX_PIXELS}
     *                                  pixels, naming the size; for an image name that is not a
     *                                  plain file name (see {@link #requireImageName(String)}); for
     *                                  more than {@link #MAX_RAYS_PER_PIXEL} rays per pixel, naming
     *                                  the factors
     */
    public RenderSettings {
        requireImageName(imageName);
        Objects.requireNonNull(gridColor, "grid colour");
        Objects.requireNonNull(antiAliasing, "anti-aliasing mode");
        RayBudget.require(antiAliasing, samplesPerPixel(antiAliasing, aaColumns, aaRows, adaptiveDepth, focalDistance,
                dofSamples), beamSize, shadowSamples);
        if (width < 1 || height < 1)
            throw new IllegalArgumentException("image size must be at least 1x1, got " + width + "x" + height);
        long pixels = (long) width * height;
        if (pixels > MAX_PIXELS)
            throw new IllegalArgumentException("image size " + width + "x" + height + " is " + pixels
                    + " pixels, more than an image can hold (" + MAX_PIXELS + ")");
    }

    /**
     * The settings of a file that says nothing: a {@value #DEFAULT_SIZE}-pixel square image, no
     * grid, no anti-aliasing (RANDOM would use 4×4, ADAPTIVE depth 3 and threshold 8), no depth
     * of field (16 lens samples when it is on), all cores, seed 0, BVH on, beams of 16 rays and
     * 16 shadow samples: the camera's and the tracer's own defaults, except the thread count.
     *
     * @param imageName the image's name: images/&lt;name&gt;.png
     * @return the default settings
     */
    public static RenderSettings defaults(String imageName) {
        Editor defaults = new Editor();
        defaults.imageName = imageName;
        return defaults.settings();
    }

    /**
     * @param name   the image's name: images/&lt;name&gt;.png
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1
     * @return these settings with another image name and size
     * @throws IllegalArgumentException when the size is out of range (see the constructor)
     */
    public RenderSettings withImage(String name, int width, int height) {
        return edit(e -> {
            e.imageName = name;
            e.width = width;
            e.height = height;
        });
    }

    /**
     * @param interval a grid line every this many pixels; 0: no grid
     * @param color    the grid lines' colour
     * @return these settings with another grid overlay
     */
    public RenderSettings withGrid(int interval, Color color) {
        return edit(e -> {
            e.gridInterval = interval;
            e.gridColor = color;
        });
    }

    /**
     * @param mode how pixels are sampled
     * @return these settings with another anti-aliasing mode (its parameters kept, so a later mode
     *         change finds them)
     */
    public RenderSettings withAntiAliasing(AntiAliasing mode) {
        return edit(e -> e.antiAliasing = mode);
    }

    /**
     * The parameters of every mode at once; each is checked by the camera when applied, and only
     * the current mode's parameters are.
     *
     * @param columns   RANDOM: jittered grid columns per pixel
     * @param rows      RANDOM: jittered grid rows per pixel
     * @param depth     ADAPTIVE: maximum subdivision depth
     * @param threshold ADAPTIVE: the colour difference (0..255 scale) that subdivides
     * @return these settings with other anti-aliasing parameters
     */
    public RenderSettings withAntiAliasingParameters(int columns, int rows, int depth, double threshold) {
        return edit(e -> {
            e.aaColumns = columns;
            e.aaRows = rows;
            e.adaptiveDepth = depth;
            e.adaptiveThreshold = threshold;
        });
    }

    /**
     * @param focalDistance distance of the sharp plane along the view direction; 0: none
     * @param aperture      lens radius in scene units
     * @param samples       lens samples per pixel when anti-aliasing is off
     * @return these settings with another depth of field
     */
    public RenderSettings withDepthOfField(double focalDistance, double aperture, int samples) {
        return edit(e -> {
            e.focalDistance = focalDistance;
            e.aperture = aperture;
            e.dofSamples = samples;
        });
    }

    /**
     * @param threads 0: calling thread; n &gt; 0: n workers; -2: all cores
     * @return these settings with another thread count
     */
    public RenderSettings withThreads(int threads) {
        return edit(e -> e.threads = threads);
    }

    /**
     * @param seed the seed of every random number of the render
     * @return these settings with another seed
     */
    public RenderSettings withSeed(long seed) {
        return edit(e -> e.seed = seed);
    }

    /**
     * @param bvh           whether the tracer uses the bounding volume hierarchy
     * @param beamSize      rays per glossy or diffuse-glass beam
     * @param shadowSamples shadow rays toward a light with a radius
     * @return these settings with other tracer extensions
     */
    public RenderSettings withTracer(boolean bvh, int beamSize, int shadowSamples) {
        return edit(e -> {
            e.bvh = bvh;
            e.beamSize = beamSize;
            e.shadowSamples = shadowSamples;
        });
    }

    /**
     * Checks that {@code name} names a file in images/ and nothing else: a scene file must not
     * choose where on disk its image goes (only the command line's {@code -o} does).
     *
     * @param name the image name, without ".png"
     * @return {@code name}
     * @throws NullPointerException     for a null name
     * @throws IllegalArgumentException for a blank name, one longer than
     *                                  {@link #MAX_IMAGE_NAME_LENGTH}, or one with a path separator
     *                                  ({@code /} or {@code \}), a drive colon, {@code ..} or a
     *                                  control character, naming it; for one with an invisible
     *                                  format character (Unicode category Cf: the bidirectional
     *                                  overrides and isolates U+202A–U+202E and U+2066–U+2069, the
     *                                  marks U+200E, U+200F and U+061C, U+200B, U+FEFF...), naming
     *                                  its code point
     */
    public static String requireImageName(String name) {
        Objects.requireNonNull(name, "image name");
        if (name.isBlank()) throw new IllegalArgumentException("the image name is blank");
        if (name.length() > MAX_IMAGE_NAME_LENGTH)
            throw new IllegalArgumentException("the image name has " + name.length() + " characters, more than the limit of "
                    + MAX_IMAGE_NAME_LENGTH);
        name.codePoints().filter(cp -> Character.getType(cp) == Character.FORMAT).findFirst().ifPresent(cp -> {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "the image name contains U+%04X, an invisible"
                    + " or direction-changing character (the file name would display as something else)", cp));
        });
        for (int i = 0; i < name.length(); ++i) {
            char c = name.charAt(i);
            if (c == '/' || c == '\\' || c == ':' || Character.isISOControl(c))
                throw new IllegalArgumentException("the image name '" + name.replaceAll("[\\p{Cntrl}\\p{Cf}]", "?")
                        + "' is a path, not a name (it contains " + (Character.isISOControl(c) ? "a control character"
                                : "'" + c + "'") + ")");
        }
        if (name.contains(".."))
            throw new IllegalArgumentException("the image name '" + name + "' contains '..' (a name, not a path, is expected)");
        return name;
    }

    /**
     * The most primary rays one pixel may take, as the camera counts them
     * ({@link RayBudget#cameraRaysPerPixel}): RANDOM's grid, ADAPTIVE's whole lattice of
     * (2^depth + 1)² points (the worst case), CORNERS' five points, or without anti-aliasing the
     * lens samples with depth of field and 1 without.
     *
     * @return the samples per pixel, as a long (a grid of two ints may overflow an int)
     */
    public long samplesPerPixel() {
        return samplesPerPixel(antiAliasing, aaColumns, aaRows, adaptiveDepth, focalDistance, dofSamples);
    }

    private static long samplesPerPixel(AntiAliasing mode, int columns, int rows, int depth, double focalDistance,
            int dofSamples) {
        return RayBudget.cameraRaysPerPixel(mode, columns, rows, depth, focalDistance > 0, dofSamples);
    }

    /** @return whether these settings ask for depth of field */
    public boolean hasDepthOfField() {
        return focalDistance > 0;
    }

    /**
     * Sets everything but the view on {@code camera}: a new image writer of this name and size
     * (this allocates the image: 4 bytes a pixel), a new {@link RayTracerBasic} for {@code scene}
     * with these extensions, the sampling, seed and thread count. The view (location, direction,
     * view plane) is left as it is.
     *
     * @param camera the builder to configure; its view must be set by the caller
     * @param scene  what the new tracer renders
     * @return {@code camera}, for chaining
     * @throws IllegalArgumentException for a value the camera or tracer refuses
     */
    public Camera.Builder applyTo(Camera.Builder camera, Scene scene) {
        return applyTo(camera, scene, newImageWriter());
    }

    /** @return a new, black image writer of this name and size (4 bytes a pixel) */
    public ImageWriter newImageWriter() {
        return new ImageWriter(imageName, width, height);
    }

    /**
     * As {@link #applyTo(Camera.Builder, Scene)}, with an image writer of the caller's (which
     * keeps a reference to it, e.g. to write it elsewhere than images/, or to allocate it where
     * it can report a lack of memory); its size is the caller's business.
     *
     * @param camera the builder to configure; its view must be set by the caller
     * @param scene  what the new tracer renders
     * @param image  the image the camera renders into
     * @return {@code camera}, for chaining
     * @throws IllegalArgumentException for a value the camera or tracer refuses
     */
    public Camera.Builder applyTo(Camera.Builder camera, Scene scene, ImageWriter image) {
        camera.setImageWriter(image)
                .setRayTracer(new RayTracerBasic(scene).setBvh(bvh).setBeamSize(beamSize).setShadowSamples(shadowSamples))
                .setAntiAliasing(antiAliasing)
                .setAdaptive(adaptiveDepth, adaptiveThreshold)
                .setDepthOfFieldSamples(dofSamples)
                .setSeed(seed)
                .setMultithreading(threads);
        // The camera takes a grid only with RANDOM (for the other modes the settings merely keep
        // it, for a later --aa random).
        if (antiAliasing == AntiAliasing.RANDOM) camera.setAntiAliasingGrid(aaColumns, aaRows);
        // Aperture 0 is the pinhole camera whatever the focal distance: this also undoes an earlier
        // depth of field on a reused builder.
        if (hasDepthOfField()) camera.setDepthOfField(focalDistance, aperture);
        else camera.setDepthOfField(1, 0);
        return camera;
    }

    /**
     * Draws the grid over a rendered image when these settings ask for one.
     *
     * @param camera the camera that rendered the image (its image writer receives the grid)
     */
    public void drawGrid(Camera camera) {
        if (gridInterval > 0) camera.printGrid(gridInterval, gridColor);
    }

    /** A copy of these settings with the fields {@code change} assigns, by name. */
    private RenderSettings edit(Consumer<Editor> change) {
        Editor editor = new Editor(this);
        change.accept(editor);
        return editor.settings();
    }

    /**
     * The settings as named, mutable fields, so that each {@code with…} method assigns what it
     * changes by name: the record's constructor, whose 18 arguments include adjacent ones of the
     * same type, is called in one place only. Starts from the defaults (see
     * {@link #defaults(String)}).
     */
    private static final class Editor {
        String imageName;
        int width = DEFAULT_SIZE;
        int height = DEFAULT_SIZE;
        int gridInterval = 0;
        Color gridColor = DEFAULT_GRID_COLOR;
        AntiAliasing antiAliasing = AntiAliasing.NONE;
        int aaColumns = 4;
        int aaRows = 4;
        int adaptiveDepth = 3;
        double adaptiveThreshold = 8;
        double focalDistance = 0;
        double aperture = 0;
        int dofSamples = 16;
        int threads = -2;
        long seed = 0;
        boolean bvh = true;
        int beamSize = 16;
        int shadowSamples = 16;

        Editor() {
        }

        Editor(RenderSettings s) {
            imageName = s.imageName;
            width = s.width;
            height = s.height;
            gridInterval = s.gridInterval;
            gridColor = s.gridColor;
            antiAliasing = s.antiAliasing;
            aaColumns = s.aaColumns;
            aaRows = s.aaRows;
            adaptiveDepth = s.adaptiveDepth;
            adaptiveThreshold = s.adaptiveThreshold;
            focalDistance = s.focalDistance;
            aperture = s.aperture;
            dofSamples = s.dofSamples;
            threads = s.threads;
            seed = s.seed;
            bvh = s.bvh;
            beamSize = s.beamSize;
            shadowSamples = s.shadowSamples;
        }

        RenderSettings settings() {
            return new RenderSettings(imageName, width, height, gridInterval, gridColor, antiAliasing, aaColumns,
                    aaRows, adaptiveDepth, adaptiveThreshold, focalDistance, aperture, dofSamples, threads, seed, bvh,
                    beamSize, shadowSamples);
        }
    }
}
