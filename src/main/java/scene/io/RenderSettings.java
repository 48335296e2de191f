package scene.io;

import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectInputStream;
import java.util.Arrays;
import java.util.Objects;
import java.util.StringJoiner;
import java.util.function.Consumer;

import primitives.Color;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.Execution;
import renderer.ImageWriter;
import renderer.RayBudget;
import renderer.RayTracerBasic;
import renderer.Sampling;
import renderer.View;
import scene.Scene;

/**
 * How a scene file or a command line asks for a render: a specification that records only the
 * values it was given, and replays them onto a {@link Camera.Builder} and its
 * {@link RayTracerBasic} ({@link #applyTo(Camera.Builder, Scene, ImageWriter) applyTo}). A value
 * it does not state is the library's: the defaults and limits of the sampling, the tracer and the
 * ray budget exist once, in the builder and the tracer, whose setters check each value as it is
 * replayed and whose {@code build()} checks the ray budget.
 *
 * <p>The image and the thread count are the scene format's own (the library's image has no
 * default size, and the builder's default thread, the calling one, is the course's): a
 * specification that does not state them renders {@value #DEFAULT_SIZE}×{@value #DEFAULT_SIZE}
 * pixels without a grid, on all cores. The image size is checked when it is stated, without
 * allocating; the image is allocated only when asked for ({@link #newImageWriter()}).
 *
 * <p>A command line's options are a second specification, replayed after the file's:
 * {@code file.then(options)} states what the options state, and the file's values elsewhere.
 *
 * <p>Immutable: each {@code with…} method states its values on a copy. Serializable (a deserialized
 * copy is checked again): a cluster's driver sends the specification it resolved to its executors.
 *
 * @serial exclude
 */
public final class RenderSettings implements java.io.Serializable {
    private static final long serialVersionUID = 2L;

    /** The image side in pixels when no size is stated: the scene format's default. */
    public static final int DEFAULT_SIZE = 500;
    /** The course's grid colour (java.awt.Color.YELLOW), when a grid's colour is not stated. */
    public static final Color DEFAULT_GRID_COLOR = new Color(255, 255, 0);
    /**
     * The most pixels an image can have, {@link ImageWriter#MAX_PIXELS}: the library's limit,
     * checked here when a size is stated, without allocating.
     */
    public static final long MAX_PIXELS = ImageWriter.MAX_PIXELS;
    /**
     * The ray budget of one pixel, {@code RayBudget.MAX_RAYS_PER_PIXEL}: the library's limit,
     * which {@code Camera.Builder.build()} holds every camera to; named here for the scene
     * format's messages and documentation.
     */
    public static final long MAX_RAYS_PER_PIXEL = RayBudget.MAX_RAYS_PER_PIXEL;
    /** The longest image name, in characters (file names have at most 255 bytes): {@code ImageWriter}'s rule. */
    public static final int MAX_IMAGE_NAME_LENGTH = ImageWriter.MAX_FILE_NAME_LENGTH;
    /** The thread count when none is stated: all cores ({@link Camera.Builder#setMultithreading}'s -2). */
    private static final int ALL_CORES = -2;

    // Each field is null when the specification does not state it.
    // The image: its name (images/<name>.png), size in pixels (stated together) and grid.
    private String imageName;
    private Integer width, height;
    /** A grid line every this many pixels; 0: no grid. */
    private Integer gridInterval;
    private Color gridColor;
    // The camera's sampling (Camera.Builder's setters) and execution.
    private AntiAliasing antiAliasing;
    /** RANDOM's grid, columns × rows (stated together). */
    private Integer gridColumns, gridRows;
    private Integer adaptiveDepth;
    private Double adaptiveThreshold;
    /** The thin lens, stated together: focal distance 0 is the pinhole camera. */
    private Double focalDistance, aperture;
    private Integer lensSamples;
    private Long seed;
    private Integer threads;
    // The tracer's extensions (RayTracerBasic's setters).
    private Boolean bvh;
    private Integer beamSize, shadowSamples;

