package primitives;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;

/**
 * The library's classes in the five course packages, read from where the library itself was
 * loaded (its jar's entries, or its classes folder): the names {@link CourseClassGuard} checks for
 * a project's copies. Read, not typed: a class added to the library is guarded the day it is
 * compiled, with no list to keep. Top-level classes only (a nested one comes with its file);
 * the guard itself, {@code package-info} and the two JDK Flight Recorder event classes are left
 * out (loading a JFR event class sets up JFR's machinery, and no course has one).
 */
final class CourseClassIndex {
    private static final List<String> PACKAGES = List.of("primitives", "geometries", "lighting", "scene", "renderer");
    private static final Set<String> LEFT_OUT = Set.of(CourseClassGuard.class.getName(), "renderer.RenderEvent",
            "renderer.ImageWriteEvent");

    private CourseClassIndex() {
    }

    /**
     * @param library the library's jar, or its classes folder
     * @return the class names, sorted
     * @throws IOException when the jar or the folder cannot be read
     */
    static List<String> of(Path library) throws IOException {
        List<String> names = new ArrayList<>();
        if (Files.isDirectory(library)) {
            for (String pkg : PACKAGES) {
                Path folder = library.resolve(pkg);
                if (!Files.isDirectory(folder)) continue;
                try (Stream<Path> files = Files.list(folder)) {
                    files.forEach(f -> add(names, pkg + "/" + f.getFileName()));
                }
            }
        } else {
            try (JarFile jar = new JarFile(library.toFile())) {
                for (JarEntry e : Collections.list(jar.entries())) add(names, e.getName());
            }
        }
        Collections.sort(names);
        return names;
    }

    /** Adds the class an entry ({@code primitives/Point.class}) names, when it is one of the index's. */
    private static void add(List<String> names, String entry) {
        int slash = entry.indexOf('/');
        if (slash < 0 || entry.indexOf('/', slash + 1) >= 0 || !entry.endsWith(".class") || entry.contains("$")) return;
        if (!PACKAGES.contains(entry.substring(0, slash))) return;
        String name = entry.substring(0, entry.length() - ".class".length()).replace('/', '.');
        if (!name.endsWith(".package-info") && !LEFT_OUT.contains(name)) names.add(name);
    }
}
