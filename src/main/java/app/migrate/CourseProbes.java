package app.migrate;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Course-year choices that no pattern over the source tells reliably, read off the student's own
 * course classes by running them: the classes the as-is check compiled, each probe on a fresh
 * loader (so nothing of the library stands in), on a thread of its own with a time limit. A probe
 * that cannot tell (a constructor of another shape, an exception, a class that does not load)
 * names nothing.
 *
 * <p>The one probe: a cylinder's normal at the centre of its bottom base. The library's is the
 * outward one, minus the axis direction; several cohorts return the axis direction on both bases,
 * which no regular expression over their {@code getNormal} told apart (a survey of 27 projects).
 */
final class CourseProbes {
    /** How long one probe may run: a normal is microseconds; a student's loop must not hold the migration. */
    private static final long LIMIT_MS = 2000;

    private CourseProbes() {
    }

    /**
     * @param classes the student's classes as they compile as they are (the as-is check's output)
     * @param course  the student's course classes
     * @param tests   the student's tests, for the ones the choice touches
     */
    static List<CourseChoices.Choice> find(Path classes, List<SourceFile> course, List<SourceFile> tests, Path projectDir) {
        List<CourseChoices.Choice> found = new ArrayList<>();
        for (SourceFile f : course) {
            if (!Catalog.libraryName(f.className()).equals("geometries.Cylinder")) continue;
            if (bottomNormalAlongAxis(classes, f.className()).orElse(false)) {
                List<String> touched = tests.stream().filter(t -> t.text().contains("Cylinder") && t.text().contains("getNormal"))
                        .map(t -> t.path().getFileName().toString()).toList();
                found.add(new CourseChoices.Choice("your Cylinder's normal at the centre of its bottom base is the axis direction",
                        f.relative(projectDir), "the outward normal there, minus the axis direction", touched));
            }
        }
        return found;
    }

    /**
     * Whether the student's cylinder of radius 1 and height 1 on the axis from the origin along
     * +z answers the axis direction at the origin, the centre of its bottom base.
     *
     * @return empty when the probe cannot tell
     */
    static Optional<Boolean> bottomNormalAlongAxis(Path classes, String cylinderClass) {
        ExecutorService thread = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "raytracer migrate: cylinder probe");
            t.setDaemon(true); // a student's endless loop must not keep the command from exiting
            return t;
        });
        try (URLClassLoader loader = new URLClassLoader(new URL[] { classes.toUri().toURL() }, ClassLoader.getPlatformClassLoader())) {
            Future<Boolean> answer = thread.submit(() -> probe(loader, cylinderClass));
            return Optional.ofNullable(answer.get(LIMIT_MS, TimeUnit.MILLISECONDS));
        } catch (TimeoutException | ExecutionException | IOException e) {
            // The student's class could not be asked (it loops, throws, is shaped otherwise, or
            // its folder cannot be read): the choice is not named, as when no probe exists for it.
            return Optional.empty();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return Optional.empty();
        } finally {
            thread.shutdownNow();
        }
    }

    /** The probe itself, on the student's classes only: null when their classes have no such shape. */
    private static Boolean probe(ClassLoader loader, String cylinderClass) throws ReflectiveOperationException {
        Class<?> point = Class.forName("primitives.Point", false, loader);
        Class<?> vector = Class.forName("primitives.Vector", false, loader);
        Class<?> ray = Class.forName("primitives.Ray", false, loader);
        Object origin = point.getConstructor(double.class, double.class, double.class).newInstance(0.0, 0.0, 0.0);
        Object up = vector.getConstructor(double.class, double.class, double.class).newInstance(0.0, 0.0, 1.0);
        Object axis = ray.getConstructor(point, vector).newInstance(origin, up);
        Object cylinder = null;
        // Any constructor of one ray and two numbers: radius and height both 1, so their order does not matter.
        for (Constructor<?> c : Class.forName(cylinderClass, true, loader).getConstructors()) {
            Class<?>[] p = c.getParameterTypes();
            if (p.length != 3) continue;
            Object[] args = new Object[3];
            int rays = 0, numbers = 0;
            for (int i = 0; i < 3; i++) {
                if (p[i] == ray) {
                    args[i] = axis;
                    rays++;
                } else if (p[i] == double.class || p[i] == Double.class) {
                    args[i] = 1.0;
                    numbers++;
                }
            }
            if (rays == 1 && numbers == 2) {
                cylinder = c.newInstance(args);
                break;
            }
        }
        if (cylinder == null) return null;
        Method getNormal = cylinder.getClass().getMethod("getNormal", point);
        Object normal;
        try {
            normal = getNormal.invoke(cylinder, origin);
        } catch (InvocationTargetException e) {
            return null; // their cylinder refuses the point: another choice, not this one
        }
        if (normal == null) return null;
        Method dot = normal.getClass().getMethod("dotProduct", vector);
        return ((Number) dot.invoke(normal, up)).doubleValue() > 0.5;
    }
}