    private RenderSettings() {
    }

    private RenderSettings(RenderSettings s) {
        imageName = s.imageName;
        width = s.width;
        height = s.height;
        gridInterval = s.gridInterval;
        gridColor = s.gridColor;
        antiAliasing = s.antiAliasing;
        gridColumns = s.gridColumns;
        gridRows = s.gridRows;
        adaptiveDepth = s.adaptiveDepth;
        adaptiveThreshold = s.adaptiveThreshold;
        focalDistance = s.focalDistance;
        aperture = s.aperture;
        lensSamples = s.lensSamples;
        seed = s.seed;
        threads = s.threads;
        bvh = s.bvh;
        beamSize = s.beamSize;
        shadowSamples = s.shadowSamples;
    }

    /** @return a specification that states nothing (a command line without options) */
    public static RenderSettings empty() {
        return new RenderSettings();
    }

    /**
     * The specification of a scene file that states nothing but its image's name: the format's
     * image ({@value #DEFAULT_SIZE}-pixel square, no grid), all cores, and the library's defaults
     * for everything else.
     *
     * @param imageName the image's name: images/&lt;name&gt;.png
     * @return the specification
     * @throws IllegalArgumentException for a name that is not a plain file name (see
     *                                  {@link #requireImageName(String)})
     */
    public static RenderSettings defaults(String imageName) {
        RenderSettings s = new RenderSettings();
        s.imageName = requireImageName(imageName);
        return s;
    }

    /**
     * @param name   the image's name: images/&lt;name&gt;.png
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1; width × height at most {@link #MAX_PIXELS}
     * @return this specification with the image's name and size stated
     * @throws IllegalArgumentException for a name that is not a plain file name, or a size out of
     *                                  range, naming it
     */
    public RenderSettings withImage(String name, int width, int height) {
        requireImageName(name);
        return withImageSize(width, height).edit(s -> s.imageName = name);
    }

    /**
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1; width × height at most {@link #MAX_PIXELS}
     * @return this specification with the image's size stated
     * @throws IllegalArgumentException for a size out of range, naming it
     */
    public RenderSettings withImageSize(int width, int height) {
        requireSize(width, height);
        return edit(s -> {
            s.width = width;
            s.height = height;
        });
    }

    /**
     * @param interval a grid line every this many pixels; 0: no grid
     * @param color    the grid lines' colour
     * @return this specification with a grid stated
     */
    public RenderSettings withGrid(int interval, Color color) {
        Objects.requireNonNull(color, "grid colour");
        return edit(s -> {
            s.gridInterval = interval;
            s.gridColor = color;
        });
    }

    /**
     * @param mode how pixels are sampled
     * @return this specification with the mode stated (its parameters as they were, so a later
     *         mode change finds them)
     */
    public RenderSettings withAntiAliasing(AntiAliasing mode) {
        Objects.requireNonNull(mode, "anti-aliasing mode");
        return edit(s -> s.antiAliasing = mode);
    }

    /**
     * @param columns RANDOM: jittered grid columns per pixel
     * @param rows    RANDOM: jittered grid rows per pixel
     * @return this specification with RANDOM's grid stated (whatever the mode, as the builder keeps it)
     */
    public RenderSettings withAntiAliasingGrid(int columns, int rows) {
        return edit(s -> {
            s.gridColumns = columns;
            s.gridRows = rows;
        });
    }

    /**
     * @param depth ADAPTIVE: the deepest subdivision
     * @return this specification with ADAPTIVE's depth stated
     */
    public RenderSettings withAdaptiveDepth(int depth) {
        return edit(s -> s.adaptiveDepth = depth);
    }

    /**
     * @param threshold ADAPTIVE: the colour difference (0..255 scale) that subdivides
     * @return this specification with ADAPTIVE's threshold stated
     */
    public RenderSettings withAdaptiveThreshold(double threshold) {
        return edit(s -> s.adaptiveThreshold = threshold);
    }

