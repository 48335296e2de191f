package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import app.Project;

/**
 * The guard against a project's own course classes next to the library's: the library's entry
 * classes fail at once, with one message naming the project's classes, where they came from, and
 * what to do; nothing fires when every class comes from one place.
 */
class CourseClassGuardTest {
    /** Where the library's classes were compiled to (target/classes). */
    private static final Path LIBRARY = location(CourseClassGuard.class);

    private static Path location(Class<?> c) {
        try {
            return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }

    /** A project's own class, as the course has it: a public class of that name with nothing the library needs. */
    private static String source(String className) {
        int dot = className.lastIndexOf('.');
        return "package " + className.substring(0, dot) + "; public class " + className.substring(dot + 1)
                + " { public " + className.substring(dot + 1) + "() { } }";
    }

    /** Compiles a project's own classes of these names into {@code dir}/classes and returns that folder. */
    private static Path compile(Path dir, String... classNames) throws IOException {
        Path sources = Files.createDirectories(dir.resolve("src")), classes = Files.createDirectories(dir.resolve("classes"));
        List<String> args = new ArrayList<>(List.of("-d", classes.toString()));
        for (String name : classNames) {
            Path file = sources.resolve(name.replace('.', '/') + ".java");
            Files.createDirectories(file.getParent());
            Files.writeString(file, source(name));
            args.add(file.toString());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertThat(javac.run(null, null, null, args.toArray(String[]::new))).as("javac's exit code").isZero();
        return classes;
    }

    /** The classes of {@code folder} packed into {@code dir}/project.jar. */
    private static Path jar(Path folder, Path dir) throws IOException {
        Path jar = dir.resolve("project.jar");
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar)); Stream<Path> files = Files.walk(folder)) {
            for (Path f : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator) {
                out.putNextEntry(new JarEntry(folder.relativize(f).toString().replace('\\', '/')));
                Files.copy(f, out);
                out.closeEntry();
            }
        }
        return jar;
    }

    /** A class loader like a project's class path: the project's own classes first, then the library. */
    private static URLClassLoader projectLoader(Path... path) throws IOException {
        List<URL> urls = new ArrayList<>();
        for (Path p : path) urls.add(p.toUri().toURL());
        urls.add(LIBRARY.toUri().toURL());
        return new URLClassLoader(urls.toArray(URL[]::new), ClassLoader.getPlatformClassLoader());
    }

    /** Runs one of the library's entry points through {@code loader}: what a scene test does first. */
    private static Object enter(ClassLoader loader, String entry) throws Throwable {
        try {
            return switch (entry) {
                case "new Scene(name)" -> loader.loadClass("scene.Scene").getConstructor(String.class).newInstance("s");
                case "Camera.getBuilder()" -> loader.loadClass("renderer.Camera").getMethod("getBuilder").invoke(null);
                case "new ImageWriter(name, nX, nY)" -> loader.loadClass("renderer.ImageWriter")
                        .getConstructor(String.class, int.class, int.class).newInstance("i", 1, 1);
                case "new Geometries()" -> loader.loadClass("geometries.Geometries").getConstructor().newInstance();
                case "AmbientLight.NONE" -> loader.loadClass("lighting.AmbientLight").getField("NONE").get(null);
                default -> throw new AssertionError(entry);
            };
        } catch (InvocationTargetException e) {
            throw e.getCause();
        }
    }

    /** The message, with the project's classes as the guard names them and the folders of this run. */
    private static String message(String classes, Path from) {
        return "Your own course classes shadow the library's: " + classes + " from " + from + ". The library ("
                + LIBRARY + ") cannot run with them. Move them out with raytracer migrate (see docs/migrate.md): it keeps your tests and your own extra classes; then rebuild clean"
                + " (mvn clean test, or your IDE's Rebuild Project).";
    }

    /** A folder shared by the tests of one project's own primitives.Vector, compiled once. */
    @TempDir
    static Path shared;
    private static Path ownVector;

    private static synchronized Path ownVector() throws IOException {
        if (ownVector == null) ownVector = compile(shared, "primitives.Vector");
        return ownVector;
    }

    @Nested
    @DisplayName("a project's own primitives.Vector first on the class path")
    class OwnVector {
        @ParameterizedTest(name = "{0}")
        @ValueSource(strings = {"new Scene(name)", "Camera.getBuilder()", "new ImageWriter(name, nX, nY)",
                "new Geometries()", "AmbientLight.NONE"})
        @DisplayName("each entry point fails at once with the one message naming it and its folder")
        void entryPointsFail(String entry) throws Exception {
            Path own = ownVector();
            try (URLClassLoader loader = projectLoader(own)) {
                assertThatThrownBy(() -> enter(loader, entry)).isExactlyInstanceOf(LinkageError.class)
                        .hasMessage(message("primitives.Vector", own));
            }
        }

        @Test
        @DisplayName("from a jar: the jar is named")
        void fromAJar(@TempDir Path dir) throws Exception {
            Path jar = jar(ownVector(), dir);
            try (URLClassLoader loader = projectLoader(jar)) {
                assertThatThrownBy(() -> enter(loader, "new Scene(name)")).hasMessage(message("primitives.Vector", jar));
            }
        }
    }

    @Test
    @DisplayName("docs/migrate.md, the page the message points to, quotes it (folders aside)")
    void migrateDocument(@TempDir Path dir) throws Exception {
        String page = Files.readString(Project.file("docs", "migrate.md"));
        assertThat(page).startsWith("# Moving an existing course project onto the library\n");
        Matcher quoted = Pattern.compile("\n(java\\.lang\\.LinkageError: Your own course classes[^\n]*)\n").matcher(page);
        assertThat(quoted.find()).as("docs/migrate.md quotes the message").isTrue();
        Path own = compile(dir, "primitives.Vector", "primitives.Point");
        try (URLClassLoader loader = projectLoader(own)) {
            assertThatThrownBy(() -> enter(loader, "new Scene(name)")).satisfies(e ->
                    assertThat(withoutFolders(e.getClass().getName() + ": " + e.getMessage()))
                            .isEqualTo(withoutFolders(quoted.group(1))));
        }
    }

    /** The message with the project's folder and the library's location blanked. */
    private static String withoutFolders(String message) {
        return message.replaceAll(" from \\S+\\. The library \\([^)]*\\)", " from FOLDER. The library (LIBRARY)");
    }

    @Test
    @DisplayName("the reverse, a project's own renderer.Camera with the library's scene: named too")
    void ownCamera(@TempDir Path dir) throws Exception {
        Path own = compile(dir, "renderer.Camera");
        try (URLClassLoader loader = projectLoader(own)) {
            assertThatThrownBy(() -> enter(loader, "new Scene(name)")).hasMessage(message("renderer.Camera", own));
        }
    }

    @Test
    @DisplayName("several classes: one message, a package's classes together, from each folder")
    void several(@TempDir Path dir) throws Exception {
        Path own = compile(dir.resolve("a"), "primitives.Vector", "primitives.Point", "geometries.Sphere");
        Path other = compile(dir.resolve("b"), "lighting.SpotLight");
        try (URLClassLoader loader = projectLoader(own, other)) {
            assertThatThrownBy(() -> enter(loader, "Camera.getBuilder()")).hasMessage(
                    message("geometries.Sphere, primitives.{Point, Vector} from " + own + "; lighting.SpotLight", other));
        }
    }

    @Nested
    @DisplayName("nothing fires")
    class NoShadow {
        @Test
        @DisplayName("when every class comes from the library's folder (its own build and tests)")
        void oneFolder() throws Throwable {
            try (URLClassLoader loader = projectLoader()) {
                assertThat(enter(loader, "new Scene(name)")).isNotNull();
                assertThat(enter(loader, "Camera.getBuilder()")).isNotNull();
            }
            assertThat(CourseClassGuard.shadowed(CourseClassGuard.class.getClassLoader())).isNull();
        }

        @Test
        @DisplayName("for a project's own extra classes in the course packages (names the library does not have)")
        void ownExtraClasses(@TempDir Path dir) throws Throwable {
            try (URLClassLoader loader = projectLoader(compile(dir, "geometries.Cube", "renderer.PixelManager"))) {
                assertThat(enter(loader, "new Scene(name)")).isNotNull();
            }
        }

        @Test
        @DisplayName("without a class loader to ask (the boot loader)")
        void bootLoader() {
            assertThat(CourseClassGuard.shadowed(null)).isNull();
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({
            "file:/home/me/project/target/classes/, /home/me/project/target/classes",
            "file:/home/me/.m2/raytracer.jar, /home/me/.m2/raytracer.jar",
            "jar:file:/a/app.jar!/lib/raytracer.jar!/, jar:file:/a/app.jar!/lib/raytracer.jar!/"})
    @DisplayName("a code source is shown as its folder or jar file; another kind of URL as it is")
    void display(String url, String shown) throws Exception {
        assertThat(CourseClassGuard.display(new URL(url))).isEqualTo(shown);
    }

    @Test
    @DisplayName("a project's class that does not even load is named, with the reason")
    void brokenClass(@TempDir Path dir) throws Exception {
        Path own = compile(dir, "primitives.Base", "primitives.Vector");
        Files.writeString(dir.resolve("src/primitives/Vector.java"), "package primitives; public class Vector extends Base { }");
        assertThat(ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", own.toString(), "-cp", own.toString(),
                dir.resolve("src/primitives/Vector.java").toString())).isZero();
        Files.delete(own.resolve("primitives/Base.class"));
        try (URLClassLoader loader = projectLoader(own)) {
            assertThatThrownBy(() -> enter(loader, "new Scene(name)")).isExactlyInstanceOf(LinkageError.class)
                    .hasMessageStartingWith("Your own course classes shadow the library's: primitives.Vector from a class "
                            + "file that does not load: java.lang.NoClassDefFoundError: primitives/Base. The library (");
        }
    }

    @Test
    @DisplayName("the guard's list is every top-level class the library compiles in the five course packages (but its JFR events), read from its classes folder or its jar")
    void listIsComplete(@TempDir Path jarDir) throws IOException {
        List<String> compiled = new ArrayList<>();
        for (String pkg : List.of("primitives", "geometries", "lighting", "scene", "renderer"))
            try (Stream<Path> files = Files.list(LIBRARY.resolve(pkg))) {
                files.map(f -> f.getFileName().toString()).filter(f -> f.endsWith(".class") && !f.contains("$"))
                        .map(f -> pkg + "." + f.substring(0, f.length() - ".class".length()))
                        .filter(c -> !c.endsWith(".package-info") && !c.equals(CourseClassGuard.class.getName())
                                && !c.equals("renderer.RenderEvent") && !c.equals("renderer.ImageWriteEvent"))
                        .forEach(compiled::add);
            }
        assertThat(compiled).contains("primitives.Point", "geometries.LeanQueries", "renderer.Camera", "scene.Scene")
                .doesNotContain("renderer.RenderEvent", "primitives.CourseClassGuard");
        assertThat(CourseClassIndex.of(LIBRARY)).containsExactlyInAnyOrderElementsOf(compiled);
        // the same from a jar of those classes, as a project that depends on the library loads it
        Path jar = jarDir.resolve("raytracer.jar");
        try (var out = new java.util.jar.JarOutputStream(Files.newOutputStream(jar)); Stream<Path> all = Files.walk(LIBRARY)) {
            for (Path f : all.filter(Files::isRegularFile).sorted().toList()) {
                out.putNextEntry(new java.util.jar.JarEntry(LIBRARY.relativize(f).toString().replace('\\', '/')));
                Files.copy(f, out);
                out.closeEntry();
            }
        }
        assertThat(CourseClassIndex.of(jar)).containsExactlyInAnyOrderElementsOf(compiled);
    }
}
