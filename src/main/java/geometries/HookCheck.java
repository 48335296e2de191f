package geometries;

import java.lang.reflect.Method;
import java.util.Arrays;
import java.util.Set;

import primitives.Ray;

/**
 * Which methods a user's class overrides, found by reflection once per class. Chiefly: whether a
 * class of intersectables overrides one of the three course years' intersection hooks
 * ({@link Intersectable#findGeoIntersectionsHelper}, {@link Intersectable#calculateIntersectionsHelper},
 * {@link Intersectable#calcIntersectionsHelper}). Each answer is cached with the class, so
 * constructing a million spheres costs one lookup each.
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

    private HookCheck() {
    }

    /** @return true when {@code type} or a superclass below Intersectable declares one of the hooks */
    static boolean overridesAHook(Class<?> type) {
        return OVERRIDES.get(type);
    }

    /**
     * The nearest class from {@code type} up to, not including, {@code top} that declares the
     * method {@code name(parameters)}; {@code top} when none below it does. The one reflection
     * walk behind the override checks of this package.
     */
    static Class<?> declaring(Class<?> type, Class<?> top, String name, Class<?>... parameters) {
        for (Class<?> c = type; c != null && c != top; c = c.getSuperclass())
            for (Method m : c.getDeclaredMethods())
                if (m.getName().equals(name) && Arrays.equals(m.getParameterTypes(), parameters)) return c;
        return top;
    }
}