    /**
     * The parameters of every mode at once: each is checked when replayed.
     *
     * @param columns   RANDOM: jittered grid columns per pixel
     * @param rows      RANDOM: jittered grid rows per pixel
     * @param depth     ADAPTIVE: the deepest subdivision
     * @param threshold ADAPTIVE: the colour difference (0..255 scale) that subdivides
     * @return this specification with the four stated
     */
    public RenderSettings withAntiAliasingParameters(int columns, int rows, int depth, double threshold) {
        return withAntiAliasingGrid(columns, rows).withAdaptiveDepth(depth).withAdaptiveThreshold(threshold);
    }

    /**
     * @param focalDistance distance of the sharp plane along the view direction; 0: the pinhole
     *                      camera (no depth of field)
     * @param aperture      lens radius in scene units
     * @return this specification with the lens stated
     */
    public RenderSettings withDepthOfField(double focalDistance, double aperture) {
        return edit(s -> {
            s.focalDistance = focalDistance;
            s.aperture = aperture;
        });
    }

    /**
     * @param samples lens samples per pixel when anti-aliasing is off
     * @return this specification with the lens samples stated
     */
    public RenderSettings withDepthOfFieldSamples(int samples) {
        return edit(s -> s.lensSamples = samples);
    }

    /**
     * @param focalDistance distance of the sharp plane along the view direction; 0: none
     * @param aperture      lens radius in scene units
     * @param samples       lens samples per pixel when anti-aliasing is off
     * @return this specification with the lens and its samples stated
     */
    public RenderSettings withDepthOfField(double focalDistance, double aperture, int samples) {
        return withDepthOfField(focalDistance, aperture).withDepthOfFieldSamples(samples);
    }

    /**
     * @param threads 0: calling thread; n &gt; 0: n workers; -1 or -2: all cores
     * @return this specification with the thread count stated
     */
    public RenderSettings withThreads(int threads) {
        return edit(s -> s.threads = threads);
    }

    /**
     * @param seed the seed of every random number of the render
     * @return this specification with the seed stated
     */
    public RenderSettings withSeed(long seed) {
        return edit(s -> s.seed = seed);
    }

    /**
     * @param on whether the tracer uses the bounding volume hierarchy
     * @return this specification with the choice stated
     */
    public RenderSettings withBvh(boolean on) {
        return edit(s -> s.bvh = on);
    }

    /**
     * @param rays rays per glossy or diffuse-glass beam
     * @return this specification with the beam size stated
     */
    public RenderSettings withBeamSize(int rays) {
        return edit(s -> s.beamSize = rays);
    }

    /**
     * @param samples shadow rays toward a light with a radius
     * @return this specification with the shadow samples stated
     */
    public RenderSettings withShadowSamples(int samples) {
        return edit(s -> s.shadowSamples = samples);
    }

    /**
     * @param bvh           whether the tracer uses the bounding volume hierarchy
     * @param beamSize      rays per glossy or diffuse-glass beam
     * @param shadowSamples shadow rays toward a light with a radius
     * @return this specification with the tracer's three extensions stated
     */
    public RenderSettings withTracer(boolean bvh, int beamSize, int shadowSamples) {
        return withBvh(bvh).withBeamSize(beamSize).withShadowSamples(shadowSamples);
    }

    /**
     * The specification that replays this one and then {@code later}: {@code later}'s values where
     * it states them, this one's elsewhere (a command line's options over a scene file's values).
     *
     * @param later the specification replayed second
     * @return the two as one
     */
    public RenderSettings then(RenderSettings later) {
        RenderSettings s = new RenderSettings(this);
        s.imageName = or(later.imageName, imageName);
        if (later.width != null) {
            s.width = later.width;
            s.height = later.height;
        }
        s.gridInterval = or(later.gridInterval, gridInterval);
        s.gridColor = or(later.gridColor, gridColor);
        s.antiAliasing = or(later.antiAliasing, antiAliasing);
        if (later.gridColumns != null) {
            s.gridColumns = later.gridColumns;
            s.gridRows = later.gridRows;
        }
        s.adaptiveDepth = or(later.adaptiveDepth, adaptiveDepth);
        s.adaptiveThreshold = or(later.adaptiveThreshold, adaptiveThreshold);
        if (later.focalDistance != null) {
            s.focalDistance = later.focalDistance;
            s.aperture = later.aperture;
        }
        s.lensSamples = or(later.lensSamples, lensSamples);
        s.seed = or(later.seed, seed);
        s.threads = or(later.threads, threads);
        s.bvh = or(later.bvh, bvh);
        s.beamSize = or(later.beamSize, beamSize);
        s.shadowSamples = or(later.shadowSamples, shadowSamples);
        return s;
    }

