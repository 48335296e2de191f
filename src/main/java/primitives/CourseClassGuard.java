package primitives;

import java.io.IOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Internal: stops the library at once, with one message, when it runs next to a project's own
 * classes of the course's names. A course project that adds the library as a dependency and keeps
 * its own {@code primitives/Vector.java} puts its own {@code primitives.Vector} first on the class
 * path; the library's {@code renderer.Camera} then runs with it and fails far away, with a
 * {@code NoSuchMethodError} that names neither the cause nor the cure. The library's entry
 * classes (the scene, the camera's builder, tracers, image writers, shapes and lights) call
 * {@link #check()} first; it compares, once per class loader, where each of the library's classes
 * of the five course packages is loaded from (its code source) with where this class was, and
 * names every one that comes from elsewhere. You never need to call it.
 *
 * @hidden internal: the check against a student's copy of a course class, public for the other course packages
 */
public final class CourseClassGuard {
    private CourseClassGuard() {
    }

    /** The verdict for the class loader of this class, reached once: a class's first initialisation. */
    private static final class Verdict {
        /** The message, or null when every class of the library comes from where this one does. */
        static final String SHADOWED = shadowed(CourseClassGuard.class.getClassLoader());
    }

    /**
     * Internal: called by the library's entry classes before they do anything. The first call
     * loads the library's classes (without initialising them) and compares their code sources;
     * later calls read the verdict.
     *
     * @throws LinkageError naming the project's classes that shadow the library's, where they came
     *                      from, and what to do
     */
    public static void check() {
        String message = Verdict.SHADOWED;
        if (message != null) throw new LinkageError(message);
    }

    /**
     * @param loader the loader that loaded this class
     * @return the message naming every library class that {@code loader} loads from somewhere
     *         else than this class, or null when there is none (or nothing can be told: no loader,
     *         no code source)
     */
    static String shadowed(ClassLoader loader) {
        String names = shadowing(loader);
        return names == null ? null : "Your own course classes shadow the library's: " + names
                + ". The library (" + location(CourseClassGuard.class) + ") cannot run with them. Move them out with raytracer"
                + " migrate (see docs/migrate.md): it keeps your tests and your"
                + " own extra classes; then rebuild clean (mvn clean test, or your IDE's Rebuild Project).";
    }

    /**
     * Internal (for the test-run listener of {@code renderer.junit}): which of the library's course
     * classes {@code loader} loads from somewhere else than the library.
     *
     * @param loader the class loader the tests run with
     * @return {@code primitives.{Point, Vector} from /project/out}, groups joined by {@code ; },
     *         or null when none is shadowed (or nothing can be told)
     */
    public static String shadowing(ClassLoader loader) {
        String library = location(CourseClassGuard.class);
        if (loader == null || library == null) return null;
        List<String> classes;
        try {
            classes = CourseClassIndex.of(codeSource(CourseClassGuard.class));
        } catch (IOException | URISyntaxException | IllegalArgumentException e) {
            return null; // the library's own jar cannot be read: nothing can be told, as without a code source
        }
        // The library's own classes share its code source: their location need not be spelt out
        // (a URL made a path for each of its 96 classes took 3 ms of every launch).
        CodeSource own = CourseClassGuard.class.getProtectionDomain().getCodeSource();
        // location → package → simple names, sorted, so that the message reads in one order
        Map<String, Map<String, List<String>>> found = new TreeMap<>();
        for (String name : classes) {
            String where;
            try {
                // Loaded, not initialised: most of them the first render loads anyway. Asking for
                // the class file as a resource instead would search every module of the JDK for
                // each name, which costs more.
                Class<?> c = Class.forName(name, false, loader);
                if (c.getProtectionDomain().getCodeSource() == own) continue;
                where = location(c);
            } catch (ClassNotFoundException e) {
                continue; // not in this build of the library (a shrunk jar)
            } catch (LinkageError e) {
                where = "a class file that does not load: " + e; // a project's class, broken
            }
            if (where == null || where.equals(library)) continue;
            int dot = name.lastIndexOf('.');
            found.computeIfAbsent(where, w -> new TreeMap<>())
                    .computeIfAbsent(name.substring(0, dot), p -> new ArrayList<>()).add(name.substring(dot + 1));
        }
        if (found.isEmpty()) return null;
        List<String> groups = new ArrayList<>();
        found.forEach((where, packages) -> groups.add(names(packages) + " from " + where));
        return String.join("; ", groups);
    }

    /** The jar or classes folder a class was loaded from. */
    private static Path codeSource(Class<?> c) throws URISyntaxException {
        return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI());
    }

    /**
     * @return where a class was loaded from, as a reader knows it (a folder or a jar file), or null
     *         when its loader does not say
     */
    static String location(Class<?> c) {
        CodeSource source = c.getProtectionDomain().getCodeSource();
        URL url = source == null ? null : source.getLocation();
        return url == null ? null : display(url);
    }

    /** {@code primitives.{Point, Vector}, scene.Scene}: the names, a package's several in braces. */
    private static String names(Map<String, List<String>> packages) {
        List<String> parts = new ArrayList<>();
        packages.forEach((pkg, classes) -> parts.add(pkg + "."
                + (classes.size() == 1 ? classes.get(0) : "{" + String.join(", ", classes) + "}")));
        return String.join(", ", parts);
    }

    /** A location URL as a path when it is a file's ({@code file:/a/b.jar} gives {@code /a/b.jar}); its text otherwise. */
    static String display(URL url) {
        if (url.getProtocol().equals("file")) {
            try {
                return Path.of(url.toURI()).toString();
            } catch (URISyntaxException | IllegalArgumentException e) {
                return url.toString();
            }
        }
        return url.toString();
    }
}
