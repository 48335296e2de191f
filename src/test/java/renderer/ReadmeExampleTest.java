package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Parameter;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import javax.imageio.ImageIO;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Named;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.TestReporter;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import app.Project;
import renderer.junit.ImageAssertions;
import scene.io.XmlSceneReader;

/**
 * The Java blocks of the README and of every Markdown file under {@code docs/}, exactly as
 * printed: each one is a whole source file (a top-level class with its imports; a fragment is
 * marked {@code text}) that compiles against the library and the test class path, and each one
 * runs: a block with {@code @Test} methods has them run as JUnit would, and a block of static
 * methods is called by a nested test below that checks what it promises. An example can therefore
 * never drift from the code.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class ReadmeExampleTest {
    private static final Path README = Project.file("README.md");
    private static final Path DOCS = Project.file("docs");
    private static final Path STUDENT_GUIDE = DOCS.resolve("student-guide.md");
    private static final Path SCENE_FORMAT = DOCS.resolve("scene-format.md");
    private static final Path SPARK = DOCS.resolve("spark.md");
    private static final Pattern CLASS_NAME = Pattern.compile("^(?:public\\s+)?(?:final\\s+)?class\\s+(\\w+)", Pattern.MULTILINE);

    /**
     * The blocks run by a nested test below rather than by {@link #everyTestMethodPasses}: their
     * tests need more than a call (a picture checked, a failure expected), or they have no
     * {@code @Test} method and a nested test calls them. The value says which.
     */
    private static final Map<String, String> RUN_BELOW = Map.of(
            "SpheresTest", "TwoSpheres", "TeapotTest", "Teapot", "SphereImageTest", "SphereImage",
            "CapturedSummary", "Summary", "RenderSceneFile", "SceneFiles", "PreviewSceneFile", "SceneFiles",
            "SparkRenderExample", "SparkExample");

    /** The compiled blocks of each document, compiled at most once per run. */
    private final Map<Path, List<Class<?>>> compiled = new HashMap<>();
    private final List<URLClassLoader> loaders = new ArrayList<>();
    private Path work;

    @BeforeAll
    void workFolder(@TempDir Path work) {
        this.work = work;
    }

    @AfterAll
    void closeLoaders() throws IOException {
        for (URLClassLoader loader : loaders) loader.close();
    }

    /** @return README.md and every Markdown file under docs/, in a fixed order */
    static Stream<Path> documents() throws IOException {
        try (Stream<Path> docs = Files.walk(DOCS)) {
            List<Path> all = new ArrayList<>(List.of(README));
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(all::add);
            return all.stream();
        }
    }

    /** The documents as the parameterized tests' arguments, each shown by its name. */
    static Stream<Arguments> eachDocument() throws IOException {
        return documents().map(d -> Arguments.of(Named.of(name(d), d)));
    }

    /** The document's name as its tests show it: README.md, docs/student-guide.md. */
    private static String name(Path document) {
        return Project.file("").toAbsolutePath().relativize(document.toAbsolutePath()).toString();
    }

    static List<String> javaBlocks(String markdown) {
        return blocks(markdown, "java");
    }

    /** The fenced blocks of {@code language} ({@code java}, {@code xml}) in {@code markdown}, in order. */
    static List<String> blocks(String markdown, String language) {
        List<String> found = new ArrayList<>();
        Matcher m = Pattern.compile("^```" + language + "\\n(.*?)^```$", Pattern.MULTILINE | Pattern.DOTALL).matcher(markdown);
        while (m.find()) found.add(m.group(1));
        return found;
    }

    private static List<String> javaBlocks(Path document) {
        try {
            return javaBlocks(Files.readString(document));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String className(String block) {
        Matcher name = CLASS_NAME.matcher(block);
        return name.find() ? name.group(1) : null;
    }

    /**
     * @return whether this test run has the Spark build (app.spark and Spark itself) on its class
     *         path; both are asked, as a run without -Pspark after one with it finds app.spark's
     *         classes left in target/classes but not Spark
     */
    private static boolean sparkBuild() {
        try {
            Class.forName("app.spark.SparkRenderer", false, ReadmeExampleTest.class.getClassLoader());
            Class.forName("org.apache.spark.SparkContext", false, ReadmeExampleTest.class.getClassLoader());
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }

    /** Surefire names the test class path in a property (its own class path is a manifest-only jar). */
    private static String testClassPath() {
        return System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"));
    }

    /**
     * Compiles the document's Java blocks (once), each as the file its class names, with every
     * warning an error, and loads their classes. The Spark example needs the Spark build (the
     * profile {@code spark}, {@code -Pspark}); a test run without it compiles the other blocks.
     */
    private synchronized List<Class<?>> classes(Path document) throws IOException {
        List<Class<?>> done = compiled.get(document);
        if (done != null) return done;
        List<String> blocks = javaBlocks(document);
        if (!sparkBuild()) blocks = blocks.stream().filter(b -> !b.contains("import org.apache.spark.")).toList();
        Path folder = work.resolve("doc" + compiled.size());
        Path sources = Files.createDirectories(folder.resolve("src"));
        Path out = Files.createDirectories(folder.resolve("classes"));
        List<File> files = new ArrayList<>();
        for (String block : blocks) {
            Path file = sources.resolve(className(block) + ".java");
            Files.writeString(file, block);
            files.add(file.toFile());
        }
        List<Class<?>> classes = new ArrayList<>();
        if (!files.isEmpty()) {
            JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
            DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
            try (StandardJavaFileManager fm = javac.getStandardFileManager(diagnostics, Locale.ROOT, StandardCharsets.UTF_8)) {
                // -proc:none: the test class path holds annotation processors (log4j's, through the
                // provided Spark dependency) that the blocks do not need.
                List<String> options = List.of("-classpath", testClassPath(), "-d", out.toString(),
                        "-proc:none", "-Xlint:all", "-Werror", "-encoding", "UTF-8");
                boolean ok = javac.getTask(null, fm, diagnostics, options, null, fm.getJavaFileObjectsFromFiles(files)).call();
                assertThat(diagnostics.getDiagnostics()).as("javac's messages on the Java blocks of %s", name(document)).isEmpty();
                assertThat(ok).as("the Java blocks of %s compile", name(document)).isTrue();
            }
            URLClassLoader loader = new URLClassLoader(new URL[] { out.toUri().toURL() }, getClass().getClassLoader());
            loaders.add(loader);
            for (File file : files) {
                try {
                    classes.add(loader.loadClass(file.getName().replace(".java", "")));
                } catch (ClassNotFoundException e) {
                    throw new AssertionError("compiled but not found: " + file, e);
                }
            }
        }
        compiled.put(document, classes);
        return classes;
    }

    private Class<?> type(Path document, String simpleName) throws IOException {
        return classes(document).stream().filter(c -> c.getSimpleName().equals(simpleName)).findFirst()
                .orElseThrow(() -> new AssertionError("no Java block of " + name(document) + " declares " + simpleName));
    }

    private static List<Method> testMethods(Class<?> type) {
        List<Method> tests = new ArrayList<>();
        for (Method m : type.getDeclaredMethods())
            if (m.isAnnotationPresent(Test.class)) tests.add(m);
        return tests;
    }

    /**
     * Runs every {@code @Test} method of {@code type}, each on a fresh instance, as JUnit does; a
     * {@code TestReporter} parameter gets one that collects the entries in {@code reported}.
     */
    private static void runTests(Class<?> type, List<Map<String, String>> reported) throws ReflectiveOperationException {
        List<Method> tests = testMethods(type);
        assertThat(tests).as("@Test methods of %s", type.getSimpleName()).isNotEmpty();
        Constructor<?> constructor = type.getDeclaredConstructor();
        constructor.setAccessible(true);
        for (Method test : tests) {
            test.setAccessible(true);
            List<Object> arguments = new ArrayList<>();
            for (Parameter p : test.getParameters()) {
                assertThat(p.getType()).as("a parameter this runner can give to %s", test).isEqualTo(TestReporter.class);
                arguments.add((TestReporter) entry -> reported.add(new LinkedHashMap<>(entry)));
            }
            try {
                test.invoke(constructor.newInstance(), arguments.toArray());
            } catch (InvocationTargetException e) {
                throw new AssertionError(type.getSimpleName() + "." + test.getName() + " failed", e.getCause());
            }
        }
    }

    /** Runs {@code call} with System.out captured; returns what it printed (and prints it too). */
    private static String capturingOutput(ThrowingRunnable call) throws Exception {
        PrintStream console = System.out;
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
        try {
            call.run();
        } finally {
            System.setOut(console);
        }
        String text = printed.toString(StandardCharsets.UTF_8);
        console.print(text);
        return text;
    }

    @FunctionalInterface
    private interface ThrowingRunnable {
        void run() throws Exception;
    }

    private static BufferedImage readAndDelete(String name) throws IOException {
        Path png = Path.of("images", name + ".png");
        assertThat(png).exists();
        BufferedImage image = ImageIO.read(png.toFile());
        Files.delete(png);
        return image;
    }

    private static int red(int rgb) {
        return (rgb >> 16) & 0xFF;
    }

    private static int green(int rgb) {
        return (rgb >> 8) & 0xFF;
    }

    private static int blue(int rgb) {
        return rgb & 0xFF;
    }

    @Test
    @DisplayName("the documents are README.md and docs/**/*.md, and their Java blocks are there")
    void documentsAreFound() throws IOException {
        assertThat(documents().map(ReadmeExampleTest::name))
                .contains("README.md", "docs/student-guide.md", "docs/scene-format.md", "docs/spark.md");
        assertThat(javaBlocks(README)).as("README.md's Java blocks").isNotEmpty();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("eachDocument")
    @DisplayName("each Java block is a whole file: a top-level class and its imports")
    void everyJavaBlockIsAWholeFile(Path document) {
        assertThat(javaBlocks(document)).allSatisfy(block -> {
            assertThat(className(block)).as("a Java block of %s declares a top-level class (a fragment is ```text):%n%s",
                    name(document), block).isNotNull();
            assertThat(block).as("a Java block of %s has its imports", name(document)).contains("import ");
        });
    }

    @Test
    @DisplayName("no two Java blocks, in all the documents, declare the same class")
    void classNamesAreUnique() throws IOException {
        List<String> names = documents().flatMap(d -> javaBlocks(d).stream()).map(ReadmeExampleTest::className).toList();
        assertThat(names).doesNotHaveDuplicates();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("eachDocument")
    @DisplayName("the Java blocks compile as printed, without a warning")
    void everyJavaBlockCompiles(Path document) throws IOException {
        assertThat(classes(document)).hasSizeLessThanOrEqualTo(javaBlocks(document).size());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("eachDocument")
    @DisplayName("each block runs: its @Test methods pass here, or a nested test below runs it")
    void everyTestMethodPasses(Path document) throws Exception {
        for (Class<?> type : classes(document)) {
            if (RUN_BELOW.containsKey(type.getSimpleName())) continue;
            assertThat(testMethods(type)).as("%s of %s has @Test methods, or a nested test runs it (RUN_BELOW)",
                    type.getSimpleName(), name(document)).isNotEmpty();
            runTests(type, new ArrayList<>());
        }
    }

    @Test
    @DisplayName("every block a nested test runs is still in the documents")
    void runBelowNamesExistingBlocks() throws IOException {
        Set<String> names = Set.copyOf(documents().flatMap(d -> javaBlocks(d).stream()).map(ReadmeExampleTest::className).toList());
        assertThat(names).containsAll(RUN_BELOW.keySet());
    }

    @Nested
    @DisplayName("README.md: the first scene test, 5786 names")
    class TwoSpheres {
        @Test
        @DisplayName("renders images/twoSpheres.png: the inner sphere seen through the outer one; the lines printed are the README's")
        void rendersAndPrintsTheQuotedSummary() throws Exception {
            Files.deleteIfExists(Path.of("images", "twoSpheres.png"));
            Class<?> test = type(README, "SpheresTest");
            String printed = capturingOutput(() -> runTests(test, new ArrayList<>()));

            BufferedImage image = readAndDelete("twoSpheres");
            assertThat(image.getWidth()).isEqualTo(500);
            assertThat(image.getHeight()).isEqualTo(500);
            // The centre looks through the transparent outer sphere (kT 0.3) at the orange inner
            // one: more red than blue, unlike the rim, which shows the blue outer sphere alone.
            int centre = image.getRGB(250, 250), rim = image.getRGB(250, 250 - 150);
            assertThat(red(centre)).as("centre red").isGreaterThan(blue(centre));
            assertThat(blue(rim)).as("rim blue").isGreaterThan(red(rim));

            // The README quotes the summary this render prints; with setResolution the image is
            // named after the test method. Sampling is deterministic, so every count must match;
            // only the times and the machine's core count may differ.
            String readme = Files.readString(README);
            String named = "SpheresTest.twoSpheres()";
            Matcher quoted = Pattern.compile("`(render " + Pattern.quote(named) + ": [^`]*)`").matcher(readme);
            assertThat(quoted.find()).as("the README quotes the summary line").isTrue();
            String line = printed.lines().filter(l -> l.startsWith("render " + named + ": ")).findFirst()
                    .orElseThrow(() -> new AssertionError("no summary line printed:\n" + printed));
            assertThat(withoutTimes(quoted.group(1))).isEqualTo(withoutTimes(line));

            // And the line the write printed: the file, where this machine's project lies blanked.
            Matcher quotedWrite = Pattern.compile("`(write " + Pattern.quote(named) + ": [^`]*)`").matcher(readme);
            assertThat(quotedWrite.find()).as("the README quotes the write line").isTrue();
            String write = printed.lines().filter(l -> l.startsWith("write " + named + ": ")).findFirst()
                    .orElseThrow(() -> new AssertionError("no write line printed:\n" + printed));
            assertThat(withoutTimes(quotedWrite.group(1))).isEqualTo(withoutTimes(write));
        }
    }

    /**
     * A summary or write line with its machine-dependent figures (times, rates, thread count, the
     * folder the project lies in) blanked.
     */
    static String withoutTimes(String summary) {
        return summary.replaceAll("\\d+\\.\\d+ s\\b", "T s")
                .replaceAll("\\d+\\.\\d+ Mrays/s", "R Mrays/s")
                .replaceAll("\\d+ threads?\\b", "N threads")
                .replaceAll(", (\\d+-wide vector|scalar) walk[^,]*$", "")
                .replaceAll(": \\S*/images/", ": PROJECT/images/");
    }

    @Test
    @DisplayName("the summary comparison ignores times, core count and the project's folder, nothing else")
    void summaryComparison() {
        String a = "render x: 0.475 s, 2x2 [NONE] of scene 's', 4 px, rays: camera 4, shadow 2, secondary 0, 1.00 camera rays per px, "
                + "3.29 Mrays/s (all rays), 2 threads, prepared in 0.001 s";
        String b = a.replace("0.475 s", "1.5 s").replace("3.29", "12.00").replace("2 threads", "16 threads");
        assertThat(withoutTimes(a)).isEqualTo(withoutTimes(b)).isEqualTo(withoutTimes(a.replace("2 threads", "1 thread")))
                .isNotEqualTo(withoutTimes(a.replace("shadow 2", "shadow 3")));
        String write = "write x: /home/me/project/images/x.png in 0.016 s";
        assertThat(withoutTimes(write)).isEqualTo(withoutTimes("write x: /work/images/x.png in 1.250 s"))
                .isNotEqualTo(withoutTimes("write x: /work/images/y.png in 1.250 s"));
    }

    @Nested
    @DisplayName("docs/student-guide.md")
    class StudentGuide {
        @Nested
        @DisplayName("the triangle mesh example")
        class Teapot {
            @Test
            @DisplayName("renders images/teapot.png: the red teapot in the middle of a black background")
            void renders() throws Exception {
                Files.deleteIfExists(Path.of("images", "teapot.png"));
                Class<?> test = type(STUDENT_GUIDE, "TeapotTest");
                capturingOutput(() -> runTests(test, new ArrayList<>()));

                BufferedImage image = readAndDelete("teapot");
                int centre = image.getRGB(200, 200), corner = image.getRGB(5, 5);
                assertThat(red(centre)).as("teapot red").isGreaterThan(green(centre) + 50).isGreaterThan(blue(centre) + 50);
                assertThat(corner & 0xFFFFFF).as("background").isZero();
            }
        }

        @Nested
        @DisplayName("the summary line sent elsewhere (setOutput)")
        class Summary {
            @Test
            @DisplayName("CapturedSummary.render writes the summary line into the log, not System.out, and returns its figures")
            void intoTheLog() throws Exception {
                Method render = type(STUDENT_GUIDE, "CapturedSummary").getDeclaredMethod("render", ByteArrayOutputStream.class);
                render.setAccessible(true);
                ByteArrayOutputStream log = new ByteArrayOutputStream();
                Object[] stats = new Object[1];
                String printed = capturingOutput(() -> stats[0] = render.invoke(null, log));
                assertThat(printed).as("System.out").doesNotContain("render ");
                assertThat(log.toString(StandardCharsets.UTF_8)).startsWith("render ").contains("10000 px");
                assertThat(((RenderStats) stats[0]).pixels()).isEqualTo(10_000);
            }
        }

        @Nested
        @DisplayName("the image assertion example")
        class SphereImage {
            @Test
            @DisplayName("renders, and without its reference (none is committed) fails saying how to record one, writing nothing")
            void failsWithoutItsReference() throws Exception {
                // Recording would write into the project's src/test/resources: not from this test.
                assumeFalse(Boolean.getBoolean(ImageAssertions.UPDATE_PROPERTY), "references are being recorded");
                Path reference = ImageAssertions.DEFAULT_REFERENCE_FOLDER.resolve("images/sphere.png");
                assertThat(reference).as("no reference of the example is committed").doesNotExist();
                Class<?> test = type(STUDENT_GUIDE, "SphereImageTest");
                List<Map<String, String>> reported = new ArrayList<>();
                assertThatThrownBy(() -> capturingOutput(() -> runTests(test, reported)))
                        .cause().isInstanceOf(AssertionError.class)
                        .hasMessageContaining("no reference image").hasMessageContaining("images/sphere.png")
                        .hasMessageContaining("-D" + ImageAssertions.UPDATE_PROPERTY);
                assertThat(reported).as("the render's figures in the test report (RenderReports.to)")
                        .anySatisfy(entry -> assertThat(entry).containsKey("Mrays/s"));
                assertThat(reference).doesNotExist();
            }
        }
    }

    @Nested
    @DisplayName("docs/scene-format.md: scene files from Java")
    class SceneFiles {
        @Test
        @DisplayName("RenderSceneFile renders scenes/two-colors.xml into images/two-colors.png at the file's 500x500")
        void renders() throws Exception {
            Files.deleteIfExists(Path.of("images", "two-colors.png"));
            Method render = type(SCENE_FORMAT, "RenderSceneFile").getDeclaredMethod("render", Path.class);
            render.setAccessible(true);
            capturingOutput(() -> render.invoke(null, Project.file("scenes", "two-colors.xml")));
            BufferedImage image = readAndDelete("two-colors");
            assertThat(image.getWidth()).isEqualTo(500);
            assertThat(image.getHeight()).isEqualTo(500);
        }

        @Test
        @DisplayName("PreviewSceneFile gives a camera of the file's view at 100x100")
        void preview() throws Exception {
            Method preview = type(SCENE_FORMAT, "PreviewSceneFile").getDeclaredMethod("preview", scene.io.LoadedScene.class);
            preview.setAccessible(true);
            Camera camera = (Camera) preview.invoke(null, XmlSceneReader.read(Project.file("scenes", "two-colors.xml")));
            RenderStats[] stats = new RenderStats[1];
            capturingOutput(() -> stats[0] = camera.render());
            assertThat(stats[0].pixels()).isEqualTo(100 * 100);
        }
    }

    @Nested
    @DisplayName("docs/spark.md: the Spark example")
    class SparkExample {
        @Test
        @DisplayName("compiles in a test run with -Pspark (its calls run on Spark in app.spark.SparkRendererTest)")
        void compilesWithTheSparkBuild() throws IOException {
            List<String> names = classes(SPARK).stream().map(Class::getSimpleName).toList();
            if (sparkBuild()) assertThat(names).contains("SparkRenderExample");
            else assertThat(names).doesNotContain("SparkRenderExample");
        }
    }
}
