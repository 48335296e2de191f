package renderer;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Locale;
import java.util.MissingResourceException;
import java.util.Objects;
import java.util.function.BiConsumer;


import primitives.Color;
import primitives.CourseClassGuard;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * The camera a scene test builds and renders with, every course year: {@link #getBuilder()}, then
 * a location, a direction, a view plane, the image (2023&ndash;24: {@link Builder#setImageWriter};
 * 2024&ndash;25 and 2025&ndash;26: {@link Builder#setResolution}) and a tracer, {@code build()},
 * and {@code renderImage()} and {@code writeToImage(...)}. The library's improvements
 * (anti-aliasing, depth of field, threads, progress) are one builder line each.
 *
 * <p>A pinhole (or thin-lens) camera: a facade over what it sees ({@link View}), how a render
 * samples ({@code Sampling}) and runs ({@code Execution}), the tracer that colours each camera
 * ray and the image writer that receives the pixels. Made by {@link Builder#build()}, which
 * checks each setting in the value that owns it. Shallowly immutable: its values do not change,
 * but the tracer stays mutable (a render holds it to the ray budget again and prepares it for
 * the scene as it is then) and the image writer receives each render's pixels. The pixel loop
 * itself lives in {@code RenderLoop}, the sampling strategies in the samplers.
 */
public final class Camera {
    /**
     * Render threads per available core at most: rendering is bound by the processor, so more
     * threads than cores gain nothing, and a few times more stay harmless; a count such as 100,000
     * would exhaust the native threads of the machine.
     */
    public static final int MAX_THREADS_PER_CORE = Execution.MAX_THREADS_PER_CORE;
    /**
     * The most primary samples of one pixel from the RANDOM grid (columns × rows) or the depth of
     * field's lens samples: 65,536 (a 256×256 grid), so that the count fits an int and a pixel
     * ends (ADAPTIVE's depth 6 stays below it, at most 65² lattice points).
     */
    public static final int MAX_SAMPLES_PER_PIXEL = Sampling.MAX_SAMPLES_PER_PIXEL;
    /** ADAPTIVE's deepest subdivision when none is set ({@link Builder#setAdaptive}): sub-pixels down to 1/8 of the side. */
    public static final int DEFAULT_ADAPTIVE_DEPTH = Sampling.DEFAULT_ADAPTIVE_DEPTH;
    /** ADAPTIVE's pixel-level corner spread that subdivides when none is set ({@link Builder#setAdaptive}), 0..255 scale. */
    public static final double DEFAULT_ADAPTIVE_THRESHOLD = Sampling.DEFAULT_ADAPTIVE_THRESHOLD;

    private final View view;
    private final Sampling sampling;
    private final Execution execution;
    private final RayTracerBase rayTracer;
    private final ImageWriter imageWriter;
    /** Whether the camera made its writer from a resolution (not given one to share). */
    private final boolean ownWriter;
    /** Whether a render prints its one-line summary and a write its line. */
    private final boolean summary;
    /** Told of each finished render (a test's report, for example); by default nobody. */
    private final BiConsumer<? super Camera, ? super RenderStats> renderListener;

    private Camera(View view, Sampling sampling, Execution execution, RayTracerBase rayTracer, ImageWriter imageWriter,
                   boolean ownWriter, boolean summary, BiConsumer<? super Camera, ? super RenderStats> renderListener) {
        this.view = view;
        this.sampling = sampling;
        this.execution = execution;
        this.rayTracer = rayTracer;
        this.imageWriter = imageWriter;
        this.ownWriter = ownWriter;
        this.summary = summary;
        this.renderListener = renderListener;
    }

    /**
     * @return the most render threads this machine allows: {@link #MAX_THREADS_PER_CORE} per
     *         available core
     */
    public static int maxThreads() {
        return Execution.maxThreads();
    }

    /** @return a new builder with the defaults: no anti-aliasing, pinhole, calling thread, seed 0 */
    public static Builder getBuilder() {
        return new Builder();
    }

    /**
     * A builder that starts from a built camera's settings (the form some cohorts use to render
     * a second view); see {@link Builder#Builder(Camera)}.
     *
     * @param camera the camera whose settings the builder starts from
     * @return a new builder holding those settings
     * @throws NullPointerException when camera is null, naming it
     */
    public static Builder getBuilder(Camera camera) {
        return new Builder(camera);
    }

    /** @return where the camera stands: the rays' common head (the lens centre with depth of field) */
    public Point getLocation() {
        return view.location();
    }

    /** @return the unit view direction, through the view plane's centre */
    public Vector getVTo() {
        return view.frame().to();
    }

    /** @return the image's unit up direction, orthogonal to {@link #getVTo()} */
    public Vector getVUp() {
        return view.frame().up();
    }

    /** @return the image's unit right direction: vTo × vUp */
    public Vector getVRight() {
        return view.frame().right();
    }

    /**
     * @return the image writer this camera renders into (the one given to the builder, or the one
     *         it made for {@link Builder#setResolution}): its pixels, size and name, for reading a
     *         render back, for example to compare it with a reference image
     */
    public ImageWriter getImageWriter() {
        return imageWriter;
    }

    /**
     * The ray from the camera through the centre of pixel (column j, row i) of a view plane cut
     * into nX × nY pixels.
     *
     * @param nX the number of columns the view plane is cut into, &gt; 0
     * @param nY the number of rows, &gt; 0
     * @param j  the column, 0 at the left, &lt; nX
     * @param i  the row, 0 at the top, &lt; nY
     * @return the ray from the camera location through the pixel's centre (unit direction)
     * @throws IllegalArgumentException for a non-positive resolution or a pixel outside it
     */
    public Ray constructRay(int nX, int nY, int j, int i) {
        return view.constructRay(nX, nY, j, i);
    }

    /**
     * The 2025–26 form of {@link #constructRay(int, int, int, int)}: the ray through the centre of
     * pixel (column j, row i) of this camera's own resolution (its image writer's).
     *
     * @param j the column, 0 at the left
     * @param i the row, 0 at the top
     * @return the ray from the camera through that pixel's centre
     * @throws IllegalArgumentException for a pixel outside the resolution
     */
    public Ray constructRay(int j, int i) {
        return constructRay(imageWriter.getNx(), imageWriter.getNy(), j, i);
    }

    View view() {
        return view;
    }

    Sampling sampling() {
        return sampling;
    }

    Execution execution() {
        return execution;
    }

    ImageWriter imageWriter() {
        return imageWriter;
    }

    RayTracerBase rayTracer() {
        return rayTracer;
    }

    /**
     * Renders the image into the image writer and returns what it did; prints the one-line
     * summary unless silenced ({@code render NAME: TIME, WxH [sampling] of scene 'SCENE', figures},
     * the time and figures being those of {@link RenderStats#toString()}). NAME is the image writer's name or, for a writer named only
     * when written ({@link Builder#setResolution}), the calling test method's
     * ({@code SpheresTest.twoSpheres()}). While a JDK Flight Recorder recording runs, the render
     * is also a {@code raytracer.Render} event.
     *
     * @return the render's time and ray counts, as printed in the summary
     * @throws java.util.concurrent.CancellationException when the calling thread is interrupted
     * @throws java.util.ConcurrentModificationException  when the scene changed during the render
     *                                                    (shapes or lights added, say): the image
     *                                                    may mix two states and must not be written
     */
    public RenderStats render() {
        String name = getImageLabel();
        String scene = getSceneName();
        RenderEvent event = ImageEvent.recording() ? new RenderEvent() : null; // see RenderEvent
        RenderStats stats = new RenderLoop(view, sampling, execution, rayTracer, imageWriter).render(name);
        if (event != null) event.commit(name, scene, imageWriter, sampling.antiAliasing(), stats);
        renderListener.accept(this, stats);
        if (summary) execution.output().println("render " + name + ": " + stats.time() + ", " + imageWriter.getNx() + "x"
                + imageWriter.getNy() + " [" + describe() + "] of scene '" + scene + "', " + stats.figures() + rayTracer.walk());
        return stats;
    }

    /**
     * The name the summary and write lines, progress lines, test reports and JFR events give the
     * image: its writer's name, or for an unnamed writer (named only when written, the 2024–25
     * flow) the calling test method ({@code SpheresTest.twoSpheres()}), or {@code (unnamed)}
     * outside a test.
     *
     * @return the image's name as this camera's reports show it
     */
    String getImageLabel() {
        return imageWriter.hasName() ? imageWriter.getImageName()
                : CallingTest.find().orElse(imageWriter.getImageName());
    }

    /**
     * @return the name of the scene this camera's tracer traces ({@link Scene#name}), as reports show it
     */
    String getSceneName() {
        return rayTracer.scene.name;
    }

    /**
     * Renders the image (see {@link #render()}); the course's spelling, for chaining
     * {@code renderImage().writeToImage()}.
     *
     * @return this camera, for chaining
     * @throws java.util.concurrent.CancellationException when the calling thread is interrupted
     * @throws java.util.ConcurrentModificationException  when the scene changed during the render
     */
    public Camera renderImage() {
        render();
        return this;
    }

    /** @return the sampling settings in words, for summaries and benchmark tables */
    String describe() {
        return describe(sampling, view.lens(), rayTracer);
    }

    /** The words of {@link #describe()}, for a camera or a builder's settings. */
    private static String describe(Sampling sampling, View.Lens lens, RayTracerBase tracer) {
        return sampling.describe(lens) + ", " + tracer.describe() + ", seed " + sampling.seed();
    }

    /**
     * Paints a grid over the image: every pixel whose column or row is a multiple of
     * {@code interval}.
     *
     * @param interval the grid's spacing in pixels, &gt; 0
     * @param color    the grid lines' colour
     * @return this camera, for chaining
     * @throws IllegalArgumentException when {@code interval} is not positive
     * @throws NullPointerException     when {@code color} is null
     */
    public Camera printGrid(int interval, Color color) {
        if (interval <= 0) throw new IllegalArgumentException("grid interval must be positive, got " + interval);
        Objects.requireNonNull(color, "grid color");
        for (int i = 0; i < imageWriter.getNy(); ++i)
            for (int j = 0; j < imageWriter.getNx(); ++j)
                if (i % interval == 0 || j % interval == 0) imageWriter.writePixel(j, i, color);
        return this;
    }

    /**
     * Writes the image to images/&lt;name&gt;.png, the name the image writer was made with, and
     * unless silenced prints {@code write NAME: /absolute/path.png in 0.042 s} (NAME as in the
     * render's summary).
     *
     * @return this camera, for chaining (the course's {@code void} callers ignore it)
     * @throws IllegalStateException when the camera's writer has no name (it was made from
     *                               {@link Builder#setResolution}): use {@link #writeToImage(String)}
     */
    public Camera writeToImage() {
        return write(imageWriter.getPath());
    }

    /**
     * Writes the image to images/&lt;imageName&gt;.png (the 2024–25 course's form) and prints the
     * line of {@link #writeToImage()}.
     *
     * @param imageName the file name without ".png"; may contain sub-folders
     * @return this camera, for chaining (most 2024–25 sources return it; {@code void} callers ignore it)
     * @throws IllegalArgumentException for a blank name
     */
    public Camera writeToImage(String imageName) {
        return write(ImageWriter.pathOf(imageName));
    }

    /**
     * Writes the PNG (a {@code raytracer.ImageWrite} JFR event while a recording runs), tells a
     * render listener that is also a {@link WriteListener}, and unless silenced prints a line with
     * the image's name, the file and the time it took, and says so when nothing was drawn on the
     * image (no render or grid: the PNG is all black).
     */
    private Camera write(Path file) {
        String name = getImageLabel();
        Path target = file.toAbsolutePath();
        long start = System.nanoTime();
        imageWriter.writeToImage(target); // the public method: a subclass of ImageWriter may override it
        double seconds = (System.nanoTime() - start) / 1e9;
        if (renderListener instanceof WriteListener listener) listener.written(this, target, seconds);
        if (summary) execution.output().println(String.format(Locale.ROOT, "write %s: %s in %.3f s", name, target, seconds)
                + (imageWriter.isBlank() ? " (" + ImageWriter.BLANK + ")" : ""));
        return this;
    }

    /**
     * Collects camera settings. Most setters validate at once; the view plane's size and distance
     * and the resolution are checked by {@link #build()} (the 2025–26 course sets them up first
     * and expects only {@code build()} to throw), still naming the bad value. A builder can be
     * reused: each build returns an independent camera.
     * <p>Defaults (the 2024–25 course's): without an image writer or resolution the image is
     * 1×1; without a tracer, a {@link SimpleRayTracer} on an empty scene.
     */
    public static final class Builder {
        private Point location;
        private Vector to, up;
        private Point target;
        private double vpWidth, vpHeight, vpDistance;
        private boolean vpSizeSet, vpDistanceSet;
        /** Degrees the frame is turned about the view direction at build ({@link #rotate}), in [0, 360). */
        private int roll;
        /** The resolution for a writer the camera makes itself; used when imageWriter is null. */
        private int nX = 1, nY = 1;
        private ImageWriter imageWriter;
        private RayTracerBase rayTracer;
        /** Every mode's parameters, the lens samples and the seed: each setter replaces one part. */
        private Sampling sampling = Sampling.DEFAULT;
        private View.Lens lens = View.Lens.PINHOLE;
        /** As set: -1 and -2 (all cores) are resolved when a camera is built. */
        private int threads;
        private double debugPrint;
        private boolean summary = true;
        private PrintStream output = System.out;
        private BiConsumer<? super Camera, ? super RenderStats> renderListener = (camera, stats) -> {
        };

        /** The same as {@link Camera#getBuilder()}, for cohorts that write {@code new Camera.Builder()}. */
        public Builder() {
            CourseClassGuard.check();
        }

        /**
         * A builder holding a built camera's settings, to change some and build another camera;
         * the camera is not changed. The two share the tracer, and the image writer when one was
         * given with {@link #setImageWriter}; a camera that made its own writer from
         * {@link #setResolution} passes on the resolution, so each camera built makes its own.
         * The direction is the camera's final frame (to and up); a thread count of -1 or -2 is
         * passed on as the number of cores it became.
         *
         * @param camera the camera whose settings the builder starts from
         * @throws NullPointerException when camera is null, naming it
         */
        public Builder(Camera camera) {
            this();
            Objects.requireNonNull(camera, "camera to copy");
            View view = camera.view;
            location = view.location();
            to = view.frame().to();
            up = view.frame().up();
            vpWidth = view.plane().width();
            vpHeight = view.plane().height();
            vpDistance = view.plane().distance();
            vpSizeSet = vpDistanceSet = true;
            nX = camera.imageWriter.getNx();
            nY = camera.imageWriter.getNy();
            imageWriter = camera.ownWriter ? null : camera.imageWriter;
            rayTracer = camera.rayTracer;
            sampling = camera.sampling;
            lens = view.lens();
            threads = camera.execution.threads();
            debugPrint = camera.execution.progressStep();
            summary = camera.summary;
            output = camera.execution.output();
            renderListener = camera.renderListener;
        }

        /**
         * @param location the camera's position
         * @return this builder
         */
        public Builder setLocation(Point location) {
            this.location = Objects.requireNonNull(location, "camera location");
            return this;
        }

        /**
         * Looks along {@code to} with {@code up} as the image's up direction.
         *
         * @param to the view direction, any length
         * @param up the image's up direction, any length
         * @return this builder
         * @throws IllegalArgumentException when the two are not orthogonal
         */
        public Builder setDirection(Vector to, Vector up) {
            View.Frame frame = View.Frame.along(to, up);
            this.to = frame.to();
            this.up = frame.up();
            this.target = null;
            return this;
        }

        /**
         * Looks at {@code target}; {@code up} need not be orthogonal to the view direction: the
         * image's up is its part orthogonal to it.
         *
         * @param target the point at the image's centre
         * @param up     the up hint, not parallel to the view direction (checked by {@link #build()})
         * @return this builder
         */
        public Builder setDirection(Point target, Vector up) {
            this.target = Objects.requireNonNull(target, "camera target");
            this.up = Objects.requireNonNull(up, "camera up").normalize();
            this.to = null;
            return this;
        }

        /**
         * Looks at {@code target} with +y as the up hint (the image's up is its part orthogonal
         * to the view direction).
         *
         * @param target the point at the image's centre
         * @return this builder
         * @throws IllegalArgumentException from {@link #build()} when the target lies straight
         *                                  along ±y from the location (no up can be derived;
         *                                  give one with {@link #setDirection(Point, Vector)})
         */
        public Builder setDirection(Point target) {
            this.target = Objects.requireNonNull(target, "camera target");
            this.up = null;
            this.to = null;
            return this;
        }

        /**
         * Turns the camera about its view direction by {@code degrees} (the 2025–26 course's
         * camera roll). The sign follows the right-hand rule about the view direction: a positive
         * angle takes the image's up toward its right, so {@code rotate(90)} makes the old right
         * the new up; seen from behind the camera it turns clockwise, and the scene turns
         * counter-clockwise in the image. The turn applies to whichever direction is set, before
         * or after this call, when {@link #build()} makes the frame; calls add up
         * ({@code rotate(30).rotate(60)} is {@code rotate(90)}).
         *
         * @param degrees the angle in degrees, any int (taken modulo 360)
         * @return this builder
         */
        public Builder rotate(int degrees) {
            this.roll = Math.floorMod(roll + Math.floorMod(degrees, 360), 360);
            return this;
        }

        /**
         * The view plane's size in scene units; checked by {@link #build()}.
         *
         * @param width  the width, a positive finite number
         * @param height the height, a positive finite number
         * @return this builder
         */
        public Builder setVpSize(double width, double height) {
            this.vpWidth = width;
            this.vpHeight = height;
            this.vpSizeSet = true;
            return this;
        }

        /**
         * The view plane's distance from the location along the view direction; checked by
         * {@link #build()}.
         *
         * @param distance a positive finite number of scene units
         * @return this builder
         */
        public Builder setVpDistance(double distance) {
            this.vpDistance = distance;
            this.vpDistanceSet = true;
            return this;
        }

        /**
         * Another course spelling of {@link #setVpSize}.
         *
         * @param width  the width, a positive finite number
         * @param height the height, a positive finite number
         * @return this builder
         */
        public Builder setViewPlaneSize(double width, double height) {
            return setVpSize(width, height);
        }

        /**
         * Another course spelling of {@link #setVpDistance}.
         *
         * @param distance a positive finite number of scene units
         * @return this builder
         */
        public Builder setViewPlaneDistance(double distance) {
            return setVpDistance(distance);
        }

        /**
         * A course spelling of the bounding-volume switch on the camera: does nothing, the render
         * always walks the scene's BVH (as {@link Scene#buildBVH()}).
         *
         * @return this builder
         */
        public Builder enableBVH() {
            return this;
        }

        /**
         * The course's conservative bounding region (boxes tested before shapes): does nothing,
         * the render's BVH does that and more (as {@link #enableBVH()}).
         *
         * @return this builder
         */
        public Builder enableCBR() {
            return this;
        }

        /**
         * The writer the camera renders into (the 2023–24 form; replaces a
         * {@link #setResolution resolution} given before). Cameras built with it share it.
         *
         * @param imageWriter the writer, which also fixes the resolution
         * @return this builder
         */
        public Builder setImageWriter(ImageWriter imageWriter) {
            this.imageWriter = Objects.requireNonNull(imageWriter, "image writer");
            this.nX = imageWriter.getNx();
            this.nY = imageWriter.getNy();
            return this;
        }

        /**
         * The image size (the 2024–25 form): each built camera makes its own unnamed writer of
         * this size (replaces an {@link #setImageWriter image writer} given before); name the
         * file with {@link Camera#writeToImage(String)}. Checked by {@link #build()}.
         *
         * @param nX the number of columns, positive
         * @param nY the number of rows, positive
         * @return this builder
         */
        public Builder setResolution(int nX, int nY) {
            this.nX = nX;
            this.nY = nY;
            this.imageWriter = null;
            return this;
        }

        /**
         * @param rayTracer the tracer that colours each camera ray
         * @return this builder
         */
        public Builder setRayTracer(RayTracerBase rayTracer) {
            this.rayTracer = Objects.requireNonNull(rayTracer, "ray tracer");
            return this;
        }

        /**
         * A new tracer of the given kind for {@code scene} (the 2024–25 form); see
         * {@link RayTracerType} for what each kind gives.
         *
         * @param scene the scene to trace
         * @param type  the kind of tracer
         * @return this builder
         * @throws NullPointerException when scene or type is null
         */
        public Builder setRayTracer(Scene scene, RayTracerType type) {
            Objects.requireNonNull(scene, "scene");
            return setRayTracer(Objects.requireNonNull(type, "ray tracer type").create(scene));
        }

        /**
         * @param mode how pixels are sampled (default NONE)
         * @return this builder
         */
        public Builder setAntiAliasing(AntiAliasing mode) {
            this.sampling = sampling.withAntiAliasing(mode);
            return this;
        }

        /**
         * RANDOM anti-aliasing with a grid of columns × rows jittered samples per pixel (one line
         * for both settings).
         *
         * @param mode    must be RANDOM
         * @param columns jittered samples across a pixel, ≥ 1
         * @param rows    jittered samples down a pixel, ≥ 1
         * @return this builder
         * @throws IllegalArgumentException for a mode other than RANDOM (the grid is RANDOM's; use
         *                                  {@link #setAdaptive} for ADAPTIVE) or a grid below 1×1
         */
        public Builder setAntiAliasing(AntiAliasing mode, int columns, int rows) {
            if (mode != AntiAliasing.RANDOM)
                throw new IllegalArgumentException("a " + columns + "x" + rows + " grid applies to RANDOM anti-aliasing only, got "
                        + mode + (mode == AntiAliasing.ADAPTIVE ? " (use setAdaptive(depth, threshold))" : ""));
            setAntiAliasingGrid(columns, rows);
            return setAntiAliasing(mode);
        }

        /**
         * The RANDOM grid: columns × rows samples per pixel (default 4×4); other modes ignore it.
         *
         * @param columns jittered samples across a pixel, ≥ 1
         * @param rows    jittered samples down a pixel, ≥ 1
         * @return this builder
         * @throws IllegalArgumentException for a grid below 1×1 or of more than
         *                                  {@link #MAX_SAMPLES_PER_PIXEL} samples, naming it
         */
        public Builder setAntiAliasingGrid(int columns, int rows) {
            this.sampling = sampling.withGrid(columns, rows);
            return this;
        }

        /**
         * ADAPTIVE's settings ({@link AntiAliasing#ADAPTIVE} says how they are used): the deepest
         * subdivision (default {@value Camera#DEFAULT_ADAPTIVE_DEPTH}) and the threshold (default
         * {@value Camera#DEFAULT_ADAPTIVE_THRESHOLD}); other modes ignore them.
         *
         * @param maxDepth  the deepest subdivision, 1..6
         * @param threshold the pixel-level corner spread that subdivides, finite and ≥ 0 (0: any
         *                  difference subdivides; corners that agree exactly, as on a flat
         *                  background, never do)
         * @return this builder
         * @throws IllegalArgumentException when either is out of range, naming it
         */
        public Builder setAdaptive(int maxDepth, double threshold) {
            this.sampling = sampling.withAdaptive(maxDepth, threshold);
            return this;
        }

        /**
         * Depth of field with a thin lens: objects at {@code focalDistance} (along the view
         * direction, scene units) stay sharp, the blur grows with {@code apertureRadius}
         * (scene units). Aperture 0 is the pinhole camera.
         *
         * @param focalDistance  the distance of the sharp plane, positive and finite
         * @param apertureRadius the lens radius, finite and ≥ 0
         * @return this builder
         * @throws IllegalArgumentException when either is out of range, naming it
         */
        public Builder setDepthOfField(double focalDistance, double apertureRadius) {
            this.lens = View.Lens.thin(focalDistance, apertureRadius);
            return this;
        }

        /**
         * The pinhole camera, everything sharp (the default): turns off a depth of field set before.
         *
         * @return this builder
         */
        public Builder setPinhole() {
            this.lens = View.Lens.PINHOLE;
            return this;
        }

        /**
         * Lens samples per pixel with depth of field and no anti-aliasing (default 16), stratified
         * over the lens (16 cover it as a jittered 4×4 grid would); with anti-aliasing, each
         * anti-aliasing sample takes its own lens point instead.
         *
         * @param samples rays per pixel, 1 to {@link #MAX_SAMPLES_PER_PIXEL}
         * @return this builder
         * @throws IllegalArgumentException when it is below 1 or above the limit
         */
        public Builder setDepthOfFieldSamples(int samples) {
            this.sampling = sampling.withLensSamples(samples);
            return this;
        }

        /**
         * Another course spelling of {@link #setDepthOfFieldSamples}.
         *
         * @param samples rays per pixel, 1 to {@link #MAX_SAMPLES_PER_PIXEL}
         * @return this builder
         */
        public Builder setDofRays(int samples) {
            return setDepthOfFieldSamples(samples);
        }

        /**
         * The seed every random number of the render derives from (default 0): the same seed gives
         * the same image on any number of threads.
         *
         * @param seed any value
         * @return this builder
         */
        public Builder setSeed(long seed) {
            this.sampling = sampling.withSeed(seed);
            return this;
        }

        /**
         * @param threads 0: render on the calling thread; n &gt; 0: n worker threads, at most
         *                {@link #maxThreads()}; -2: one per available core; -1 (the course's
         *                "parallel streams"): the same as -2, the library's one render loop on all
         *                cores
         * @return this builder
         * @throws IllegalArgumentException for another value, naming it and the limit
         */
        public Builder setMultithreading(int threads) {
            this.threads = Execution.requireThreads(threads);
            return this;
        }

        /**
         * @param percentStep print a progress line each time this much more is done (0..100]; 0: none
         * @return this builder
         * @throws IllegalArgumentException when it is outside [0, 100]
         */
        public Builder setDebugPrint(double percentStep) {
            this.debugPrint = Progress.requireStep(percentStep);
            return this;
        }

        /**
         * @param on whether to print the one-line summary after each render and the line with the
         *           file and its time after each write (default true)
         * @return this builder
         */
        public Builder setSummary(boolean on) {
            this.summary = on;
            return this;
        }

        /**
         * @param output where progress lines, the summary and the write line go (default System.out)
         * @return this builder
         * @throws NullPointerException when it is null
         */
        public Builder setOutput(PrintStream output) {
            this.output = Objects.requireNonNull(output, "output stream");
            return this;
        }

        /**
         * Someone to tell of each render, after the render loop and before the summary line: for
         * example {@code renderer.junit.RenderReports.to(testReporter)}, which publishes the
         * render's figures in a JUnit test's report. It runs on the thread that called
         * {@link Camera#render()}. A listener that is also a {@link WriteListener} is told of
         * each {@code writeToImage} of the camera as well, after the PNG is in place.
         *
         * @param listener called with the camera and what its render did
         * @return this builder
         * @throws NullPointerException when it is null
         */
        public Builder setRenderListener(BiConsumer<? super Camera, ? super RenderStats> listener) {
            this.renderListener = Objects.requireNonNull(listener, "render listener");
            return this;
        }

        /**
         * Checks the view settings alone and returns the {@link View} they make, without an image
         * or a tracer. The checks and messages are {@link #build()}'s, in the same order.
         *
         * @return the view of the current settings (the resolution is the image writer's, or the
         *         one set, 1×1 by default)
         * @throws MissingResourceException naming the location or direction when it is missing
         * @throws IllegalArgumentException when the view plane's size or distance is missing,
         *                                  when it or the resolution is not positive (naming the
         *                                  value), or when a target is the location or lies along
         *                                  the up direction from it
         */
        View view() {
            final String missing = "Missing rendering data";
            final String camera = "Camera";
            if (location == null) throw new MissingResourceException(missing + ": location", camera, "location");
            if (to == null && target == null) throw new MissingResourceException(missing + ": direction", camera, "direction");
            if (!vpSizeSet) throw new IllegalArgumentException(missing + ": view plane size (setVpSize)");
            View.ViewPlane.requireSize(vpWidth, vpHeight);
            if (!vpDistanceSet) throw new IllegalArgumentException(missing + ": view plane distance (setVpDistance)");
            View.ViewPlane plane = new View.ViewPlane(vpWidth, vpHeight, vpDistance, nX, nY);
            View.Frame frame = (to != null ? View.Frame.of(to, up) : View.Frame.lookingAt(location, target, up)).rolled(roll);
            return new View(location, frame, plane, lens);
        }

        /**
         * Checks the settings and makes the camera, with a 1×1 image and a
         * {@link SimpleRayTracer} on an empty scene when none were given.
         *
         * @return a new camera, independent of cameras built before
         * @throws MissingResourceException naming the location or direction when it is missing
         * @throws IllegalArgumentException when the view plane's size or distance is missing, when
         *                                  it or the resolution is not positive (naming the
         *                                  value), when the settings contradict each other, or
         *                                  when a pixel would take more than
         *                                  {@link RayBudget#MAX_RAYS_PER_PIXEL} rays (camera
         *                                  samples × (1 + 2 beams) × (1 + shadow samples × the
         *                                  scene's soft lights + its other lights), naming them)
         */
        public Camera build() {
            View view = view();
            RayTracerBase tracer = tracer();
            // Before the image is allocated: a refused budget costs no memory.
            SamplerPlan plan = withinBudget(view.lens(), tracer);
            ImageWriter writer = imageWriter != null ? imageWriter : new ImageWriter(nX, nY);
            return new Camera(view, sampling, execution(plan), tracer, writer, imageWriter == null, summary, renderListener);
        }

        /**
         * Checks the settings as {@link #build()} does and makes a renderer of rectangles of the
         * image, without allocating the image (see {@link RegionRenderer#of(Builder)}).
         */
        RegionRenderer regionRenderer() {
            View view = view();
            RayTracerBase tracer = tracer();
            SamplerPlan plan = withinBudget(view.lens(), tracer);
            String name = imageWriter != null && imageWriter.hasName() ? imageWriter.getImageName() : "region";
            return new RegionRenderer(view, sampling, execution(plan), tracer, name);
        }

        /**
         * Checks the settings as {@link #build()} does, without allocating the image or preparing
         * the scene (see {@link CameraReports#describe(Builder)}).
         *
         * @return the settings in words, as the built camera's summary line will show them
         */
        String describeChecked() {
            View view = view();
            RayTracerBase tracer = tracer();
            withinBudget(view.lens(), tracer);
            return describe(sampling, view.lens(), tracer);
        }

        /**
         * Holds the settings to the ray budget as {@link #build()} does, with no view: the budget
         * depends on the sampling, the lens, the tracer and its scene's lights alone (see
         * {@link CameraReports#requireRayBudget(Builder)}).
         */
        void requireRayBudget() {
            withinBudget(lens, tracer());
        }

        /** The sampling's plan under {@code lens}, its ray budget held with {@code tracer}. */
        private SamplerPlan withinBudget(View.Lens lens, RayTracerBase tracer) {
            SamplerPlan plan = sampling.plan(!lens.isPinhole());
            tracer.requireRayBudget(plan);
            return plan;
        }

        /** The execution of a camera with this builder's settings, the tile size its sampler's. */
        private Execution execution(SamplerPlan sampling) {
            return new Execution(Execution.resolveThreads(threads), sampling.tileSize(), debugPrint, output);
        }

        /** The tracer given, or a {@link SimpleRayTracer} on an empty scene. */
        private RayTracerBase tracer() {
            return rayTracer != null ? rayTracer : RayTracerType.SIMPLE.create(new Scene("empty scene"));
        }
    }
}
