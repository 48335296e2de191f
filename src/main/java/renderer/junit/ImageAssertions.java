package renderer.junit;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;

import org.junit.jupiter.api.TestReporter;
import org.opentest4j.AssertionFailedError;

import renderer.CallingTest;
import renderer.Camera;
import renderer.CameraReports;
import renderer.ImageWriter;
import renderer.junit.Comparison.Metrics;
import renderer.junit.Comparison.Status;

/**
 * Asserts that a render matches a reference image, with the metrics, limits and verdicts of the
 * project's OpenImageIO verification ({@code scripts/verify_images.py}): a channel difference on
 * the 0..1 scale per pixel, an image failing when too many pixels differ by more than
 * {@link ImageThresholds#failThreshold()} or one pixel by more than
 * {@link ImageThresholds#hardFail()}.
 *
 * <pre>{@code
 * camera.renderImage();
 * ImageAssertions.assertImageMatches(camera, "spheres");   // src/test/resources/spheres.png
 * }</pre>
 *
 * <p><b>References</b> are PNG files under {@code src/test/resources} of the project (the folder
 * Maven's Surefire names in the system property {@code basedir}; without it, as in an IDE, the
 * working directory, which is the project there; see {@link #withReferenceFolder}), named
 * by a relative path with or without ".png". They are read from that folder, not from the class
 * path, so that recording one and comparing with it touch the same file.
 *
 * <p><b>A failure</b> is an {@link AssertionFailedError} whose message gives the PSNR, the largest
 * difference and where it is, the share and count of failing pixels, and the paths of a diff
 * image (the difference × 20) and a heat map (black: none, blue: failThreshold, red: hardFail,
 * yellow: 0.25, white: 1). They are written next to the render: beside the PNG for a file (named
 * after it), and for a camera (with the render itself, since a camera's pixels are in memory)
 * under {@code target/image-assertions/<TestClass.testMethod>/}, named after the reference there,
 * so that two tests comparing with one reference keep their own files (outside a test, directly
 * under {@code target/image-assertions/}). The invocations of one parameterized test share its
 * folder: the last failure's files are there. A reference of another size or channel count, a missing reference and an
 * unreadable PNG each fail with one message naming the file, and write nothing.
 *
 * <p><b>Recording.</b> With {@code -Draytracer.updateReferences=true}, an assertion whose
 * reference is missing or differs in any pixel writes the render as the reference and fails
 * saying so (run again without the property to verify); an identical reference is left alone and
 * the assertion passes. Recording is refused, as a failure, when the environment variable
 * {@code CI} is set: references change only in a reviewed commit.
 *
 * <p>Instances are immutable settings; the static methods use {@link #defaults()}.
 */
public final class ImageAssertions {
    /** The system property that turns recording on: {@code -Draytracer.updateReferences=true}. */
    public static final String UPDATE_PROPERTY = "raytracer.updateReferences";
    /** The project folder: Surefire's {@code basedir}, else the working directory (an IDE's run). */
    private static final String PROJECT = System.getProperty("basedir", "");
    /** Where references are, by default: the project's {@code src/test/resources}. */
    public static final Path DEFAULT_REFERENCE_FOLDER = Path.of(PROJECT, "src", "test", "resources");
    /** Where a camera's failed render and its diff images go, by default: the project's {@code target/image-assertions}. */
    public static final Path DEFAULT_OUTPUT_FOLDER = Path.of(PROJECT, "target", "image-assertions");

    private static final ImageAssertions DEFAULTS = new ImageAssertions(ImageThresholds.DEFAULTS, DEFAULT_REFERENCE_FOLDER,
            DEFAULT_OUTPUT_FOLDER, null, System::getenv, System::getProperty);

    private final ImageThresholds thresholds;
    private final Path referenceFolder;
    private final Path outputFolder;
    /** Where verdicts are published; null: nowhere. */
    private final TestReporter reporter;
    /** The environment ({@code CI}) and the system properties, looked up at each assertion (a seam for tests). */
    private final UnaryOperator<String> environment;
    private final UnaryOperator<String> properties;

    private ImageAssertions(ImageThresholds thresholds, Path referenceFolder, Path outputFolder, TestReporter reporter,
                            UnaryOperator<String> environment, UnaryOperator<String> properties) {
        this.thresholds = thresholds;
        this.referenceFolder = referenceFolder;
        this.outputFolder = outputFolder;
        this.reporter = reporter;
        this.environment = environment;
        this.properties = properties;
    }

    /** @return the default settings: {@link ImageThresholds#DEFAULTS}, the default folders, no reporter */
    public static ImageAssertions defaults() {
        return DEFAULTS;
    }

