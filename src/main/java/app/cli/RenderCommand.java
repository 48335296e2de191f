package app.cli;

import static app.cli.CommandSpecs.addHelpOptions;
import static app.cli.CommandSpecs.exitCodes;
import static app.cli.CommandSpecs.given;
import static app.cli.CommandSpecs.option;
import static app.cli.CommandSpecs.value;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.ServiceLoader;
import java.util.concurrent.Callable;
import java.util.function.Supplier;

import picocli.CommandLine;
import picocli.CommandLine.Help;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;
import picocli.CommandLine.Model.UsageMessageSpec;
import picocli.CommandLine.ParameterException;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.Execution;
import renderer.ImageWriter;
import renderer.ImageWriters;
import scene.Scene;
import scene.io.FileSource;
import scene.io.Limits;
import scene.io.LoadedScene;
import scene.io.Messages;
import scene.io.RenderSettings;
import scene.io.SceneFormatException;
import scene.io.XmlSceneReader;
import scene.samples.Showcase;

/**
 * The command line ({@code java -jar raytracer.jar}): renders a scene file, or the built-in showcase, into a PNG.
 * Command-line options override the file's settings. Exit codes: 0 success, 1 a failure while
 * rendering or writing the image (not enough memory for the image included), 2 bad input (a usage
 * error or an invalid scene file). Bad input, a failed write and an image too large for the memory
 * are each reported in one line on the error stream, not as a stack trace, and leave no image.
 */
public final class RenderCommand implements Callable<Integer> {
    /** Exit code of a render or write failure. */
    public static final int FAILURE = 1;
    /** Exit code of bad input: a usage error or an invalid scene file. */
    public static final int BAD_INPUT = 2;
    /** The name that starts each error line. */
    static final String NAME = "raytracer";
    /** Percent between progress lines when the output is not a terminal. */
    private static final double LOG_STEP = 10;
    /** Percent between redraws of the terminal progress bar. */
    private static final double BAR_STEP = 1;

    /**
     * The stated limits, for --help: each is refused with a message that names it. Each line fits
     * picocli's 80 columns (a longer one wraps to column 0, out of the table). Made when the help
     * is written, not with the class: their string concatenations and String.format were the
     * first of the process, and on JDK 17 the first of each starts the JVM's machinery for it,
     * which a render with --quiet never needs otherwise.
     */
    private static String[] limits() {
        return new String[] {
                "  threads            at most " + Camera.MAX_THREADS_PER_CORE + " per core (" + Camera.maxThreads() + " here)",
                "  samples per pixel  at most " + Camera.MAX_SAMPLES_PER_PIXEL + " (RANDOM grid, depth-of-field samples)",
                "  rays per pixel     at most " + RenderSettings.MAX_RAYS_PER_PIXEL + ": samples per pixel",
                "                     (grid, adaptive, lens) x (1 + 2 x beam-size)",
                "                     x (1 + shadow-samples x lights with a radius",
                "                     + other lights); deeper bounces counted as traced",
                "  image              at most " + RenderSettings.MAX_PIXELS + " pixels, written to images/<name>.png:",
                "                     a name of at most " + RenderSettings.MAX_IMAGE_NAME_LENGTH + " characters, no / \\ : ..",
                "                     and no control, invisible or space-like character",
                "                     other than the space (U+202E, U+3164, U+00A0...)",
                "  scene file         at most " + Limits.MAX_SCENE_BYTES + " bytes, elements nested at most "
                        + Limits.MAX_NESTING_DEPTH + " deep,",
                "                     numbers at most " + magnitude(Limits.MAX_MAGNITUDE) + " in magnitude,",
                "                     sizes and factors 0 or at least " + magnitude(Limits.MIN_MAGNITUDE),
                "  OBJ file           a regular .obj file inside the scene file's folder",
                "                     (or --mesh-root), of at most " + Limits.MAX_OBJ_BYTES + " bytes, streamed,",
                "                     lines of at most " + Limits.MAX_OBJ_LINE_LENGTH + " characters",
                "  memory             what does not fit in Java's heap (-Xmx) fails at once" };
    }

