package renderer.junit;

import java.io.PrintStream;
import java.nio.file.Path;

import org.junit.platform.launcher.LauncherSession;
import org.junit.platform.launcher.LauncherSessionListener;

import primitives.CourseClassGuard;

/**
 * Says, once per test run, that a project's own course classes shadow the library's. A course
 * project that adds the library as a dependency but keeps all of its own {@code primitives},
 * {@code geometries}, {@code renderer}… classes runs its tests green on its own code: no class of
 * the library ever loads, so the library's guard (which stops the first library class that runs
 * beside a shadowing one) never speaks. JUnit's launcher loads this listener from the library's
 * {@code META-INF/services} in every test run, Maven's, Gradle's or the IDE's, with no opt-in;
 * it prints one line on the error stream naming the classes and {@code raytracer migrate}, and
 * nothing at all where the library's own classes are the ones that load.
 */
public final class ShadowedLibraryListener implements LauncherSessionListener {
    private final PrintStream err;

    /** The listener JUnit loads: it writes to {@code System.err}. */
    public ShadowedLibraryListener() {
        this(System.err);
    }

    ShadowedLibraryListener(PrintStream err) {
        this.err = err;
    }

    @Override
    public void launcherSessionOpened(LauncherSession session) {
        ClassLoader tests = Thread.currentThread().getContextClassLoader();
        String shadowing = CourseClassGuard.shadowing(tests != null ? tests : ShadowedLibraryListener.class.getClassLoader());
        if (shadowing != null) err.println(message(shadowing, Path.of("").toAbsolutePath()));
    }

    /** The one line, for the classes named and the project's folder. */
    static String message(String shadowing, Path project) {
        return "raytracer: these tests run on your own course classes, not the library's: " + shadowing
                + ". Move them out with: raytracer migrate " + project
                + " (docs/migrate.md)";
    }
}
