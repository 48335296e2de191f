package geometries;

import java.lang.reflect.Method;
import java.util.Arrays;
import java.util.Set;

import primitives.Point;
import primitives.Ray;

/**
 * Which course methods a class redefines, found by reflection once per class and cached with it,
 * so that constructing a million spheres costs one lookup each. The one reflection walk of the
 * library ({@link #declaring}) behind its two questions:
 * <ul>
 * <li>{@link #overridesAHook}: whether a class of intersectables overrides one of the three
 * course years' intersection hooks ({@link Intersectable#findGeoIntersectionsHelper},
 * {@link Intersectable#calculateIntersectionsHelper}, {@link Intersectable#calcIntersectionsHelper});
 * one that overrides none cannot answer a query;</li>
 * <li>{@link #redefinesNormal}: whether a shape's course normal {@code getNormal(Point)} is
 * redefined below the class that computes the normal in doubles ({@code normalAt(Hit)}), so that
 * the renderer must ask the course method. Unlike {@link Geometry#isLibraryShape()} this looks at
 * what a class overrides, not at its name: a user's subclass that leaves the normal alone keeps
 * the library's doubles form.</li>
 * </ul>
 */
final class HookCheck {
    private static final Set<String> HOOKS =
            Set.of("findGeoIntersectionsHelper", "calculateIntersectionsHelper", "calcIntersectionsHelper");

    /** Per class, computed on first use; a ClassValue holds no state beyond that fixed answer. */
    private static final ClassValue<Boolean> OVERRIDES = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            for (String hook : HOOKS)
                if (declaring(type, Intersectable.class, hook, Ray.class, double.class) != Intersectable.class) return true;
            return false;
        }
    };

    /**
     * Per class: whether {@code getNormal(Point)} is declared in a class strictly below the one
     * that declares {@code normalAt(Hit)} (a library shape's; Geometry's default does not count).
     */
    private static final ClassValue<Boolean> NORMAL = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            Class<?> doubles = declaring(type, Geometry.class, "normalAt", Hit.class);
            Class<?> course = declaring(type, Geometry.class, "getNormal", Point.class);
            return doubles != Geometry.class && course != doubles && doubles.isAssignableFrom(course);
        }
    };

    private HookCheck() {
    }

    /** @return true when {@code type} or a superclass below Intersectable declares one of the hooks */
    static boolean overridesAHook(Class<?> type) {
        return OVERRIDES.get(type);
    }

    /**
     * @return true when {@code type} or a superclass declares {@code getNormal(Point)} below the
     *         class that declares {@code normalAt(Hit)}
     */
    static boolean redefinesNormal(Class<?> type) {
        return NORMAL.get(type);
    }

    /**
     * The nearest class from {@code type} up to, not including, {@code top} that declares the
     * method {@code name(parameters)}; {@code top} when none below it does.
     */
    static Class<?> declaring(Class<?> type, Class<?> top, String name, Class<?>... parameters) {
        for (Class<?> c = type; c != null && c != top; c = c.getSuperclass())
            for (Method m : c.getDeclaredMethods())
                if (m.getName().equals(name) && Arrays.equals(m.getParameterTypes(), parameters)) return c;
        return top;
    }
}
