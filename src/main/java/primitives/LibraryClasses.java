package primitives;

import java.util.Set;

/**
 * Internal: the one rule by which the library tells its own objects from a user's. Several parts
 * of the library answer for an object with arithmetic of their own, which stands for the course
 * methods only of the classes that wrote it: a tree tests the library's spheres and triangles from
 * packed copies, a light answers for points given as doubles, a render keeps a tree, or a shadow
 * occluder, from one ray or render to the next. A subclass may override a course method (an
 * intersection hook, a normal, a light's falloff), move its shape or count its calls, so for an
 * instance of a subclass, even one that overrides nothing, the library asks the course methods.
 *
 * <p>Each package lists its own classes once, as a constant of this type ({@code Geometry} its
 * shapes, {@code Light} its lights), and asks {@link #contains}: the object's class is one of
 * them exactly. (Whether a subclass of a library shape may keep the shape's lean queries is the
 * narrower rule of {@code geometries.HookCheck.answersInDoubles}: only while it overrides no
 * course hook.) You never need it.
 *
 * @hidden internal: the library's own classes, public for the other course packages
 */
public final class LibraryClasses {
    private final Set<Class<?>> classes;

    private LibraryClasses(Set<Class<?>> classes) {
        this.classes = classes;
    }

    /**
     * @param classes the library's own classes, each concrete or abstract
     * @return the set of them
     * @throws NullPointerException     when a class is null
     * @throws IllegalArgumentException when a class is listed twice
     */
    public static LibraryClasses of(Class<?>... classes) {
        return new LibraryClasses(Set.of(classes));
    }

    /**
     * @param more further classes of the library
     * @return these classes and {@code more}
     * @throws IllegalArgumentException when a class would be listed twice
     */
    public LibraryClasses and(Class<?>... more) {
        Class<?>[] all = classes.toArray(new Class<?>[classes.size() + more.length]);
        System.arraycopy(more, 0, all, classes.size(), more.length);
        return of(all);
    }

    /**
     * @param object any object
     * @return true when the class of {@code object} is exactly one of these classes, not a
     *         subclass of one
     */
    public boolean contains(Object object) {
        return classes.contains(object.getClass());
    }
}