    /** 1e9 rather than 1.0E9. */
    private static String magnitude(double d) {
        return String.format(Locale.ROOT, "%.0e", d).replace("e+0", "e").replace("e-0", "e-");
    }

    /*
     * The options' values, set from the parse at the start of call(). The model that declares them
     * is model(): picocli's programmatic API rather than its annotations (see there for why).
     */
    private Path scene;
    private Path output;
    private Integer width;
    private Integer height;
    private Integer threads;
    private AntiAliasing antiAliasing;
    private Long seed;
    private boolean quiet;
    private Path meshRoot;
    // ===== Spark: more scene files as frames, one option, and a branch into app.spark =====
    private List<Path> frames = List.of();
    private String spark;
    // ===== end Spark =====

    private final CommandSpec spec;
    /** Starts the PNG encoder's set-up (EncoderWarmUp.start; a test's own to see a failing one handled). */
    private final Supplier<EncoderWarmUp> encoderSetUp;
    private final PrintStream out;
    private final PrintStream err;
    private final boolean terminal;

    /**
     * @param out          where progress, the summary and the result go
     * @param err          where errors go
     * @param terminal     whether {@code out} is an interactive terminal (progress bar) or not (lines)
     * @param encoderSetUp starts the PNG encoder's set-up, once per render, beside the scene's reading
     */
    RenderCommand(PrintStream out, PrintStream err, boolean terminal, Supplier<EncoderWarmUp> encoderSetUp) {
        this.encoderSetUp = encoderSetUp;
        this.out = out;
        this.err = err;
        this.terminal = terminal;
        this.spec = model(this);
    }

    /*
     * The options' names, each written once: the model declares them, call() reads their values
     * back by them.
     */
    private static final String SCENE = "SCENE", OUTPUT = "--output", WIDTH = "--width", HEIGHT = "--height",
            THREADS = "--threads", AA = "--aa", SEED = "--seed", QUIET = "--quiet", MESH_ROOT = "--mesh-root",
            MORE = "MORE", SPARK = "--spark";

    /**
     * The command's model for picocli, in its programmatic API rather than annotations (see
     * {@link CommandSpecs} for why): call() takes the values from the parse.
     */
    private static CommandSpec model(RenderCommand command) {
        CommandSpec spec = CommandSpec.wrapWithoutInspection(command).name("java -jar raytracer.jar")
                .versionProvider(new Version());
        spec.usageMessage().sortOptions(false).autoWidth(true)
                .description("Renders a scene file into a PNG image. The scene format is described in docs/scene-format.md.",
                        "Without a scene, renders the built-in showcase (600x600, adaptive anti-aliasing) into images/showcase.png.")
                .exitCodeListHeading("%nExit codes:%n")
                .exitCodeList(exitCodes("0", "the image was written",
                        "1", "the render or the writing failed (e.g. not enough memory for the image)",
                        "2", "bad input: a usage error or an invalid scene file (nothing is written)"));
        spec.addPositional(PositionalParamSpec.builder().index("0").arity("0..1").paramLabel(SCENE).type(Path.class)
                .description("The scene file (XML). Default: the built-in showcase.").build());
        spec.addOption(OptionSpec.builder("-o", OUTPUT).type(Path.class).paramLabel("FILE")
                .description("The PNG file to write. Default: images/<image name>.png.").build());
        spec.addOption(option(WIDTH, Integer.class, "N",
                "Image width in pixels. Given alone, the height follows the file's aspect ratio.").build());
        spec.addOption(option(HEIGHT, Integer.class, "N",
                "Image height in pixels. Given alone, the width follows the file's aspect ratio.").build());
        spec.addOption(option(THREADS, Integer.class, "N", "Render threads: N > 0 worker threads (at most "
                + Camera.MAX_THREADS_PER_CORE + " per core), 0 the calling thread, -1 or -2 all cores. Default: the file's,"
                + " else all cores.").build());
        spec.addOption(option(AA, AntiAliasing.class, "MODE", "Anti-aliasing: ${COMPLETION-CANDIDATES} (case-insensitive);"
                + " the parameters stay the file's. Default: the file's, else NONE.").build());
        spec.addOption(option(SEED, Long.class, "N",
                "The seed of every random number of the render. Default: the file's, else 0.").build());
        spec.addOption(OptionSpec.builder("-q", QUIET).type(boolean.class).description("Print nothing but errors.").build());
        spec.addOption(option(MESH_ROOT, Path.class, "DIR", "The folder a scene file's meshes may be read from,"
                + " sub-folders included. Default: the scene file's own folder: a mesh path outside it (absolute, '../',"
                + " a link leading out) or without the .obj extension is refused unread.").build());
        // ===== Spark =====
        spec.addPositional(PositionalParamSpec.builder().index("1..*").arity("0..*").paramLabel(MORE).type(List.class)
                .auxiliaryTypes(Path.class).description("With --spark: more scene files, rendered as the frames of one"
                        + " Spark job (one PNG each).").build());
        spec.addOption(OptionSpec.builder(SPARK).type(String.class).paramLabel("MASTER").description(
                "Render on Apache Spark, byte-identical to the local render: MASTER is a Spark master URL (local[2],"
                        + " spark://HOST:7077, yarn, k8s://...) or 'submit' for the --master of spark-submit.",
                "Needs the command line built with Spark (mvn -Pspark package) and Spark on the class path (the 'spark'"
                        + " Maven profile or spark-submit; see docs/spark.md).",
                "A cluster master needs the runnable jar: under spark-submit, or with java -cp target/raytracer.jar and"
                        + " Spark's jars (the command ships the jar); from the Maven profile's class folders only local[N]"
                        + " runs, and a cluster master is refused at once.").build());
        // ===== end Spark =====
        addHelpOptions(spec);
        return spec;
    }