    /**
     * Asserts with the {@link #defaults()} that the camera's image matches a reference.
     *
     * @param camera        a camera that has rendered
     * @param referenceName the reference's path under {@code src/test/resources}, ".png" optional
     * @throws AssertionFailedError     when the render does not match, the reference is missing or
     *                                  unreadable, or a reference was recorded
     * @throws IllegalArgumentException when the name is blank or leaves the reference folder
     */
    public static void assertImageMatches(Camera camera, String referenceName) {
        DEFAULTS.assertMatches(camera, referenceName);
    }

    /**
     * Asserts with the {@link #defaults()} that a PNG matches a reference.
     *
     * @param render        the rendered PNG
     * @param referenceName the reference's path under {@code src/test/resources}, ".png" optional
     * @throws AssertionFailedError     when the render does not match, either PNG is missing or
     *                                  unreadable, or a reference was recorded
     * @throws IllegalArgumentException when the name is blank or leaves the reference folder
     */
    public static void assertImageMatches(Path render, String referenceName) {
        DEFAULTS.assertMatches(render, referenceName);
    }

    /**
     * @param thresholds the limits to judge by
     * @return these settings with those limits
     * @throws NullPointerException when it is null
     */
    public ImageAssertions withThresholds(ImageThresholds thresholds) {
        return new ImageAssertions(Objects.requireNonNull(thresholds, "thresholds"), referenceFolder, outputFolder, reporter,
                environment, properties);
    }

    /**
     * @param folder where references are read and recorded (default {@code src/test/resources})
     * @return these settings with that folder
     * @throws NullPointerException when it is null
     */
    public ImageAssertions withReferenceFolder(Path folder) {
        return new ImageAssertions(thresholds, Objects.requireNonNull(folder, "reference folder"), outputFolder, reporter,
                environment, properties);
    }

    /**
     * @param folder where a camera's failed render and its diff images go, in a folder named after
     *               the calling test (default {@code target/image-assertions}); a PNG's go beside it
     * @return these settings with that folder
     * @throws NullPointerException when it is null
     */
    public ImageAssertions withOutputFolder(Path folder) {
        return new ImageAssertions(thresholds, referenceFolder, Objects.requireNonNull(folder, "output folder"), reporter,
                environment, properties);
    }

    /**
     * Publishes each verdict through a test's reporter, so that it shows in the IDE's test view
     * and in Surefire's report: the image, the reference, the verdict, the PSNR, the largest
     * difference and the failing pixels (and the diff images' paths on a failure).
     *
     * @param reporter the test's {@link TestReporter} (a parameter of the test method)
     * @return these settings with that reporter
     * @throws NullPointerException when it is null
     */
    public ImageAssertions reportingTo(TestReporter reporter) {
        return new ImageAssertions(thresholds, referenceFolder, outputFolder, Objects.requireNonNull(reporter, "reporter"),
                environment, properties);
    }

    /** A seam for tests: the environment and system properties to read instead of the JVM's. */
    ImageAssertions withLookups(UnaryOperator<String> environment, UnaryOperator<String> properties) {
        return new ImageAssertions(thresholds, referenceFolder, outputFolder, reporter, environment, properties);
    }

    /**
     * Asserts that the camera's image matches a reference.
     *
     * @param camera        a camera that has rendered
     * @param referenceName the reference's path under the reference folder, ".png" optional
     * @throws AssertionFailedError     when the render does not match, the reference is missing or
     *                                  unreadable, or a reference was recorded
     * @throws IllegalArgumentException when the name is blank or leaves the reference folder
     */
    public void assertMatches(Camera camera, String referenceName) {
        Objects.requireNonNull(camera, "camera");
        Path reference = reference(referenceName);
        ImageWriter image = camera.getImageWriter();
        Path stem = outputFolder.resolve(testFolder()).resolve(stem(referenceFolder.relativize(reference)));
        check(new Render("the render of " + CameraReports.imageLabel(camera), Picture.of(image), sibling(stem, ".png"), stem, true,
                image::writeToImage), reference);
    }

    /**
     * The folder, under the output folder, of the calling test's files: {@code TestClass.method}
     * (nested classes as {@code Outer.Inner.method}); empty outside a test.
     */
    private static String testFolder() {
        return CallingTest.find().map(test -> test.substring(0, test.length() - "()".length())).orElse("");
    }

