package app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/**
 * The packages form layers and imports only point down: primitives → geometries, lighting →
 * renderer → scene.io, scene.samples → app (the command line and the Spark jobs). The package
 * {@code scene} itself (the {@code Scene} aggregate of geometries and lights) sits below the
 * renderer, because the course's tracers take a {@code Scene}. Checked on the sources (the tests
 * run from the project root).
 */
class PackageLayersTest {
    /** The library and command line, and the Spark entry point (built by the profile spark). */
    private static final List<Path> SOURCES = List.of(Project.file("src/main/java"), Project.file("src/spark/java"));

    /**
     * Each package's layer, by the longest matching prefix; a file may import its own layer and
     * those below.
     */
    private static final Map<String, Integer> LAYER = Map.of("primitives", 0, "geometries", 1, "lighting", 1,
            "scene", 2, "renderer", 3, "scene.io", 4, "scene.samples", 4, "app", 5);

    /**
     * Imports the course API itself prescribes: {@code Ray.findClosestGeoPoint} (and its
     * later-year spelling) takes the hit records of {@code geometries}, and the 2024–25 hit record
     * {@code Intersectable.Intersection} has a {@code LightSource light} field (lighting never
     * imports geometries, so the peers still form no cycle).
     */
    private static final Set<String> COURSE_EXCEPTIONS = Set.of("primitives/Ray.java -> geometries",
            "geometries/Intersectable.java -> lighting");

    private static final Pattern IMPORT = Pattern.compile(
            "^import\\s+(?:static\\s+)?((?:primitives|geometries|lighting|renderer|scene|app)(?:\\.[a-z]\\w*)*)\\.[A-Z]",
            Pattern.MULTILINE);

    /** The layer of a package name such as {@code scene.io.xml}: its longest listed prefix. */
    private static int layer(String pkg) {
        for (String p = pkg;; p = p.substring(0, p.lastIndexOf('.'))) {
            Integer l = LAYER.get(p);
            if (l != null)
                return l;
            if (p.indexOf('.') < 0)
                throw new AssertionError("package " + pkg + " has no layer in PackageLayersTest");
        }
    }

    @Test
    @DisplayName("no import points from a lower layer to a higher one")
    void importsOnlyPointDown() throws IOException {
        List<Path> sources = new ArrayList<>();
        for (Path root : SOURCES)
            try (Stream<Path> files = Files.walk(root)) {
                files.filter(f -> f.toString().endsWith(".java")).forEach(sources::add);
            }
        assertThat(sources).as("the library's sources").hasSizeGreaterThan(50);
        List<String> upward = new ArrayList<>();
        for (Path file : sources) {
            Path relative = SOURCES.stream().filter(file::startsWith).findFirst().orElseThrow().relativize(file);
            String own = relative.getParent().toString().replace(File.separatorChar, '.');
            Matcher m = IMPORT.matcher(Files.readString(file));
            while (m.find()) {
                String used = m.group(1);
                String edge = relative.toString().replace(File.separatorChar, '/') + " -> " + used;
                if (layer(used) > layer(own) && !COURSE_EXCEPTIONS.contains(edge))
                    upward.add(edge);
            }
        }
        assertThat(upward).as("imports that point up the layers").isEmpty();
    }

    @Test
    @DisplayName("peers in one layer do not import each other (geometries and lighting)")
    void peersStayApart() throws IOException {
        for (String[] pair : new String[][] { { "geometries", "lighting" }, { "lighting", "geometries" } }) {
            Path library = SOURCES.get(0);
            try (Stream<Path> files = Files.walk(library.resolve(pair[0]))) {
                for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                    String edge = library.relativize(file).toString().replace(File.separatorChar, '/') + " -> " + pair[1];
                    if (COURSE_EXCEPTIONS.contains(edge)) continue;
                    assertThat(Files.readString(file)).as("%s imports %s", file, pair[1])
                            .doesNotContainPattern("(?m)^import\\s+(static\\s+)?" + pair[1] + "\\.");
                }
            }
        }
    }

    /**
     * The course makes the renderer name {@code Scene}: a camera renders one, a tracer is made
     * over one (the constructors and {@code setRayTracer(Scene, …)} of every course year). Those
     * classes may import it; the rest of the renderer gets the scene's parts from them.
     */
    private static final Set<String> COURSE_SCENE_USERS = Set.of("Camera.java", "RayTracerBase.java",
            "RayTracerBasic.java", "RayTracerType.java", "SimpleRayTracer.java");

    @Test
    @DisplayName("in the renderer, only the classes the course names with a Scene import package scene")
    void sceneOnlyWhereTheCourseNamesIt() throws IOException {
        Path renderer = SOURCES.get(0).resolve("renderer");
        List<String> importing = new ArrayList<>();
        try (Stream<Path> files = Files.walk(renderer)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList())
                if (Pattern.compile("(?m)^import\\s+(static\\s+)?scene\\.").matcher(Files.readString(file)).find())
                    importing.add(renderer.relativize(file).toString().replace(File.separatorChar, '/'));
        }
        assertThat(importing).as("renderer files importing package scene").isNotEmpty()
                .allSatisfy(f -> assertThat(COURSE_SCENE_USERS).contains(f));
    }
}