    /**
     * Runs the command on the process's streams.
     *
     * @param args the command line, as {@code main} receives it
     * @return the exit code: 0 done, 1 failure while rendering, 2 bad input or usage error
     */
    public static int run(String... args) {
        return commandLine(System.out, System.err, System.console() != null).execute(args);
    }

    /** The command line, with its streams, ready to {@code execute}. */
    static CommandLine commandLine(PrintStream out, PrintStream err, boolean terminal) {
        return commandLine(out, err, terminal, EncoderWarmUp::start);
    }

    /** As {@link #commandLine(PrintStream, PrintStream, boolean)}, with the PNG encoder's set-up {@code encoderSetUp} starts. */
    static CommandLine commandLine(PrintStream out, PrintStream err, boolean terminal, Supplier<EncoderWarmUp> encoderSetUp) {
        CommandLine cl = new CommandLine(new RenderCommand(out, err, terminal, encoderSetUp).spec);
        cl.addSubcommand("migrate", new CommandLine(new MigrateCommand(out, err).spec()));
        UsageMessageSpec usage = cl.getCommandSpec().usageMessage().footerHeading("%nLimits (docs/scene-format.md, \"Limits\"):%n");
        // The footer as picocli writes one (Help.footer), its lines made only then (see limits()).
        usage.sectionMap().put(UsageMessageSpec.SECTION_KEY_FOOTER, help -> Help.join(help.ansi(), usage.width(),
                usage.adjustLineBreaksForWideCJKCharacters(), limits(), new StringBuilder()).toString());
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.registerConverter(Path.class, CommandSpecs::path);
        cl.setOut(new PrintWriter(out, true, StandardCharsets.UTF_8));
        cl.setErr(new PrintWriter(err, true, StandardCharsets.UTF_8));
        cl.setParameterExceptionHandler((e, args) -> {
            usageError(e.getCommandLine(), e.getMessage());
            return BAD_INPUT;
        });
        cl.setExecutionExceptionHandler((e, commandLine, parseResult) -> {
            if (e instanceof ParameterException pe) {
                usageError(commandLine, pe.getMessage());
                return BAD_INPUT;
            }
            // A failure while rendering or writing: one line; the stack trace helps no user.
            commandLine.getErr().println(NAME + ": failed: " + describe(e));
            return FAILURE;
        });
        return cl;
    }

    private static void usageError(CommandLine commandLine, String message) {
        PrintWriter w = commandLine.getErr();
        w.println(NAME + ": " + Messages.visible(message));
        w.println("Try 'java -jar raytracer.jar --help' for more information.");
    }

