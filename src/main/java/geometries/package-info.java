/**
 * Shapes and the queries on them. Each {@link geometries.Intersectable} answers the course's list
 * queries and the renderer's lean ones (a closest hit into a reused {@link geometries.Hit}, an
 * any-hit walk for shadows); {@link geometries.Geometries} puts its bounded members into a
 * {@link geometries.Bvh}.
 */
package geometries;