    /**
     * Asserts that a PNG matches a reference.
     *
     * @param render        the rendered PNG
     * @param referenceName the reference's path under the reference folder, ".png" optional
     * @throws AssertionFailedError     when the render does not match, either PNG is missing or
     *                                  unreadable, or a reference was recorded
     * @throws IllegalArgumentException when the name is blank or leaves the reference folder
     */
    public void assertMatches(Path render, String referenceName) {
        Objects.requireNonNull(render, "render");
        Path reference = reference(referenceName);
        Picture picture;
        try {
            picture = Picture.read(render, "render");
        } catch (Picture.UnreadableException e) {
            throw fail(referenceName, reference, Comparison.without(Status.ERROR, e.getMessage()), e.getMessage());
        }
        check(new Render("render " + render, picture, render, stem(render), false, to -> copy(render, to)), reference);
    }

    /**
     * A render to check.
     *
     * @param what    how messages name it
     * @param picture its pixels
     * @param file     where its PNG is, or goes on a failure
     * @param stem     the path its diff images are named after (stem + ".diff.png")
     * @param inMemory whether it has no PNG yet (a camera's): one is written to {@code file} on a failure
     * @param writer   writes its PNG to the given file
     */
    private record Render(String what, Picture picture, Path file, Path stem, boolean inMemory, Consumer<Path> writer) {
    }

    private void check(Render render, Path reference) {
        String name = referenceFolder.relativize(reference).toString();
        if (Boolean.parseBoolean(properties.apply(UPDATE_PROPERTY))) {
            record(render, reference, name);
            return;
        }
        if (!Files.exists(reference)) {
            String message = "no reference image " + reference + " for " + render.what() + "; record it with -D" + UPDATE_PROPERTY
                    + "=true (refused when CI is set), look at it and commit it";
            throw fail(name, reference, Comparison.without(Status.MISSING_REFERENCE, message), message);
        }
        Picture expected;
        try {
            expected = Picture.read(reference, "reference");
        } catch (Picture.UnreadableException e) {
            throw fail(name, reference, Comparison.without(Status.ERROR, e.getMessage()), e.getMessage() + "; nothing was written");
        }
        Comparison result = Comparison.of(render.picture(), expected, thresholds);
        switch (result.status()) {
            case SIZE_MISMATCH -> throw fail(name, reference, result, render.what() + " does not match reference " + reference + ": "
                    + result.message() + "; nothing was written");
            case FAIL -> throw failed(render, reference, name, result, expected);
            case WARN -> {
                publish(name, reference, result, null, null);
                if (reporter == null) System.err.println(name + ": " + result.message());
            }
            default -> publish(name, reference, result, null, null);
        }
    }

    private AssertionFailedError failed(Render render, Path reference, String name, Comparison result, Picture expected) {
        Path diff = sibling(render.stem(), ".diff.png"), heat = sibling(render.stem(), ".heat.png");
        String written;
        try {
            if (render.inMemory()) render.writer().accept(render.file());
            DiffImages.write(render.picture(), expected, thresholds, diff, heat);
            written = "\n  diff:     " + diff + "\n  heat map: " + heat + "\n  render:   " + render.file();
        } catch (UncheckedIOException e) {
            written = "\n  (the diff images could not be written: " + e.getMessage() + ")";
            diff = heat = null;
        }
        Metrics m = result.metrics();
        String message = render.what() + " does not match reference " + reference + ": " + result.message() + "\n  "
                + figures(m) + written;
        publish(name, reference, result, diff, heat);
        return failure(message);
    }

    /** The figures a failure message and a report show. */
    private static String figures(Metrics m) {
        return String.format(Locale.ROOT,
                "PSNR %s dB, largest difference %.4f (%d of 255 steps) at pixel (%d,%d) channel %d, failing pixels %.3f%% (%d of %d), mean difference %.5f",
                Comparison.psnr(m.psnr()), m.maxError(), Math.round(m.maxError() * 255), m.maxX(), m.maxY(), m.maxChannel(),
                m.failPercent(), m.failing(), m.pixels(), m.meanError());
    }

    private void record(Render render, Path reference, String name) {
        String ci = environment.apply("CI");
        if (ci != null && !ci.isEmpty()) {
            String message = "refusing to record reference " + reference + ": -D" + UPDATE_PROPERTY
                    + " is set, and so is CI (CI='" + ci + "'); references are recorded on purpose on a developer machine and committed";
            throw fail(name, reference, Comparison.without(Status.ERROR, message), message);
        }
        String reason = updateReason(render.picture(), reference);
        if (reason == null) {
            publish(name, reference, Comparison.of(render.picture(), render.picture(), thresholds), null, null);
            return;
        }
        try {
            render.writer().accept(reference);
        } catch (UncheckedIOException e) {
            String message = "cannot record reference " + reference + ": " + e.getMessage();
            throw fail(name, reference, Comparison.without(Status.ERROR, message), message);
        }
        String message = "recorded reference " + reference + " (" + reason + ") from " + render.what()
                + "; look at it, commit it, and run again without -D" + UPDATE_PROPERTY + " to verify";
        throw fail(name, reference, Comparison.without(Status.FAIL, message), message);
    }

