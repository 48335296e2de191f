package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.imageio.ImageIO;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;

import app.Project;

/**
 * The README's Java blocks, exactly as printed: each one is a whole source file that compiles
 * against the library and the test class path, and its tests run and make the pictures the README
 * promises. A README example can therefore never drift from the code.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class ReadmeExampleTest {
    private static final Path README = Project.file("README.md");
    private static final Pattern CLASS_NAME = Pattern.compile("^(?:public\\s+)?(?:final\\s+)?class\\s+(\\w+)", Pattern.MULTILINE);

    private List<String> blocks;
    /** The class each block declares, compiled, in the README's order. */
    private final List<Class<?>> classes = new ArrayList<>();
    private URLClassLoader loader;

    @BeforeAll
    void compileEveryBlock(@TempDir Path work) throws IOException {
        blocks = javaBlocks(Files.readString(README));
        // The Spark example needs the Spark build (profile spark, on whenever the tests run); a
        // test run without it (-P '!spark') compiles the other blocks.
        if (!sparkBuild()) blocks = blocks.stream().filter(b -> !b.contains("import org.apache.spark.")).toList();
        Path sources = Files.createDirectories(work.resolve("src"));
        Path out = Files.createDirectories(work.resolve("classes"));
        List<File> files = new ArrayList<>();
        for (String block : blocks) {
            Matcher name = CLASS_NAME.matcher(block);
            assertThat(name.find()).as("a README Java block declares a top-level class:%n%s", block).isTrue();
            Path file = sources.resolve(name.group(1) + ".java");
            assertThat(file).as("two README blocks declare the class %s", name.group(1)).doesNotExist();
            Files.writeString(file, block);
            files.add(file.toFile());
        }

        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager fm = javac.getStandardFileManager(diagnostics, Locale.ROOT, StandardCharsets.UTF_8)) {
            // -proc:none: the test class path holds annotation processors (log4j's, through the
            // provided Spark dependency) that the README blocks do not need.
            List<String> options = List.of("-classpath", testClassPath(), "-d", out.toString(),
                    "-proc:none", "-Xlint:all", "-Werror", "-encoding", "UTF-8");
            boolean ok = javac.getTask(null, fm, diagnostics, options, null, fm.getJavaFileObjectsFromFiles(files)).call();
            assertThat(diagnostics.getDiagnostics()).as("javac's messages on the README blocks").isEmpty();
            assertThat(ok).as("the README blocks compile").isTrue();
        }

        loader = new URLClassLoader(new URL[] { out.toUri().toURL() }, getClass().getClassLoader());
        for (File file : files) {
            String name = file.getName().replace(".java", "");
            try {
                classes.add(loader.loadClass(name));
            } catch (ClassNotFoundException e) {
                throw new AssertionError("compiled but not found: " + name, e);
            }
        }
    }

    @AfterAll
    void closeLoader() throws IOException {
        if (loader != null) loader.close();
    }

    /** @return whether this test run has the Spark build (app.spark and Spark itself) on its class path */
    private static boolean sparkBuild() {
        try {
            Class.forName("app.spark.SparkRenderer", false, ReadmeExampleTest.class.getClassLoader());
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }

    /** Surefire names the test class path in a property (its own class path is a manifest-only jar). */
    private static String testClassPath() {
        return System.getProperty("surefire.test.class.path", System.getProperty("java.class.path"));
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

    /** Runs every {@code @Test} method of the README class named {@code simpleName}, each on a fresh instance, as JUnit does. */
    private void runTests(String simpleName) throws ReflectiveOperationException {
        Class<?> type = classes.stream().filter(c -> c.getSimpleName().equals(simpleName)).findFirst()
                .orElseThrow(() -> new AssertionError("no README block declares " + simpleName));
        List<Method> tests = new ArrayList<>();
        for (Method m : type.getDeclaredMethods())
            if (m.isAnnotationPresent(Test.class)) tests.add(m);
        assertThat(tests).as("@Test methods of %s", simpleName).isNotEmpty();
        Constructor<?> constructor = type.getDeclaredConstructor();
        constructor.setAccessible(true);
        for (Method test : tests) {
            test.setAccessible(true);
            try {
                test.invoke(constructor.newInstance());
            } catch (InvocationTargetException e) {
                throw new AssertionError("README " + simpleName + "." + test.getName() + " failed", e.getCause());
            }
        }
    }

    /** Runs {@code simpleName}'s tests with System.out captured; returns what they printed. */
    private String runCapturingOutput(String simpleName) throws ReflectiveOperationException {
        PrintStream console = System.out;
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        System.setOut(new PrintStream(printed, true, StandardCharsets.UTF_8));
        try {
            runTests(simpleName);
        } finally {
            System.setOut(console);
        }
        String text = printed.toString(StandardCharsets.UTF_8);
        console.print(text);
        return text;
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
    @DisplayName("the README has Java blocks, and each is a whole file (its imports included)")
    void blocksAreWholeFiles() {
        assertThat(blocks).hasSizeGreaterThanOrEqualTo(2);
        assertThat(blocks).allSatisfy(block -> assertThat(block).contains("import "));
    }

    @Nested
    @DisplayName("the scene test, course style")
    class TwoSpheres {
        @Test
        @DisplayName("renders images/twoSpheres.png: the inner sphere seen through the outer one; the summary line printed is the README's")
        void rendersAndPrintsTheQuotedSummary() throws Exception {
            Files.deleteIfExists(Path.of("images", "twoSpheres.png"));
            String printed = runCapturingOutput("SpheresTest");

            BufferedImage image = readAndDelete("twoSpheres");
            assertThat(image.getWidth()).isEqualTo(500);
            assertThat(image.getHeight()).isEqualTo(500);
            // The centre looks through the transparent outer sphere (kT 0.3) at the orange inner
            // one: more red than blue, unlike the rim, which shows the blue outer sphere alone.
            int centre = image.getRGB(250, 250), rim = image.getRGB(250, 250 - 150);
            assertThat(red(centre)).as("centre red").isGreaterThan(blue(centre));
            assertThat(blue(rim)).as("rim blue").isGreaterThan(red(rim));

            // The README quotes the summary this render prints. Sampling is deterministic, so
            // every count must match; only the times and the machine's core count may differ.
            Matcher quoted = Pattern.compile("`(render twoSpheres [^`]*)`").matcher(Files.readString(README));
            assertThat(quoted.find()).as("the README quotes the summary line").isTrue();
            String line = printed.lines().filter(l -> l.startsWith("render twoSpheres ")).findFirst()
                    .orElseThrow(() -> new AssertionError("no summary line printed:\n" + printed));
            assertThat(withoutTimes(quoted.group(1))).isEqualTo(withoutTimes(line));

            // And the line the write printed: the file, where this machine's project lies blanked.
            Matcher quotedWrite = Pattern.compile("`(write twoSpheres: [^`]*)`").matcher(Files.readString(README));
            assertThat(quotedWrite.find()).as("the README quotes the write line").isTrue();
            String write = printed.lines().filter(l -> l.startsWith("write twoSpheres: ")).findFirst()
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

    @Nested
    @DisplayName("the triangle mesh example")
    class Teapot {
        @Test
        @DisplayName("renders images/teapot.png: the red teapot in the middle of a black background")
        void renders() throws Exception {
            Files.deleteIfExists(Path.of("images", "teapot.png"));
            runCapturingOutput("TeapotTest");

            BufferedImage image = readAndDelete("teapot");
            int centre = image.getRGB(200, 200), corner = image.getRGB(5, 5);
            assertThat(red(centre)).as("teapot red").isGreaterThan(green(centre) + 50).isGreaterThan(blue(centre) + 50);
            assertThat(corner & 0xFFFFFF).as("background").isZero();
        }
    }

    @Test
    @DisplayName("the summary comparison ignores times, core count and the project's folder, nothing else")
    void summaryComparison() {
        String a = "render x 2x2 [NONE]: 0.475 s, 4 px, rays: camera 4, shadow 2, secondary 0, 1.00 camera rays per px, "
                + "3.29 Mrays/s (all rays), 2 threads, prepared in 0.001 s";
        String b = a.replace("0.475 s", "1.5 s").replace("3.29", "12.00").replace("2 threads", "16 threads");
        assertThat(withoutTimes(a)).isEqualTo(withoutTimes(b)).isEqualTo(withoutTimes(a.replace("2 threads", "1 thread")))
                .isNotEqualTo(withoutTimes(a.replace("shadow 2", "shadow 3")));
        String write = "write x: /home/me/project/images/x.png in 0.016 s";
        assertThat(withoutTimes(write)).isEqualTo(withoutTimes("write x: /work/images/x.png in 1.250 s"))
                .isNotEqualTo(withoutTimes("write x: /work/images/y.png in 1.250 s"));
    }
}
