package geometries;

import java.lang.reflect.Method;
import java.util.Arrays;
import java.util.List;

import primitives.Point;
import primitives.Ray;

/**
 * Which course methods a class redefines, found by reflection once per class and cached with it,
 * so that constructing a million spheres costs one lookup each. The one reflection walk of the
 * library ({@link #declaring}) behind its two questions:
 * <ul>
 * <li>{@link #overridesAHook}, {@link #oneArgumentHook}: whether a class of intersectables
 * overrides one of the three course years' intersection hooks
 * ({@link Intersectable#findGeoIntersectionsHelper}, {@link Intersectable#calculateIntersectionsHelper},
 * {@link Intersectable#calcIntersectionsHelper}), with {@code maxDistance} or in the one-argument
 * form of the courses before it, and which one-argument hook answers when no two-argument one
 * does; a class that overrides none cannot answer a query;</li>
 * <li>{@link #redefinesNormal}: whether a shape's course normal {@code getNormal(Point)} is
 * redefined below the class that computes the normal in doubles ({@code normalAt(Hit)}), so that
 * the renderer must ask the course method. Unlike {@link Geometry#isLibraryShape()} this looks at
 * what a class overrides, not at its name: a user's subclass that leaves the normal alone keeps
 * the library's doubles form.</li>
 * </ul>
 */
final class HookCheck {
    /** The three years' hook names, in the order of the default hooks' circle (see {@link Intersectable}). */
    private static final List<String> HOOKS =
            List.of("findGeoIntersectionsHelper", "calculateIntersectionsHelper", "calcIntersectionsHelper");

    /**
     * A course year's hook, by its name: with {@code maxDistance}, or in its one-argument form
     * {@code name(Ray)}, the course's hook before it had the bound, which a user's shape may
     * override alone. The constants follow {@link #HOOKS}.
     */
    enum Hook {
        FIND_GEO, CALCULATE, CALC;

        /** The one-argument form's name, for messages. */
        String methodName() {
            return HOOKS.get(ordinal()) + "(Ray)";
        }
    }

    /**
     * Per class: the two-argument hook declared lowest (nearest the class; in one class, the
     * first in {@link #HOOKS}' order): the one a user's subclass of a library shape wrote, which
     * the render asks as that year's queries do.
     */
    private static final ClassValue<Hook> LOWEST_HOOK = new ClassValue<>() {
        @Override
        protected Hook computeValue(Class<?> type) {
            Hook lowest = Hook.FIND_GEO;
            Class<?> at = Intersectable.class;
            for (Hook hook : Hook.values()) {
                Class<?> c = declaring(type, Intersectable.class, HOOKS.get(hook.ordinal()), Ray.class, double.class);
                if (c != at && lower(at, c) == c) {
                    at = c;
                    lowest = hook;
                }
            }
            return lowest;
        }
    };

    /**
     * @return the two-argument hook a query of the class's own making should ask: the lowest
     *         declared ({@link Hook#FIND_GEO} when none is, whose default goes round to the rest)
     */
    static Hook lowestHook(Class<?> type) {
        return LOWEST_HOOK.get(type);
    }

    /**
     * What a class overrides of the six hooks: the lowest class declaring a two-argument one
     * ({@code Intersectable} when none does), and the lowest one-argument hook with its class
     * (null and {@code Intersectable} when none). Among one-argument hooks the lowest class wins;
     * in one class, the first in {@link #HOOKS}' order.
     */
    private record Overrides(Class<?> twoArgument, Hook oneArgument, Class<?> oneArgumentClass) {
    }

    /**
     * The library's classes that answer the lean queries with doubles arithmetic of their own:
     * {@link #answersInDoubles} asks which of them a class descends from.
     */
    private static final List<Class<?>> DOUBLES = List.of(Sphere.class, SingleHitGeometry.class, Tube.class,
            TriangleMesh.class, Geometries.class, Bvh.class);