    private static <T> T or(T stated, T otherwise) {
        return stated != null ? stated : otherwise;
    }

    /** @return the image's name (images/&lt;name&gt;.png); null when not stated */
    public String imageName() {
        return imageName;
    }

    /** @return the image width in pixels: as stated, else {@value #DEFAULT_SIZE} */
    public int width() {
        return width != null ? width : DEFAULT_SIZE;
    }

    /** @return the image height in pixels: as stated, else {@value #DEFAULT_SIZE} */
    public int height() {
        return height != null ? height : DEFAULT_SIZE;
    }

    /** @return a grid line every this many pixels; 0 (not stated): no grid */
    public int gridInterval() {
        return gridInterval != null ? gridInterval : 0;
    }

    /** @return the grid lines' colour: as stated, else {@link #DEFAULT_GRID_COLOR} */
    public Color gridColor() {
        return gridColor != null ? gridColor : DEFAULT_GRID_COLOR;
    }

    /**
     * Checks that {@code name} names a file in images/ and nothing else: a scene file must not
     * choose where on disk its image goes (only the command line's {@code -o} does). The rule is
     * the image writer's, which names the files.
     *
     * @param name the image name, without ".png"
     * @return {@code name}
     * @throws NullPointerException     for a null name
     * @throws IllegalArgumentException for a blank name, one longer than
     *                                  {@link #MAX_IMAGE_NAME_LENGTH}, or one with a path separator
     *                                  ({@code /} or {@code \}), a drive colon or {@code ..},
     *                                  naming it; for one with a character that would not show
     *                                  as what it is ({@link Messages#hidden}: control, format and
     *                                  bidirectional characters, separators and spaces other than
     *                                  U+0020, private-use and unassigned code points, Unicode's
     *                                  default-ignorable characters such as the Hangul fillers, the
     *                                  blank braille pattern), naming its code point and its kind
     */
    public static String requireImageName(String name) {
        return ImageWriter.requireFileName(name);
    }

    /** Each side at least 1 and at most {@link #MAX_PIXELS} pixels in all, naming the size. */
    private static void requireSize(int width, int height) {
        if (width < 1 || height < 1)
            throw new IllegalArgumentException("image size must be at least 1x1, got " + width + "x" + height);
        long pixels = (long) width * height;
        if (pixels > MAX_PIXELS)
            throw new IllegalArgumentException("image size " + width + "x" + height + " is " + pixels
                    + " pixels, more than an image can hold (" + MAX_PIXELS + ")");
    }

    /**
     * Replays this specification onto {@code camera} with a new image writer of its name and size
     * (this allocates the image: 4 bytes a pixel); see
     * {@link #applyTo(Camera.Builder, Scene, ImageWriter)}.
     *
     * @param camera the builder to configure; its view is the caller's
     * @param scene  what the new tracer renders
     * @return {@code camera}, for chaining
     * @throws IllegalArgumentException for a stated value the camera or the tracer refuses
     */
    public Camera.Builder applyTo(Camera.Builder camera, Scene scene) {
        return applyTo(camera, scene, newImageWriter());
    }

    /**
     * @return a new, black image writer of this size (4 bytes a pixel) and name; without a stated
     *         name, an unnamed one (the 2024&ndash;25 form, named when written)
     */
    public ImageWriter newImageWriter() {
        return imageName != null ? new ImageWriter(imageName, width(), height()) : new ImageWriter(width(), height());
    }

