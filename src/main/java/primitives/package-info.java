/**
 * The course's values, which scene tests and shapes are written with: {@link primitives.Point},
 * {@link primitives.Vector}, {@link primitives.Ray}, {@link primitives.Color},
 * {@link primitives.Double3}, {@link primitives.Material} and the zero tolerance of
 * {@link primitives.Util} that every geometric test shares. All immutable except the course's
 * {@code Material} fields.
 *
 * <p>The engine's, out of the student's Javadoc: {@code Rgb} (the renderer's in-place
 * accumulator, whose kernels Color and Double3 compute with), {@code Kernels} (Vector's and
 * Ray's arithmetic on raw components, for code that keeps vectors in doubles), {@code Checks} (the
 * argument checks whose messages name the value), {@code LibraryClasses} and
 * {@code CourseClassGuard} (which classes are the library's own). The package depends on nothing
 * else of the library but where the course's API puts it: {@link primitives.Ray}'s closest-hit
 * query takes and returns the hit records of {@code geometries.Intersectable}.
 */
package primitives;
