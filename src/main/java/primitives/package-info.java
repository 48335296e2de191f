/**
 * Values everything else is made of: points, vectors, rays, colours, coefficient triples and
 * materials, all immutable except the course's {@link primitives.Material} fields and
 * {@link primitives.Rgb} (the renderer's in-place accumulator, whose kernels Color and Double3
 * compute with), and the zero tolerance of {@link primitives.Util} that every geometric test
 * shares. Depends on nothing else of the library but where the course's API puts it:
 * {@link primitives.Ray}'s closest-hit query takes and returns the hit records of
 * {@code geometries.Intersectable}.
 */
package primitives;
