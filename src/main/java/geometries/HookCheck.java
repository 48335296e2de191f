package geometries;

import java.lang.reflect.Method;
import java.util.Set;

import primitives.Ray;

/**
 * Whether a class of intersectables overrides one of the three course years' intersection hooks
 * ({@link Intersectable#findGeoIntersectionsHelper}, {@link Intersectable#calculateIntersectionsHelper},
 * {@link Intersectable#calcIntersectionsHelper}). The answer is found once per class by
 * reflection and cached with the class, so constructing a million spheres costs one lookup each.
 */
final class HookCheck {
    private static final Set<String> HOOKS =
            Set.of("findGeoIntersectionsHelper", "calculateIntersectionsHelper", "calcIntersectionsHelper");

    /** Per class, computed on first use; a ClassValue holds no state beyond that fixed answer. */
    private static final ClassValue<Boolean> OVERRIDES = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            for (Class<?> c = type; c != null && c != Intersectable.class; c = c.getSuperclass())
                for (Method m : c.getDeclaredMethods())
                    if (HOOKS.contains(m.getName()) && m.getParameterCount() == 2
                            && m.getParameterTypes()[0] == Ray.class && m.getParameterTypes()[1] == double.class)
                        return true;
            return false;
        }
    };

    private HookCheck() {
    }

    /** @return true when {@code type} or a superclass below Intersectable declares one of the hooks */
    static boolean overridesAHook(Class<?> type) {
        return OVERRIDES.get(type);
    }
}
