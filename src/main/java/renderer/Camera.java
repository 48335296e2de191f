package renderer;

import java.io.PrintStream;
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
 * <p>A pinhole (or thin-lens) camera: a facade over its view, sampling and execution (see the
 * {@linkplain renderer package page}), its tracer and its image writer. Its settings do not change;
 * a render prepares the tracer for the scene as it is then, and fills the image writer.
 */
public final class Camera {
    /** Render threads per available core at most ({@link #maxThreads()}); far more would exhaust the machine's threads. */
    public static final int MAX_THREADS_PER_CORE = Execution.MAX_THREADS_PER_CORE;
    /** The most primary samples of a pixel, a RANDOM grid's or a lens's: 65,536 (256×256), so that a pixel ends. */
    public static final int MAX_SAMPLES_PER_PIXEL = Sampling.MAX_SAMPLES_PER_PIXEL;
    /** ADAPTIVE's deepest subdivision when none is set ({@link Builder#setAdaptive}): sub-pixels down to 1/8 of the side. */
    public static final int DEFAULT_ADAPTIVE_DEPTH = Sampling.DEFAULT_ADAPTIVE_DEPTH;
    /** ADAPTIVE's pixel-level corner spread that subdivides when none is set ({@link Builder#setAdaptive}), 0..255 scale. */
    public static final double DEFAULT_ADAPTIVE_THRESHOLD = Sampling.DEFAULT_ADAPTIVE_THRESHOLD;

    /** The view, sampling, execution and tracer, held to the ray budget together when built. */
    private final RenderSetup setup;
    private final ImageWriter imageWriter;
    /** Whether the camera made its writer from a resolution (not given one to share). */
    private final boolean ownWriter;
    /** Whom its renders and writes tell, and whether they print their lines. */
    private final CameraOutput output;

    private Camera(RenderSetup setup, ImageWriter imageWriter, boolean ownWriter, CameraOutput output) {
        this.setup = setup;
        this.imageWriter = imageWriter;
        this.ownWriter = ownWriter;
        this.output = output;
    }

    /** @return the most render threads this machine allows: {@link #MAX_THREADS_PER_CORE} per available core */
    public static int maxThreads() {
        return Execution.maxThreads();
    }

    /** @return a new builder with the defaults: no anti-aliasing, pinhole, calling thread, seed 0 */
    public static Builder getBuilder() {
        return new Builder();
    }

    /**
     * A builder starting from a built camera's settings, to render a second view: see {@link Builder#Builder(Camera)}.
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
        return view().location();
    }

    /** @return the unit view direction, through the view plane's centre */
    public Vector getVTo() {
        return view().frame().to();
    }

    /** @return the image's unit up direction, orthogonal to {@link #getVTo()} */
    public Vector getVUp() {
        return view().frame().up();
    }

    /** @return the image's unit right direction: vTo × vUp */
    public Vector getVRight() {
        return view().frame().right();
    }