    /** As the script's --update: null when the reference holds the same pixels, else why it is rewritten. */
    private static String updateReason(Picture render, Path reference) {
        if (!Files.exists(reference)) return "new";
        Picture old;
        try {
            old = Picture.read(reference, "reference");
        } catch (Picture.UnreadableException e) {
            return "replacing an unreadable reference: " + e.getMessage();
        }
        Comparison exact = Comparison.of(render, old, ImageThresholds.DEFAULTS.withFailThreshold(0).withWarnThreshold(0));
        if (exact.status() == Status.SIZE_MISMATCH) return "changed: " + exact.message();
        Metrics m = exact.metrics();
        return m.maxError() > 0 ? String.format(Locale.ROOT, "changed: max error %s, %.3f%% of pixels differ",
                Comparison.g(m.maxError(), 4), m.failPercent()) : null;
    }

    private AssertionFailedError fail(String name, Path reference, Comparison result, String message) {
        publish(name, reference, result, null, null);
        return failure(message);
    }

    /** The failure, its stack trace starting at the caller: nothing of this class's insides. */
    private static AssertionFailedError failure(String message) {
        AssertionFailedError e = new AssertionFailedError(message);
        StackTraceElement[] trace = e.getStackTrace();
        int first = 0;
        while (first < trace.length && trace[first].getClassName().startsWith(ImageAssertions.class.getName())) ++first;
        e.setStackTrace(Arrays.copyOfRange(trace, first, trace.length));
        return e;
    }

    private void publish(String name, Path reference, Comparison result, Path diff, Path heat) {
        if (reporter == null) return;
        Map<String, String> entry = new LinkedHashMap<>();
        entry.put("image", name);
        if (reference != null) entry.put("reference", reference.toString());
        entry.put("verdict", result.status().label());
        Metrics m = result.metrics();
        if (m != null) {
            entry.put("PSNR", Comparison.psnr(m.psnr()) + " dB");
            entry.put("max difference", String.format(Locale.ROOT, "%.4f at (%d,%d) channel %d", m.maxError(), m.maxX(),
                    m.maxY(), m.maxChannel()));
            entry.put("failing pixels", String.format(Locale.ROOT, "%.3f%% (%d of %d)", m.failPercent(), m.failing(), m.pixels()));
        }
        if (!result.message().isBlank()) entry.put("message", result.message());
        if (diff != null) entry.put("diff", diff.toString());
        if (heat != null) entry.put("heat map", heat.toString());
        reporter.publishEntry(entry);
    }

    /** The reference file a name stands for, checked to stay inside the reference folder. */
    private Path reference(String referenceName) {
        Objects.requireNonNull(referenceName, "reference name");
        if (referenceName.isBlank()) throw new IllegalArgumentException("reference name must not be blank");
        String file = referenceName.endsWith(".png") ? referenceName : referenceName + ".png";
        Path relative = Path.of(file).normalize();
        if (relative.isAbsolute() || relative.startsWith(".."))
            throw new IllegalArgumentException("reference name '" + referenceName + "' must be a path inside the reference folder "
                    + referenceFolder + ", without '..' or a root");
        return referenceFolder.resolve(relative);
    }

    /** @return the path without its ".png" */
    private static Path stem(Path png) {
        String name = png.getFileName().toString();
        return png.resolveSibling(name.endsWith(".png") ? name.substring(0, name.length() - 4) : name);
    }

    private static Path sibling(Path stem, String suffix) {
        return stem.resolveSibling(stem.getFileName() + suffix);
    }

    /** Copies a PNG into place atomically: a temporary file beside the target, then moved. */
    private static void copy(Path from, Path to) {
        try {
            Path folder = to.toAbsolutePath().getParent();
            Files.createDirectories(folder);
            Path tmp = Files.createTempFile(folder, "." + to.getFileName(), ".tmp");
            try {
                Files.copy(from, tmp, StandardCopyOption.REPLACE_EXISTING);
                try {
                    Files.move(tmp, to, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(tmp, to, StandardCopyOption.REPLACE_EXISTING);
                }
            } finally {
                Files.deleteIfExists(tmp);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot copy " + from + " to " + to + ": " + e.getMessage(), e);
        }
    }
}