    private static String describe(Throwable e) {
        String message = e.getMessage();
        // A message may quote a file's or a user's text: nothing in it reaches the terminal raw.
        return message == null || message.isBlank() ? e.getClass().getSimpleName() : Messages.visible(message);
    }

    @Override
    public Integer call() {
        long start = System.nanoTime();
        readOptions();
        checkOptions();
        if (spark != null || !frames.isEmpty()) return spark();
        // Beside the scene's reading, on the core it leaves idle; awaited before the render.
        EncoderWarmUp encoder = encoderSetUp.get();
        Job job;
        try {
            job = scene == null ? showcase() : load(scene, meshRoot);
        } catch (SceneFormatException e) {
            err.println(e.getMessage());
            return BAD_INPUT;
        } catch (IOException e) {
            err.println(Messages.visible(Messages.cannotReadScene(scene, e)));
            return BAD_INPUT;
        } catch (OutOfMemoryError e) {
            // Meshes within the size limits can still outgrow a small heap: one line, at once; the
            // OBJ reader's names the file, its size and the triangles read.
            err.println(named(e) ? NAME + ": " + Messages.visible(e.getMessage())
                    : NAME + ": not enough memory to load " + Messages.visible(String.valueOf(scene)) + maxMemory()
                    + " (give Java more memory with -Xmx)");
            return FAILURE;
        }
        RenderSettings settings = override(job.settings(), job.scene());
        Path target = output != null ? output : ImageWriter.IMAGES.resolve(settings.imageName() + ".png");

        // The one image of the run, at its final size: the reader allocated none.
        ImageWriter image;
        try {
            image = settings.newImageWriter();
        } catch (OutOfMemoryError e) {
            err.println(notEnoughMemory(settings));
            return FAILURE;
        }
        Camera camera;
        PrintStream progress = out;
        ProgressBar bar = null;
        try {
            settings.applyTo(job.view(), job.scene(), image).setSummary(!quiet);
            if (quiet) {
                job.view().setDebugPrint(0);
            } else if (terminal) {
                bar = new ProgressBar(out);
                progress = new PrintStream(bar, true, StandardCharsets.UTF_8);
                job.view().setDebugPrint(BAR_STEP);
            } else {
                job.view().setDebugPrint(LOG_STEP);
            }
            camera = job.view().setOutput(progress).build();
        } catch (IllegalArgumentException e) {
            // A value the camera refuses that neither the reader nor the options rejected: bad
            // input all the same, in one line.
            err.println(Messages.visible(job.source() + ": " + e.getMessage()));
            return BAD_INPUT;
        }

        try {
            encoder.await();
        } catch (IOException e) {
            err.println(NAME + ": " + Messages.visible(e.getMessage()));
            return FAILURE;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println(NAME + ": interrupted before the render");
            return FAILURE;
        }
        try {
            camera.render();
        } catch (OutOfMemoryError e) {
            // The BVH's build names itself; anything else, the render as a whole: one line either way.
            err.println(outOfMemory(e, "render " + settings.imageName() + " (" + settings.width() + "x"
                    + settings.height() + ")"));
            return FAILURE;
        } finally {
            if (bar != null) bar.finish();
        }
        settings.drawGrid(camera);
        try {
            image.writeToImage(target);
        } catch (UncheckedIOException e) {
            err.println(NAME + ": " + Messages.visible(e.getMessage()));
            return FAILURE;
        } catch (OutOfMemoryError e) { // the PNG encoder's own copy of the pixels
            err.println(outOfMemory(e, "write " + target + " (" + settings.width() + "x" + settings.height() + ")"));
            return FAILURE;
        }
        if (!quiet)
            out.println(String.format(Locale.ROOT, "wrote %s (%dx%d) in %.2f s", target, settings.width(),
                    settings.height(), (System.nanoTime() - start) / 1e9));
        return 0;
    }