    /** @return the image writer this camera renders into: to read a render back, say to compare it with a reference */
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
        return view().constructRay(nX, nY, j, i);
    }

    /**
     * The 2025–26 form of {@link #constructRay(int, int, int, int)}, at this camera's own resolution.
     *
     * @param j the column, 0 at the left
     * @param i the row, 0 at the top
     * @return the ray from the camera through that pixel's centre
     * @throws IllegalArgumentException for a pixel outside the resolution
     */
    public Ray constructRay(int j, int i) {
        return constructRay(imageWriter.getNx(), imageWriter.getNy(), j, i);
    }

    RenderSetup setup() {
        return setup;
    }

    View view() {
        return setup.view();
    }

    Sampling sampling() {
        return setup.sampling();
    }

    ImageWriter imageWriter() {
        return imageWriter;
    }

    RayTracerBase rayTracer() {
        return setup.tracer();
    }

    /** @return the sampling settings in words, for summaries and benchmark tables */
    String describe() {
        return setup.describe();
    }

    /**
     * Renders the image into the image writer and, unless silenced ({@link Builder#setSummary}),
     * prints one summary line: {@code render NAME: TIME, WxH [sampling] of scene 'SCENE', figures}
     * (docs/student-guide.md, "What a render prints"). While a JDK Flight Recorder recording runs,
     * the render is also a {@code raytracer.Render} event.
     *
     * @return the render's time and ray counts, as printed in the summary
     * @throws java.util.concurrent.CancellationException when the calling thread is interrupted
     * @throws java.util.ConcurrentModificationException  when the scene changed during the render
     *                                                    (shapes or lights added, say): the image
     *                                                    may mix two states and must not be written
     */
    public RenderStats render() {
        return output.render(this);
    }

    /**
     * Renders the image as {@link #render()} does: the course's spelling, for {@code renderImage().writeToImage()}.
     *
     * @return this camera, for chaining
     * @throws java.util.concurrent.CancellationException as {@link #render()}
     * @throws java.util.ConcurrentModificationException  as {@link #render()}
     */
    public Camera renderImage() {
        render();
        return this;
    }

    /**
     * Paints a grid over the image: every pixel whose column or row is a multiple of {@code interval}.
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
     * unless silenced prints {@code write NAME: /absolute/path.png in 0.042 s}.
     *
     * @return this camera, for chaining (the course's {@code void} callers ignore it)
     * @throws IllegalStateException when the camera's writer has no name (it was made from
     *                               {@link Builder#setResolution}): use {@link #writeToImage(String)}
     */
    public Camera writeToImage() {
        output.write(this, imageWriter.getPath());
        return this;
    }

    /**
     * Writes the image to images/&lt;imageName&gt;.png (the 2024–25 form), with the line of {@link #writeToImage()}.
     *
     * @param imageName the file name without ".png"; may contain sub-folders
     * @return this camera, for chaining (most 2024–25 sources return it; {@code void} callers ignore it)
     * @throws IllegalArgumentException for a blank name
     */
    public Camera writeToImage(String imageName) {
        output.write(this, ImageWriter.pathOf(imageName));
        return this;
    }

    /**
     * Collects camera settings: most setters check at once, the view plane and the resolution only
     * at {@link #build()}, which also gives the 2024–25 course's defaults (docs/student-guide.md,
     * "Which course year?", says why). A builder can be reused: each build makes an independent camera.
     */
    public static final class Builder {
        /** The location, direction, roll, view plane, resolution and lens, made into a View by build(). */
        private final ViewDraft draft;
        /** The writer given, which cameras built share; null: each camera makes its own of the resolution set. */
        private ImageWriter imageWriter;
        private RayTracerBase rayTracer;
        /** Every mode's parameters, the lens samples and the seed: each setter replaces one part. */
        private Sampling sampling = Sampling.DEFAULT;
        /** As set: -1 and -2 (all cores) are resolved when a camera is built. */
        private int threads;
        private double debugPrint;
        /** Whether lines are printed, where, and whom renders are told of: each setter replaces one part. */
        private CameraOutput output = CameraOutput.standard();

        /** The same as {@link Camera#getBuilder()}, for cohorts that write {@code new Camera.Builder()}. */
        public Builder() {
            CourseClassGuard.check();
            draft = new ViewDraft();
        }

        /**
         * A builder holding a built camera's settings, to change some and build another camera
         * (the camera is not changed; docs/student-guide.md, "Which course year?", says what the
         * two share). The direction is the camera's final frame, a thread count of -1 or -2 the
         * number of cores it became.
         *
         * @param camera the camera whose settings the builder starts from
         * @throws NullPointerException when camera is null, naming it
         */
        public Builder(Camera camera) {
            CourseClassGuard.check();
            Objects.requireNonNull(camera, "camera to copy");
            draft = new ViewDraft(camera.view());
            imageWriter = camera.ownWriter ? null : camera.imageWriter;
            rayTracer = camera.rayTracer();
            sampling = camera.sampling();
            threads = camera.setup.execution().threads();
            debugPrint = camera.setup.execution().progressStep();
            output = camera.output;
        }

        /**
         * @param location the camera's position
         * @return this builder
         */
        public Builder setLocation(Point location) {
            draft.location(location);
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
            draft.direction(to, up);
            return this;
        }

        /**
         * Looks at {@code target}; the image's up is the part of {@code up} orthogonal to the view direction.
         *
         * @param target the point at the image's centre
         * @param up     the up hint, not parallel to the view direction (checked by {@link #build()})
         * @return this builder
         */
        public Builder setDirection(Point target, Vector up) {
            draft.target(target, up);
            return this;
        }

        /**
         * Looks at {@code target} with +y as the up hint.
         *
         * @param target the point at the image's centre
         * @return this builder
         * @throws IllegalArgumentException from {@link #build()} when the target lies along ±y from the
         *                                  location: give an up with {@link #setDirection(Point, Vector)}
         */
        public Builder setDirection(Point target) {
            draft.target(target);
            return this;
        }

        /**
         * Turns the camera about its view direction (the 2025–26 course's roll), by the right-hand
         * rule: {@code rotate(90)} makes the old right the new up. It applies at {@link #build()},
         * to whichever direction is set, and calls add up (docs/student-guide.md, "Which course year?").
         *
         * @param degrees the angle in degrees, any int (taken modulo 360)
         * @return this builder
         */
        public Builder rotate(int degrees) {
            draft.roll(degrees);
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
            draft.size(width, height);
            return this;
        }

        /**
         * The view plane's distance from the location along the view direction; checked by {@link #build()}.
         *
         * @param distance a positive finite number of scene units
         * @return this builder
         */
        public Builder setVpDistance(double distance) {
            draft.distance(distance);
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
         * A course spelling of the BVH switch: does nothing, the render always walks the scene's BVH.
         *
         * @return this builder
         */
        public Builder enableBVH() {
            return this;
        }

        /**
         * The course's conservative bounding region (boxes tested before shapes): does nothing, the
         * render's BVH does that and more (as {@link #enableBVH()}).
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
            draft.resolution(imageWriter.getNx(), imageWriter.getNy());
            return this;
        }

        /**
         * The image size (the 2024–25 form; replaces an {@link #setImageWriter image writer}), checked by
         * {@link #build()}: each camera built makes its own writer, named by {@link Camera#writeToImage(String)}.
         *
         * @param nX the number of columns, positive
         * @param nY the number of rows, positive
         * @return this builder
         */
        public Builder setResolution(int nX, int nY) {
            draft.resolution(nX, nY);
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
         */
        public Builder setRayTracer(Scene scene, RayTracerType type) {
            Objects.requireNonNull(scene, "scene");
            return setRayTracer(Objects.requireNonNull(type, "ray tracer type").create(scene));
        }

        /**
         * @param mode how pixels are sampled (default NONE; {@link AntiAliasing} says what each mode does)
         * @return this builder
         */
        public Builder setAntiAliasing(AntiAliasing mode) {
            this.sampling = sampling.withAntiAliasing(mode);
            return this;
        }

        /**
         * RANDOM anti-aliasing with a grid of columns × rows jittered samples per pixel, in one line.
         *
         * @param mode    must be RANDOM
         * @param columns jittered samples across a pixel, ≥ 1
         * @param rows    jittered samples down a pixel, ≥ 1
         * @return this builder
         * @throws IllegalArgumentException for a mode other than RANDOM (the grid is RANDOM's; use
         *                                  {@link #setAdaptive} for ADAPTIVE) or a grid below 1×1
         */
        public Builder setAntiAliasing(AntiAliasing mode, int columns, int rows) {
            this.sampling = sampling.withRandomGrid(mode, columns, rows);
            return this;
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
         * ADAPTIVE's settings ({@link AntiAliasing#ADAPTIVE} says how they are used), other modes ignore
         * them: the deepest subdivision (default {@value #DEFAULT_ADAPTIVE_DEPTH}) and the threshold
         * (default {@value #DEFAULT_ADAPTIVE_THRESHOLD}).
         *
         * @param maxDepth  the deepest subdivision, 1..6
         * @param threshold the pixel-level corner spread that subdivides, finite and ≥ 0 (0: any difference does)
         * @return this builder
         * @throws IllegalArgumentException when either is out of range, naming it
         */
        public Builder setAdaptive(int maxDepth, double threshold) {
            this.sampling = sampling.withAdaptive(maxDepth, threshold);
            return this;
        }

        /**
         * Depth of field with a thin lens: objects at {@code focalDistance} stay sharp, the blur
         * grows with {@code apertureRadius}; aperture 0 is the pinhole camera.
         *
         * @param focalDistance  the distance of the sharp plane along the view direction, in scene units, positive
         * @param apertureRadius the lens radius in scene units, finite and ≥ 0
         * @return this builder
         * @throws IllegalArgumentException when either is out of range, naming it
         */
        public Builder setDepthOfField(double focalDistance, double apertureRadius) {
            draft.lens(View.Lens.thin(focalDistance, apertureRadius));
            return this;
        }

        /**
         * The pinhole camera, everything sharp (the default): turns off a depth of field set before.
         *
         * @return this builder
         */
        public Builder setPinhole() {
            draft.lens(View.Lens.PINHOLE);
            return this;
        }

        /**
         * Lens samples per pixel with depth of field and no anti-aliasing (default 16), stratified over the
         * lens; with anti-aliasing each sample takes its own lens point (docs/student-guide.md, "The
         * improvements in detail", compares the modes).
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
         *                {@link #maxThreads()}; -2, or the course's -1 ("parallel streams"): one per core
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
         * @param on whether each render prints its summary line and each write its line (default true)
         * @return this builder
         */
        public Builder setSummary(boolean on) {
            this.output = output.withSummary(on);
            return this;
        }

        /**
         * @param output where progress lines, the summary and the write line go (default System.out)
         * @return this builder
         */
        public Builder setOutput(PrintStream output) {
            this.output = this.output.withStream(Objects.requireNonNull(output, "output stream"));
            return this;
        }

        /**
         * Someone to tell of each render, after the render loop and before the summary line, on the
         * thread that called {@link Camera#render()}: {@code renderer.junit.RenderReports.to(testReporter)},
         * say (docs/student-guide.md, "Asserting images"). A {@link WriteListener} hears of the writes too.
         *
         * @param listener called with the camera and what its render did
         * @return this builder
         */
        public Builder setRenderListener(BiConsumer<? super Camera, ? super RenderStats> listener) {
            this.output = output.withListener(Objects.requireNonNull(listener, "render listener"));
            return this;
        }

        /**
         * Checks the settings and makes the camera, with a 1×1 image and a
         * {@link SimpleRayTracer} on an empty scene when none were given.
         *
         * @return a new camera, independent of cameras built before
         * @throws MissingResourceException naming the location or direction when it is missing
         * @throws IllegalArgumentException when the view plane's size or distance is missing, when it or the
         *                                  resolution is not positive (naming the value), when the settings
         *                                  contradict each other, or when a pixel would take more than
         *                                  {@link RayBudget#MAX_RAYS_PER_PIXEL} rays (docs/performance.md, "Limits")
         */
        public Camera build() {
            RenderSetup setup = setup(); // before the image is allocated: a refused budget costs no memory
            View.ViewPlane plane = setup.view().plane();
            ImageWriter writer = imageWriter != null ? imageWriter : new ImageWriter(plane.nX(), plane.nY());
            return new Camera(setup, writer, imageWriter == null, output);
        }

        /** The view of the settings alone, without an image or a tracer: {@link #build()}'s checks, in its order. */
        View view() {
            return draft.view();
        }

        /** The settings checked as {@link #build()} checks them (the view, then the ray budget), no image allocated. */
        RenderSetup setup() {
            return RenderSetup.check(view(), sampling, tracer(), threads, debugPrint, output.stream());
        }

        /** A renderer of rectangles of the image, checked as {@link #build()} checks (see {@link RegionRenderer#of(Builder)}). */
        RegionRenderer regionRenderer() {
            RenderSetup setup = setup();
            return new RegionRenderer(setup, imageWriter != null && imageWriter.hasName() ? imageWriter.getImageName() : "region");
        }

        /** Holds the settings to {@link #build()}'s ray budget with no view: it needs the sampling, lens and tracer alone. */
        void requireRayBudget() {
            RenderSetup.withinBudget(sampling, draft.lens(), tracer());
        }

        /** The tracer given, or a {@link SimpleRayTracer} on an empty scene. */
        private RayTracerBase tracer() {
            return rayTracer != null ? rayTracer : RayTracerType.SIMPLE.create(new Scene("empty scene"));
        }
    }
}
