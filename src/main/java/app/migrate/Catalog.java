package app.migrate;

import java.util.Set;

/**
 * Which of a student's classes the library provides: a class of the same name in the course's
 * packages (the 2025–26 {@code geometries.api}/{@code impl} and {@code lighting.api}/{@code impl}
 * folded into {@code geometries} and {@code lighting}, as the library keeps them). Such a class
 * must leave the build: on the class path it would shadow the library's (the guard then stops the
 * run). Asked of the class loader that holds the library, without initialising anything.
 */
final class Catalog {
    /** The course's packages; a class elsewhere is the student's own, whatever its name. */
    private static final Set<String> COURSE_PACKAGES = Set.of("primitives", "geometries", "lighting", "renderer", "scene");

    private final ClassLoader library;

    Catalog(ClassLoader library) {
        this.library = library;
    }

    /** {@code geometries.impl.Sphere} → {@code geometries.Sphere}; other names unchanged. */
    static String libraryName(String className) {
        return className.replaceFirst("^(geometries|lighting)\\.(api|impl)\\.", "$1.");
    }

    /** {@code geometries.impl} → {@code geometries}; other packages unchanged. */
    static String libraryPackage(String packageName) {
        return packageName.replaceFirst("^(geometries|lighting)\\.(api|impl)$", "$1");
    }

    /** Whether a package is one of 2025–26's {@code api}/{@code impl} halves, which the library folds. */
    static boolean isSplitPackage(String packageName) {
        return !libraryPackage(packageName).equals(packageName);
    }

    /** Whether the library has a class of this (folded) name in the course's packages. */
    boolean provides(String className) {
        String name = libraryName(className);
        int dot = name.indexOf('.');
        if (dot < 0 || !COURSE_PACKAGES.contains(name.substring(0, dot))) return false;
        try {
            Class.forName(name, false, library);
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }
}