    /**
     * The Spark render (a {@link SparkRunner}, which only a build with Spark has): the scene
     * files with this command's overrides and progress, on the cluster {@code --spark} names.
     */
    private int spark() {
        if (spark == null) throw usage("several scene files are rendered only with --spark, as the frames of one job");
        if (scene == null) throw usage("--spark needs a scene file (the built-in showcase is scenes/showcase.xml)");
        List<Path> scenes = new ArrayList<>();
        scenes.add(scene);
        scenes.addAll(frames);
        if (output != null && scenes.size() > 1)
            throw usage("--output names one file, for one scene; frames go to images/<image name>.png each");
        Optional<SparkRunner> runner = ServiceLoader.load(SparkRunner.class, RenderCommand.class.getClassLoader())
                .findFirst();
        if (runner.isEmpty()) {
            err.println(NAME + ": --spark needs the command line built with Spark, which this jar was not: "
                    + SparkRunner.HOW_TO_RUN);
            return BAD_INPUT;
        }
        PrintStream progress = out;
        ProgressBar bar = null;
        double step = quiet ? 0 : LOG_STEP;
        if (!quiet && terminal) {
            bar = new ProgressBar(out);
            progress = new PrintStream(bar, true, StandardCharsets.UTF_8);
            step = BAR_STEP;
        }
        try {
            return runner.get().run(new SparkRequest(spark, scenes, this::override, output, step, !quiet, meshRoot), progress, out, err);
        } finally {
            if (bar != null) bar.finish();
        }
    }

    /** The options' values from the parse (null where an option was not given). */
    private void readOptions() {
        scene = value(spec, SCENE);
        output = value(spec, OUTPUT);
        width = value(spec, WIDTH);
        height = value(spec, HEIGHT);
        threads = value(spec, THREADS);
        antiAliasing = value(spec, AA);
        seed = value(spec, SEED);
        quiet = given(spec, QUIET);
        meshRoot = value(spec, MESH_ROOT);
        List<Path> more = value(spec, MORE);
        frames = more != null ? more : List.of();
        spark = value(spec, SPARK);
    }

    /** Option values that picocli's types do not already rule out. */
    private void checkOptions() {
        if (width != null && width < 1) throw usage("--width must be at least 1, got " + width);
        if (height != null && height < 1) throw usage("--height must be at least 1, got " + height);
        if (threads != null) {
            try {
                Execution.requireThreads(threads);
            } catch (IllegalArgumentException e) {
                throw usage("--threads: " + e.getMessage());
            }
        }
        if (meshRoot != null && !Files.isDirectory(meshRoot))
            throw usage("--mesh-root must name a folder, got '" + meshRoot + "'");
        if (output != null) {
            Path name = output.getFileName();
            if (name == null || !name.toString().toLowerCase(Locale.ROOT).endsWith(".png"))
                throw usage("--output must name a .png file, got '" + output + "'");
        }
    }

    private ParameterException usage(String message) {
        return new ParameterException(spec.commandLine(), message);
    }

    /**
     * The file's settings, then the command line's options, a second specification replayed after
     * the file's (see {@link #options(RenderSettings)}).
     *
     * @param scene the file's scene: its lights count in the ray budget, as when its camera builds
     * @throws ParameterException for a size with too many pixels, or an {@code --aa} that takes
     *                            the file's values over the ray budget
     */
    RenderSettings override(RenderSettings file, Scene scene) {
        RenderSettings settings = file.then(options(file));
        if (antiAliasing != null) {
            try {
                settings.requireRayBudget(scene);
            } catch (IllegalArgumentException e) { // the file's grid or depth, now used, exceeds the ray budget
                throw usage("--aa " + antiAliasing + ": " + e.getMessage());
            }
        }
        return settings;
    }

    /**
     * The options as a specification: only the values they state.
     *
     * @param file the file's settings: a size option given alone keeps their aspect ratio
     * @throws ParameterException for a size with too many pixels
     */
    private RenderSettings options(RenderSettings file) {
        RenderSettings options = RenderSettings.empty();
        if (width != null || height != null) {
            // One side alone keeps the file's aspect ratio, so the view plane is not stretched.
            int w = width != null ? width : otherSide("--height", height, file.height(), file.width());
            int h = height != null ? height : otherSide("--width", width, file.width(), file.height());
            try {
                options = options.withImageSize(w, h);
            } catch (IllegalArgumentException e) {
                String names = width == null ? "--height" : height == null ? "--width" : "--width/--height";
                throw usage(names + ": " + e.getMessage());
            }
        }
        if (threads != null) options = options.withThreads(threads);
        if (antiAliasing != null) options = options.withAntiAliasing(antiAliasing);
        if (seed != null) options = options.withSeed(seed);
        return options;
    }