    /** The six hooks, as name and parameter types: a year's with and without {@code maxDistance}. */
    private static boolean declaresAHookBelow(Class<?> type, Class<?> library) {
        for (String hook : HOOKS)
            for (Class<?>[] parameters : List.of(new Class<?>[] { Ray.class, double.class }, new Class<?>[] { Ray.class })) {
                Class<?> c = declaring(type, Intersectable.class, hook, parameters);
                if (c != library && library.isAssignableFrom(c)) return true;
            }
        return false;
    }

    /**
     * Per class: whether its doubles forms of the lean queries stand for its course queries. True
     * for a library class of {@link #DOUBLES} and a subclass that overrides none of the six hooks
     * below it; false for a subclass that overrides one (its hook must answer, in the render too)
     * and for any other class (a user's shape on {@code Geometry}).
     */
    private static final ClassValue<Boolean> ANSWERS_IN_DOUBLES = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            for (Class<?> c = type; c != null && c != Intersectable.class; c = c.getSuperclass())
                if (DOUBLES.contains(c)) return !declaresAHookBelow(type, c);
            return false;
        }
    };

    /** Per class, computed on first use; a ClassValue holds no state beyond that fixed answer. */
    private static final ClassValue<Overrides> OVERRIDES = new ClassValue<>() {
        @Override
        protected Overrides computeValue(Class<?> type) {
            Class<?> two = Intersectable.class, oneClass = Intersectable.class;
            Hook one = null;
            for (Hook hook : Hook.values()) {
                String name = HOOKS.get(hook.ordinal());
                two = lower(two, declaring(type, Intersectable.class, name, Ray.class, double.class));
                Class<?> c = declaring(type, Intersectable.class, name, Ray.class);
                if (c != Intersectable.class && lower(oneClass, c) != oneClass) {
                    oneClass = c;
                    one = hook;
                }
            }
            return new Overrides(two, one, oneClass);
        }
    };

    /** The lower of two classes on one line of inheritance, {@code a} when they are the same. */
    private static Class<?> lower(Class<?> a, Class<?> b) {
        return a != b && a.isAssignableFrom(b) ? b : a;
    }

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

    /**
     * @return true when {@code type} or a superclass below Intersectable declares one of the six
     *         hooks (a year's, with or without {@code maxDistance})
     */
    static boolean overridesAHook(Class<?> type) {
        Overrides o = OVERRIDES.get(type);
        return o.twoArgument() != Intersectable.class || o.oneArgument() != null;
    }

    /**
     * @return the one-argument hook that answers for {@code type}: the lowest it overrides, when
     *         it overrides no two-argument hook; null otherwise (a two-argument hook answers, or
     *         none does)
     */
    static Hook oneArgumentHook(Class<?> type) {
        Overrides o = OVERRIDES.get(type);
        return o.twoArgument() == Intersectable.class ? o.oneArgument() : null;
    }

    /**
     * A one-argument hook that no query would ask: declared in a class strictly below one that
     * declares a two-argument hook (a user's subclass of a library shape, say), which answers
     * every query itself.
     *
     * @return the hook's name and the two classes, for an error message; null when there is none
     */
    static String unaskedOneArgumentHook(Class<?> type) {
        Overrides o = OVERRIDES.get(type);
        if (o.oneArgument() == null || o.twoArgument() == Intersectable.class
                || lower(o.twoArgument(), o.oneArgumentClass()) == o.twoArgument()) return null;
        return o.oneArgument().methodName() + " in " + o.oneArgumentClass().getName() + " is below "
                + o.twoArgument().getName() + "'s hook with maxDistance, which answers every query";
    }

    /**
     * The one rule behind every fast path of the lean queries: whether {@code type}'s doubles
     * forms answer for its course hooks. A user's subclass of a library shape that overrides a
     * hook loses them, so the render asks its hook, as the course queries do.
     *
     * @return true when {@code type} descends from a library class that answers in doubles and
     *         overrides none of the six hooks below it
     */
    static boolean answersInDoubles(Class<?> type) {
        return ANSWERS_IN_DOUBLES.get(type);
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