    /**
     * Replays this specification onto {@code camera}: the image writer, a new
     * {@link RayTracerBasic} for {@code scene} with the stated extensions, and each stated value
     * of the sampling, seed and threads through the builder's own setter (the thread count is all
     * cores when not stated). What is not stated stays as the builder and the tracer have it; the
     * view (location, direction, view plane) is the caller's. {@code build()} then checks the
     * ray budget.
     *
     * @param camera the builder to configure; its view is the caller's
     * @param scene  what the new tracer renders
     * @param image  the image the camera renders into (the caller keeps it, e.g. to write it
     *               elsewhere than images/, or to allocate it where it can report a lack of memory)
     * @return {@code camera}, for chaining
     * @throws IllegalArgumentException for a stated value the camera or the tracer refuses
     */
    public Camera.Builder applyTo(Camera.Builder camera, Scene scene, ImageWriter image) {
        RayTracerBasic tracer = new RayTracerBasic(scene);
        if (bvh != null) tracer.setBvh(bvh);
        if (beamSize != null) tracer.setBeamSize(beamSize);
        if (shadowSamples != null) tracer.setShadowSamples(shadowSamples);
        camera.setImageWriter(image).setRayTracer(tracer);
        if (antiAliasing != null) camera.setAntiAliasing(antiAliasing);
        if (gridColumns != null) camera.setAntiAliasingGrid(gridColumns, gridRows);
        if (adaptiveDepth != null || adaptiveThreshold != null) {
            // The builder takes the two together: a specification stating one gets the library's other.
            Sampling.Adaptive library = Sampling.DEFAULT.adaptive();
            camera.setAdaptive(adaptiveDepth != null ? adaptiveDepth : library.depth(),
                    adaptiveThreshold != null ? adaptiveThreshold : library.threshold());
        }
        // A stated pinhole (focal distance 0, whatever the aperture) is the builder's aperture 0,
        // which is the pinhole whatever the focal distance: it undoes a lens set on the builder before.
        if (focalDistance != null) {
            if (focalDistance == 0) camera.setDepthOfField(1, 0);
            else camera.setDepthOfField(focalDistance, aperture);
        }
        if (lensSamples != null) camera.setDepthOfFieldSamples(lensSamples);
        if (seed != null) camera.setSeed(seed);
        return camera.setMultithreading(threads != null ? threads : ALL_CORES);
    }

    /**
     * Checks this specification against the library's ray budget, as {@code Camera.Builder.build()}
     * will when it is replayed: the stated values over the library's defaults, by the library's rule
     * ({@link RayBudget#require(Sampling, boolean, int, int, java.util.Collection)}; the budget
     * depends on the sampling, the lens and the tracer, not on the view), with no lights.
     *
     * @return this specification
     * @throws IllegalArgumentException for a stated value the camera or the tracer refuses, or
     *                                  more than {@link #MAX_RAYS_PER_PIXEL} rays per pixel,
     *                                  with the library's message naming the factors
     */
    public RenderSettings requireRayBudget() {
        return requireRayBudget(new Scene("ray budget"));
    }

    /**
     * Checks this specification against the library's ray budget for {@code scene}'s lights (a
     * light with a radius takes the shadow samples at each shaded point, every other light one
     * ray), as {@code Camera.Builder.build()} will for a camera over that scene.
     *
     * @param scene the scene the settings will render: only its lights are read
     * @return this specification
     * @throws IllegalArgumentException as {@link #requireRayBudget()}, with the lights among the factors
     */
    public RenderSettings requireRayBudget(Scene scene) {
        if (threads != null) Execution.requireThreads(threads);
        RayBudget.require(sampling(), !lens().isPinhole(), beamSize != null ? beamSize : RayTracerBasic.DEFAULT_BEAM_SIZE,
                shadowSamples != null ? shadowSamples : RayTracerBasic.DEFAULT_SHADOW_SAMPLES, scene.lights);
        return this;
    }