    /**
     * The side that follows a given one at the file's aspect ratio: {@code given} pixels where the
     * file has {@code fileGiven}, so {@code fileOther × given / fileGiven}, rounded, at least 1.
     */
    private int otherSide(String option, int given, int fileGiven, int fileOther) {
        long side = Math.max(1, Math.round((double) fileOther * given / fileGiven));
        if (side > Integer.MAX_VALUE)
            throw usage(option + " " + given + " at the file's aspect ratio makes the other side " + side
                    + " pixels, more than an image can hold");
        return (int) side;
    }

    /**
     * The one line for an image the JVM cannot allocate: the pixel buffer (4 bytes a pixel, the
     * one allocation that grows with the image) against the most memory this JVM may use.
     */
    private static String notEnoughMemory(RenderSettings s) {
        return NAME + ": " + ImageWriters.memoryNeeded(s.width(), s.height())
                + " (render it smaller with --width or --height, or give Java more memory with -Xmx)";
    }

    /**
     * The one line for an {@code OutOfMemoryError} while rendering or writing: the library's own
     * message when it named what needed the memory (the BVH, an image), else what was being done,
     * the limit and the option that raises it.
     */
    static String outOfMemory(OutOfMemoryError e, String doing) {
        if (named(e)) return NAME + ": " + Messages.visible(e.getMessage());
        return NAME + ": not enough memory to " + Messages.visible(doing) + maxMemory()
                + " (give Java more memory with -Xmx, or render it smaller)";
    }

    /**
     * Whether the library named what needed the memory (its size, the limit and the option) in
     * the error's one-line message: the BVH's build, an image, an OBJ file.
     */
    static boolean named(OutOfMemoryError e) {
        String message = e.getMessage();
        return message != null && !message.contains("\n")
                && (message.startsWith("the BVH ") || message.startsWith("image ") || message.startsWith("the OBJ file "));
    }

    /** "; Java may use at most N MB here", or nothing when the JVM states no limit. */
    private static String maxMemory() {
        long max = Runtime.getRuntime().maxMemory();
        return max == Long.MAX_VALUE ? "" : "; Java may use at most " + (max >> 20) + " MB here";
    }

    /**
     * What to render: a scene, a camera builder with only the view set, the settings to apply to
     * it, and where they came from (for messages).
     */
    private record Job(Scene scene, Camera.Builder view, RenderSettings settings, String source) {
    }

    private static Job load(Path file, Path meshRoot) throws IOException, SceneFormatException {
        LoadedScene loaded = XmlSceneReader.read(file, FileSource.DISK, meshRoot);
        return new Job(loaded.scene(), loaded.requireView(), loaded.settings(), file.toString());
    }

    /** The built-in showcase, framed as in its documentation. */
    private static Job showcase() {
        Scene scene = Showcase.create();
        Camera.Builder camera = Camera.getBuilder()
                .setLocation(Showcase.CAMERA_LOCATION).setDirection(Showcase.CAMERA_TARGET, Vector.AXIS_Y)
                .setVpSize(Showcase.VP_SIZE, Showcase.VP_SIZE).setVpDistance(Showcase.VP_DISTANCE);
        RenderSettings settings = RenderSettings.defaults("showcase").withImage("showcase", 600, 600)
                .withAntiAliasing(AntiAliasing.ADAPTIVE);
        return new Job(scene, camera, settings, "showcase");
    }

    /** The version from the jar's manifest; a build from the sources has none. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String version = RenderCommand.class.getPackage().getImplementationVersion();
            return new String[] { "raytracer " + (version != null ? version : "development build"),
                    "Java " + System.getProperty("java.version") + ", " + Runtime.getRuntime().availableProcessors()
                            + " cores" };
        }
    }
}
