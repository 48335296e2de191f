package app.migrate;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * Which of a student's classes the library provides: a class of the same name in the course's
 * packages (the 2025–26 {@code geometries.api}/{@code impl} and {@code lighting.api}/{@code impl}
 * folded into {@code geometries} and {@code lighting}, as the library keeps them). Such a class
 * must leave the build: on the class path it would shadow the library's (the guard then stops the
 * run). Asked of the class loader that holds the library, without initialising anything.
 *
 * <p>Of those, the course's own classes ({@link #COURSE}: the classes some course year hands out
 * or asks for) are told from the library's public internals that a student may happen to name
 * alike (their own BVH's {@code geometries.BoundingBox}): both must leave, but only the first is
 * "the library provides it"; the second is the student's own work, which the library's BVH
 * replaces. A course class kept in another course package than the library's (a
 * {@code lighting.Material}) is the course's too, {@link #relocated} to the library's.
 */
final class Catalog {
    /** The course's packages; a class elsewhere is the student's own, whatever its name. */
    private static final Set<String> COURSE_PACKAGES = Set.of("primitives", "geometries", "lighting", "renderer", "scene");
    /**
     * The classes of the course, any year (COURSE-YEARS in the project's notes): what a student's
     * project has because the course gave or asked for it. {@code RadialGeometry} (2023–25) the
     * library does not have; a student's compiles against the library and stays.
     */
    static final Set<String> COURSE = Set.of("Point", "Vector", "Ray", "Double3", "Color", "Material", "Util", "Geometry",
            "Intersectable", "Geometries", "Sphere", "Plane", "Triangle", "Polygon", "Tube", "Cylinder", "RadialGeometry",
            "Light", "LightSource", "AmbientLight", "DirectionalLight", "PointLight", "SpotLight", "Camera", "ImageWriter",
            "RayTracerBase", "SimpleRayTracer", "RayTracerBasic", "RayTracerType", "Scene");

    /** 2025–26's packages, which the library keeps folded into {@code geometries} and {@code lighting}. */
    private static final Pattern FOLDED = Pattern.compile("(geometries|lighting)\\.(api|impl)");

    private final ClassLoader library;

    Catalog(ClassLoader library) {
        this.library = library;
    }

    /** {@code geometries.impl.Sphere} → {@code geometries.Sphere} (and its nested classes); other names unchanged. */
    static String libraryName(String className) {
        int second = className.indexOf('.', className.indexOf('.') + 1);
        return second < 0 ? className : libraryPackage(className.substring(0, second)) + className.substring(second);
    }

    /** {@code geometries.impl} → {@code geometries}; other packages unchanged. The one place the fold is written. */
    static String libraryPackage(String packageName) {
        return isFolded(packageName) ? packageName.substring(0, packageName.indexOf('.')) : packageName;
    }

    /** Whether a package is one of 2025–26's {@code geometries.api/impl} and {@code lighting.api/impl}. */
    static boolean isFolded(String packageName) {
        return FOLDED.matcher(packageName).matches();
    }

    /** Whether the library has a class of this (folded) name in the course's packages. */
    boolean provides(String className) {
        String name = libraryName(className);
        int dot = name.indexOf('.');
        if (dot < 0 || !COURSE_PACKAGES.contains(name.substring(0, dot))) return false;
        return exists(name);
    }

    /** Whether a class the library {@link #provides} is a course class, not a public internal of the library's. */
    static boolean isCourseClass(String className) {
        return COURSE.contains(className.substring(className.lastIndexOf('.') + 1));
    }

    /**
     * Whether a class is one of the course's by name and package ({@code geometries.impl.RadialGeometry}):
     * kept where the library has no class of its name, it is still the course's, not the student's own.
     */
    static boolean isCourseClassInCoursePackage(String className) {
        String name = libraryName(className);
        int dot = name.lastIndexOf('.');
        return dot > 0 && COURSE_PACKAGES.contains(name.substring(0, dot)) && COURSE.contains(name.substring(dot + 1));
    }

    /**
     * The library's name for a course class the student keeps in another course package
     * ({@code lighting.Material} → {@code primitives.Material}), or null when it is no such class.
     */
    String relocated(String className) {
        String name = libraryName(className);
        int dot = name.lastIndexOf('.');
        if (dot < 0 || provides(className)) return null;
        String pkg = name.substring(0, dot), simple = name.substring(dot + 1);
        if (!COURSE_PACKAGES.contains(pkg) || !COURSE.contains(simple)) return null;
        for (String other : COURSE_PACKAGES)
            if (exists(other + "." + simple)) return other + "." + simple;
        return null;
    }

    /**
     * A project's sources sorted.
     *
     * @param course    the course classes the library provides, and those it keeps elsewhere: they move
     * @param extras    the student's other classes: they stay
     * @param tests     the tests
     * @param relocated course classes kept in another course package → the library's name for them
     */
    record Sorted(List<SourceFile> course, List<SourceFile> extras, List<SourceFile> tests, Map<String, String> relocated) {
    }

    Sorted sort(List<SourceFile> files) {
        List<SourceFile> tests = files.stream().filter(SourceFile::test).toList();
        // A course class kept in another course package (lighting.Material) goes as the library's
        // (primitives.Material); what stays is pointed at the library's.
        Map<String, String> relocated = new LinkedHashMap<>();
        files.stream().filter(f -> !f.test()).forEach(f -> {
            String to = relocated(f.className());
            // Only where the project has no class of the library's name: else this one is its own.
            if (to != null && files.stream().noneMatch(g -> libraryName(g.className()).equals(to)))
                relocated.put(f.className(), to);
        });
        List<SourceFile> course = files.stream()
                .filter(f -> !f.test() && (provides(f.className()) || relocated.containsKey(f.className()))).toList();
        List<SourceFile> extras = files.stream().filter(f -> !f.test() && !course.contains(f)).toList();
        return new Sorted(course, extras, tests, relocated);
    }

    private boolean exists(String name) {
        try {
            Class.forName(name, false, library);
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }
}