    /** The stated lens, checked by the library's rule: the pinhole when none is stated or its focal distance is 0. */
    private View.Lens lens() {
        return focalDistance == null || focalDistance == 0 ? View.Lens.PINHOLE : View.Lens.thin(focalDistance, aperture);
    }

    /**
     * The stated sampling over the library's, each part checked by the library's rule. ADAPTIVE's
     * depth and threshold are one value there: a specification stating one gets the library's other.
     */
    private Sampling sampling() {
        Sampling s = Sampling.DEFAULT;
        if (antiAliasing != null) s = s.withAntiAliasing(antiAliasing);
        if (gridColumns != null) s = s.withGrid(gridColumns, gridRows);
        if (adaptiveDepth != null || adaptiveThreshold != null)
            s = s.withAdaptive(adaptiveDepth != null ? adaptiveDepth : s.adaptive().depth(),
                    adaptiveThreshold != null ? adaptiveThreshold : s.adaptive().threshold());
        if (lensSamples != null) s = s.withLensSamples(lensSamples);
        if (seed != null) s = s.withSeed(seed);
        return s;
    }

    /**
     * Draws the grid over a rendered image when this specification asks for one.
     *
     * @param camera the camera that rendered the image (its image writer receives the grid)
     */
    public void drawGrid(Camera camera) {
        if (gridInterval() > 0) camera.printGrid(gridInterval(), gridColor());
    }

    /** A copy of this specification with the values {@code change} states. */
    private RenderSettings edit(Consumer<RenderSettings> change) {
        RenderSettings copy = new RenderSettings(this);
        change.accept(copy);
        return copy;
    }

    /** The checks of the {@code with…} methods, again for a copy that arrives serialized. */
    private void readObject(ObjectInputStream in) throws IOException, ClassNotFoundException {
        in.defaultReadObject();
        try {
            if (imageName != null) requireImageName(imageName);
            if ((width == null) != (height == null)) throw new IllegalArgumentException("width and height are stated together");
            if (width != null) requireSize(width, height);
        } catch (IllegalArgumentException | NullPointerException e) {
            InvalidObjectException invalid = new InvalidObjectException("render settings: " + e.getMessage());
            invalid.initCause(e);
            throw invalid;
        }
    }

    private Object[] values() {
        return new Object[] { imageName, width, height, gridInterval, gridColor, antiAliasing, gridColumns, gridRows,
                adaptiveDepth, adaptiveThreshold, focalDistance, aperture, lensSamples, seed, threads, bvh, beamSize,
                shadowSamples };
    }

    /** Equal when both state the same values (a value stated as its default is still stated). */
    @Override
    public boolean equals(Object o) {
        return o instanceof RenderSettings other && Arrays.equals(values(), other.values());
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(values());
    }

    /** @return the stated values, by name: {@code RenderSettings[image=x 40x20, antiAliasing=RANDOM]} */
    @Override
    public String toString() {
        StringJoiner stated = new StringJoiner(", ", "RenderSettings[", "]");
        if (imageName != null || width != null)
            stated.add("image=" + (imageName != null ? imageName : "") + (width != null ? " " + width + "x" + height : ""));
        String[] names = { "gridInterval", "gridColor", "antiAliasing", "grid", "adaptiveDepth", "adaptiveThreshold",
                "depthOfField", "lensSamples", "seed", "threads", "bvh", "beamSize", "shadowSamples" };
        Object[] values = { gridInterval, gridColor, antiAliasing, gridColumns == null ? null : gridColumns + "x" + gridRows,
                adaptiveDepth, adaptiveThreshold, focalDistance == null ? null : "focal " + focalDistance + " aperture " + aperture,
                lensSamples, seed, threads, bvh, beamSize, shadowSamples };
        for (int i = 0; i < names.length; ++i)
            if (values[i] != null) stated.add(names[i] + "=" + values[i]);
        return stated.toString();
    }
}
