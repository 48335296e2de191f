package scene.io;

import java.util.Objects;
import java.util.StringJoiner;

import primitives.Color;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.CameraReports;
import renderer.ImageWriter;
import renderer.ImageWriters;
import renderer.RayBudget;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * How a scene file or a command line asks for a render: a specification that records only the
 * values it was given, and replays them onto a {@link Camera.Builder} and its {@link RayTracerBasic}
 * ({@link #replay(Camera.Builder, Scene) replay}): a value it does not state is the library's, and
 * the limits, the ray budget included, are the builder's and the tracer's own checks.
 *
 * <p>The image and the thread count are the scene format's own: a specification that does not
 * state them renders {@value #DEFAULT_SIZE}×{@value #DEFAULT_SIZE} pixels without a grid, on all
 * cores. The image is allocated only when asked for ({@link #newImageWriter()}). A command
 * line's options are a second specification replayed after the file's: {@code file.then(options)}.
 *
 * <p>A record of its parts, each a record of what it states (null: not stated): equality, hashing
 * and serialization are the parts' (a deserialized copy goes through the records' checks). Each
 * {@code with…} method states its values on a copy; a cluster's driver sends the result to its executors.
 *
 * @param image        the image's name and size
 * @param grid         the grid drawn over the image
 * @param antiAliasing the sampling as the builder's setters take it
 * @param lens         the thin lens and its samples
 * @param tracer       the tracer's extensions
 * @param threads      the thread count ({@code Camera.Builder.setMultithreading}'s); null: all cores
 * @param seed         the seed of every random number of the render; null: the library's
 * @serial exclude
 */
public record RenderSettings(ImageSpec image, GridSpec grid, AntiAliasingSpec antiAliasing, LensSpec lens, TracerSpec tracer,
                             Integer threads, Long seed) implements java.io.Serializable {
    /** The image side in pixels when no size is stated: the scene format's default. */
    public static final int DEFAULT_SIZE = 500;
    /** The course's grid colour (java.awt.Color.YELLOW), when a grid's colour is not stated. */
    public static final Color DEFAULT_GRID_COLOR = new Color(255, 255, 0);
    /** The most pixels an image can have, {@link ImageWriter#MAX_PIXELS}, checked when a size is stated. */
    public static final long MAX_PIXELS = ImageWriter.MAX_PIXELS;
    /** The ray budget of one pixel, {@code RayBudget.MAX_RAYS_PER_PIXEL}, named for the scene format's messages. */
    public static final long MAX_RAYS_PER_PIXEL = RayBudget.MAX_RAYS_PER_PIXEL;
    /** The longest image name, in characters (file names have at most 255 bytes): {@code ImageWriter}'s rule. */
    public static final int MAX_IMAGE_NAME_LENGTH = ImageWriters.MAX_FILE_NAME_LENGTH;
    /** The thread count when none is stated: all cores ({@link Camera.Builder#setMultithreading}'s -2). */
    private static final int ALL_CORES = -2;

    /** The specification that states nothing. */
    private static final RenderSettings EMPTY = new RenderSettings(ImageSpec.NONE, GridSpec.NONE, AntiAliasingSpec.NONE,
            LensSpec.NONE, TracerSpec.NONE, null, null);

    /**
     * @param image        the image's name and size
     * @param grid         the grid drawn over the image
     * @param antiAliasing the sampling as the builder's setters take it
     * @param lens         the thin lens and its samples
     * @param tracer       the tracer's extensions
     * @param threads      the thread count; null: all cores
     * @param seed         the render's seed; null: the library's
     * @throws NullPointerException naming a missing part (a copy that arrives serialized without one, say)
     */
    public RenderSettings {
        Objects.requireNonNull(image, "image part");
        Objects.requireNonNull(grid, "grid part");
        Objects.requireNonNull(antiAliasing, "anti-aliasing part");
        Objects.requireNonNull(lens, "lens part");
        Objects.requireNonNull(tracer, "tracer part");
    }

    /** @return a specification that states nothing (a command line without options) */
    public static RenderSettings empty() {
        return EMPTY;
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
        return EMPTY.with(new ImageSpec(requireImageName(imageName), null, null));
    }

    /**
     * @param name   the image's name: images/&lt;name&gt;.png
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1; width × height at most {@link #MAX_PIXELS}
     * @return this specification with the image's name and size stated
     * @throws IllegalArgumentException for a name that is not a plain file name, or a size out of range, naming it
     */
    public RenderSettings withImage(String name, int width, int height) {
        Objects.requireNonNull(name, "image name");
        return with(new ImageSpec(name, width, height));
    }

    /**
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1; width × height at most {@link #MAX_PIXELS}
     * @return this specification with the image's size stated
     * @throws IllegalArgumentException for a size out of range, naming it
     */
    public RenderSettings withImageSize(int width, int height) {
        return with(new ImageSpec(image.name(), width, height));
    }

    /**
     * @param interval a grid line every this many pixels; 0: no grid
     * @param color    the grid lines' colour
     * @return this specification with a grid stated
     */
    public RenderSettings withGrid(int interval, Color color) {
        Objects.requireNonNull(color, "grid colour");
        return with(new GridSpec(interval, color));
    }

    /**
     * @param mode how pixels are sampled
     * @return this specification with the mode stated (its parameters as they were, so a later
     *         mode change finds them)
     */
    public RenderSettings withAntiAliasing(AntiAliasing mode) {
        Objects.requireNonNull(mode, "anti-aliasing mode");
        AntiAliasingSpec a = antiAliasing;
        return with(new AntiAliasingSpec(mode, a.columns(), a.rows(), a.depth(), a.threshold()));
    }

    /**
     * @param columns RANDOM: jittered grid columns per pixel
     * @param rows    RANDOM: jittered grid rows per pixel
     * @return this specification with RANDOM's grid stated (whatever the mode, as the builder keeps it)
     */
    public RenderSettings withAntiAliasingGrid(int columns, int rows) {
        AntiAliasingSpec a = antiAliasing;
        return with(new AntiAliasingSpec(a.mode(), columns, rows, a.depth(), a.threshold()));
    }

    /**
     * @param depth ADAPTIVE: the deepest subdivision
     * @return this specification with ADAPTIVE's depth stated
     */
    public RenderSettings withAdaptiveDepth(int depth) {
        AntiAliasingSpec a = antiAliasing;
        return with(new AntiAliasingSpec(a.mode(), a.columns(), a.rows(), depth, a.threshold()));
    }

    /**
     * @param threshold ADAPTIVE: the colour difference (0..255 scale) that subdivides
     * @return this specification with ADAPTIVE's threshold stated
     */
    public RenderSettings withAdaptiveThreshold(double threshold) {
        AntiAliasingSpec a = antiAliasing;
        return with(new AntiAliasingSpec(a.mode(), a.columns(), a.rows(), a.depth(), threshold));
    }

    /**
     * @param focalDistance distance of the sharp plane along the view direction; 0: the pinhole
     *                      camera (no depth of field)
     * @param aperture      lens radius in scene units
     * @return this specification with the lens stated
     */
    public RenderSettings withDepthOfField(double focalDistance, double aperture) {
        return with(new LensSpec(focalDistance, aperture, lens.samples()));
    }

    /**
     * @param samples lens samples per pixel when anti-aliasing is off
     * @return this specification with the lens samples stated
     */
    public RenderSettings withDepthOfFieldSamples(int samples) {
        return with(new LensSpec(lens.focalDistance(), lens.aperture(), samples));
    }

    /**
     * @param threads 0: calling thread; n &gt; 0: n workers; -1 or -2: all cores
     * @return this specification with the thread count stated
     */
    public RenderSettings withThreads(int threads) {
        return new RenderSettings(image, grid, antiAliasing, lens, tracer, threads, seed);
    }

    /**
     * @param seed the seed of every random number of the render
     * @return this specification with the seed stated
     */
    public RenderSettings withSeed(long seed) {
        return new RenderSettings(image, grid, antiAliasing, lens, tracer, threads, seed);
    }

    /**
     * @param on whether the tracer uses the bounding volume hierarchy
     * @return this specification with the choice stated
     */
    public RenderSettings withBvh(boolean on) {
        return with(new TracerSpec(on, tracer.beamSize(), tracer.shadowSamples()));
    }

    /**
     * @param rays rays per glossy or diffuse-glass beam
     * @return this specification with the beam size stated
     */
    public RenderSettings withBeamSize(int rays) {
        return with(new TracerSpec(tracer.bvh(), rays, tracer.shadowSamples()));
    }

    /**
     * @param samples shadow rays toward a light with a radius
     * @return this specification with the shadow samples stated
     */
    public RenderSettings withShadowSamples(int samples) {
        return with(new TracerSpec(tracer.bvh(), tracer.beamSize(), samples));
    }

    /**
     * The specification that replays this one and then {@code later}: {@code later}'s values where
     * it states them, this one's elsewhere (a command line's options over a scene file's values).
     *
     * @param later the specification replayed second
     * @return the two as one
     */
    public RenderSettings then(RenderSettings later) {
        return new RenderSettings(image.then(later.image), grid.then(later.grid), antiAliasing.then(later.antiAliasing),
                lens.then(later.lens), tracer.then(later.tracer), Stated.or(later.threads, threads), Stated.or(later.seed, seed));
    }

    /** This specification with one part replaced. */
    private RenderSettings with(ImageSpec image) {
        return new RenderSettings(image, grid, antiAliasing, lens, tracer, threads, seed);
    }

    private RenderSettings with(GridSpec grid) {
        return new RenderSettings(image, grid, antiAliasing, lens, tracer, threads, seed);
    }

    private RenderSettings with(AntiAliasingSpec antiAliasing) {
        return new RenderSettings(image, grid, antiAliasing, lens, tracer, threads, seed);
    }

    private RenderSettings with(LensSpec lens) {
        return new RenderSettings(image, grid, antiAliasing, lens, tracer, threads, seed);
    }

    private RenderSettings with(TracerSpec tracer) {
        return new RenderSettings(image, grid, antiAliasing, lens, tracer, threads, seed);
    }

    /** @return the image's name (images/&lt;name&gt;.png); null when not stated */
    public String imageName() {
        return image.name();
    }

    /** @return the image width in pixels: as stated, else {@value #DEFAULT_SIZE} */
    public int width() {
        return image.width() != null ? image.width() : DEFAULT_SIZE;
    }

    /** @return the image height in pixels: as stated, else {@value #DEFAULT_SIZE} */
    public int height() {
        return image.height() != null ? image.height() : DEFAULT_SIZE;
    }

    /** @return a grid line every this many pixels; 0 (not stated): no grid */
    int gridInterval() {
        return grid.interval() != null ? grid.interval() : 0;
    }

    /** @return the grid lines' colour: as stated, else {@link #DEFAULT_GRID_COLOR} */
    public Color gridColor() {
        return grid.color() != null ? grid.color() : DEFAULT_GRID_COLOR;
    }

    /**
     * Checks that {@code name} names a file in images/ and nothing else: a scene file must not
     * choose where on disk its image goes (only the command line's {@code -o} does). The rule is
     * the image writer's, which names the files ({@link ImageWriters#requireFileName(String)}:
     * no path separator, drive colon or {@code ..}, at most {@link #MAX_IMAGE_NAME_LENGTH}
     * characters, none that would not show as what it is).
     *
     * @param name the image name, without ".png"
     * @return {@code name}
     * @throws NullPointerException     for a null name
     * @throws IllegalArgumentException for a name the rule refuses, naming it (and a hidden
     *                                  character's code point and kind)
     */
    public static String requireImageName(String name) {
        return ImageWriters.requireFileName(name);
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
        return image.name() != null ? new ImageWriter(image.name(), width(), height()) : new ImageWriter(width(), height());
    }

    /**
     * Replays this specification onto {@code camera}: the image writer, then the rest as
     * {@link #replay(Camera.Builder, Scene)} does.
     *
     * @param camera the builder to configure; its view is the caller's
     * @param scene  what the new tracer renders
     * @param image  the image the camera renders into (the caller keeps it, e.g. to write it
     *               elsewhere than images/, or to allocate it where it can report a lack of memory)
     * @return {@code camera}, for chaining
     * @throws IllegalArgumentException for a stated value the camera or the tracer refuses
     */
    public Camera.Builder applyTo(Camera.Builder camera, Scene scene, ImageWriter image) {
        return replay(camera, scene).setImageWriter(image);
    }

    /**
     * The one replay of this specification onto {@code camera}: the image's size as its
     * resolution (nothing allocated: a camera built from it makes its own unnamed image; a
     * cluster's executor renders regions of it), a new {@link RayTracerBasic} for {@code scene}
     * with the stated extensions, and each stated value of the sampling, seed and threads through
     * the builder's own setter (the thread count is all cores when not stated). What is not stated
     * stays as the builder and the tracer have it; the view (location, direction, view plane) is
     * the caller's. {@code build()} then checks the ray budget.
     *
     * @param camera the builder to configure; its view is the caller's
     * @param scene  what the new tracer renders
     * @return {@code camera}, for chaining
     * @throws IllegalArgumentException for a stated value the camera or the tracer refuses
     */
    public Camera.Builder replay(Camera.Builder camera, Scene scene) {
        camera.setResolution(width(), height()).setRayTracer(tracer.newTracer(scene));
        antiAliasing.applyTo(camera);
        lens.applyTo(camera);
        if (seed != null) camera.setSeed(seed);
        return camera.setMultithreading(threads != null ? threads : ALL_CORES);
    }

    /**
     * Checks this specification against the library's ray budget for {@code scene}, as
     * {@code Camera.Builder.build()} will for a camera over that scene: replayed onto a new builder
     * ({@link #replay(Camera.Builder, Scene)}), whose budget is checked with no view
     * ({@link CameraReports#requireRayBudget(Camera.Builder)}); the budget depends on the
     * sampling, the lens, the tracer and the scene's lights (a light with a radius takes the shadow
     * samples at each shaded point, every other light one ray).
     *
     * @param scene the scene the settings will render: only its lights are read
     * @return this specification
     * @throws IllegalArgumentException for more than {@link #MAX_RAYS_PER_PIXEL} rays per pixel,
     *                                  with the library's message naming the factors, the lights
     *                                  among them (each value alone was checked when it was stated)
     */
    public RenderSettings requireRayBudget(Scene scene) {
        CameraReports.requireRayBudget(replay(Camera.getBuilder(), scene));
        return this;
    }

    /**
     * Draws the grid over a rendered image when this specification asks for one.
     *
     * @param camera the camera that rendered the image (its image writer receives the grid)
     */
    public void drawGrid(Camera camera) {
        if (gridInterval() > 0) camera.printGrid(gridInterval(), gridColor());
    }

    /** @return the stated values, by name: {@code RenderSettings[image=x 40x20, antiAliasing=RANDOM]} */
    @Override
    public String toString() {
        StringJoiner stated = new StringJoiner(", ", "RenderSettings[", "]");
        image.describe(stated);
        grid.describe(stated);
        antiAliasing.describe(stated);
        lens.describe(stated);
        Stated.add(stated, "seed", seed);
        Stated.add(stated, "threads", threads);
        tracer.describe(stated);
        return stated.toString();
    }
}
