/**
 * The course's shapes: extend {@link geometries.Intersectable} (your course year's intersection
 * hook) or {@link geometries.Geometry} (emission, material, normal) for a shape of your own; use
 * {@link geometries.Sphere}, {@link geometries.Plane}, {@link geometries.Polygon},
 * {@link geometries.Triangle}, {@link geometries.Tube}, {@link geometries.Cylinder},
 * {@link geometries.TriangleMesh} and the list {@link geometries.Geometries} in scene tests.
 *
 * <p>Under them, the engine: each {@code Intersectable} also answers the renderer's lean queries
 * (a closest hit into a reused {@code Hit}, an any-hit walk for shadows), and the tracer puts
 * {@code Geometries}' bounded members into a {@code Bvh}. Those queries, a shape's box and the
 * rule that a shape is the library's own are package-private, so that a student's code
 * completion on a course class lists the course's methods only; the renderer reaches them through
 * the static facades {@code LeanQueries}, {@code GeometryLists} and {@code MeshChecks}.
 *
 * <p>Roles in this package:
 * <ul>
 * <li>The course's face, which scene tests call and users extend: {@code Intersectable} (the
 * queries, the three course years' hooks and hit records), {@code Geometry} (emission, material,
 * normal), the shapes {@code Sphere}, {@code Plane}, {@code Polygon}, {@code Triangle},
 * {@code Tube}, {@code Cylinder}, {@code TriangleMesh}, and the list {@code Geometries}.
 * {@code Intersectable} joins the two forms of each lean query once: the library's shapes
 * implement the doubles form, a user's shape its course hook.</li>
 * <li>The renderer's side: {@code LeanQueries} (the closest-hit query, the any-hit walk, the box
 * and the library-shape rule of any intersectable), {@code GeometryLists} (a scene's lists'
 * change count and nesting), {@code MeshChecks} (a mesh loader's degenerate-triangle test);
 * {@code Hit}, the per-thread record a query fills without allocating;
 * {@code HitVisitor}, which receives an any-hit walk's hits; {@code Bvh}, which the tracer asks
 * for ({@code Bvh.of(scene.geometries)}) and then queries like any intersectable;
 * {@code ShadowIndex}, a light's buffer over a tree's leaves, which proves a shadow ray clear from
 * the few leaves of its cell; and
 * {@code BoundingBox}, whose slab test ({@code entry}, one call per box) the tree's node test shares.</li>
 * <li>Internal, package-private: {@code BvhLeaf}, what a tree asks of its leaves (the superclass of
 * {@code Intersectable}, out of the course's sight); {@code BvhBuilder}, which builds a tree
 * (called by {@code Bvh}'s factories) with the surface-area heuristic of {@code BvhBinner}, both
 * holding their boxes as the flat doubles {@code BuildBoxes} names;
 * {@code BvhNodes}, the only code that knows the node array's layout (the builder writes it, the
 * walks read it); {@code SingleHitGeometry}, the queries of a shape crossed at most once (plane,
 * polygon, triangle); {@code HookCheck}, which finds by reflection the course methods a class
 * redefines; {@code Ranges}, the build's parallel loops; {@code WideNodes}, the binary tree
 * collapsed into nodes of 4 or 8 children, walked by a {@code WideWalk} (the Vector API's, in
 * {@code src/main/vector}) when {@code Vectorization} finds the module readable.</li>
 * </ul>
 * Whether an object is exactly one of the library's shapes, which the library then trusts with
 * arithmetic of its own, is decided by one rule, {@code primitives.LibraryClasses}, through
 * {@code LeanQueries.isLibraryShape(Geometry)}.
 *
 * <p>Invariants the tests hold: the two faces of every shape agree, the same distances bit for bit
 * ({@code HitTest}, {@code RayFormTest}, the contract tests); a tree and the flat list give the same
 * closest hits and the same visits ({@code BvhTest}), and the same tree for any number of build
 * threads; a user's subclass that overrides a course method is asked through it, in the course
 * queries and in the render alike, BVH on and off ({@code HookOverrideRenderTest}, {@code BvhTest},
 * {@code HitTest}): one cached rule per class, {@code HookCheck.answersInDoubles}, decides whether
 * a shape's doubles forms may answer for its hooks, and a hook overridden below the library's
 * class defeats it.
 */
package geometries;
