package geometries;

import java.util.Objects;

import primitives.Color;
import primitives.LibraryClasses;
import primitives.Material;
import primitives.Point;
import primitives.Vector;

/**
 * A shape with an emission colour and a material. Set both while building the scene; the
 * renderer treats them as constant during a render.
 */
public abstract class Geometry extends Intersectable {
    private Color emission = Color.BLACK;
    private Material material = new Material();
    /** Whether {@link #surfaceNormal} asks {@link #getNormal(Point)} (see there); fixed per class. */
    private final boolean courseNormal = HookCheck.redefinesNormal(getClass());

    /** The library's shapes whose queries are one intersection test each: all but the mesh. */
    private static final LibraryClasses PRIMITIVES = LibraryClasses.of(Sphere.class, Triangle.class, Polygon.class,
            Plane.class, Tube.class, Cylinder.class);
    /** The library's own shapes: the one list behind {@link #isLibraryShape()}. */
    private static final LibraryClasses SHAPES = PRIMITIVES.and(TriangleMesh.class);
    // The two answers, fixed per class, asked once: the shadow cache asks one per shadow ray, and
    // a set lookup there cost the one-thread showcase render several per cent.
    private final boolean libraryShape = SHAPES.contains(this);
    private final boolean libraryPrimitive = PRIMITIVES.contains(this);

    /**
     * Whether this is one of the library's own shapes, not a subclass of one: its geometry is fixed
     * when it is made (its emission and material may still change) and its queries have no side
     * effects, so what a renderer learnt of it (a tree over it, that it blocks a light) holds from
     * one ray or render to the next, and a tree may test it from packed copies of its numbers. A
     * class of yours may move its shape, or count its calls, so nothing is kept for it.
     *
     * @return true for an instance of exactly one of the library's shape classes
     */
    final boolean isLibraryShape() {
        return libraryShape;
    }

    /**
     * Internal, for the renderer's shadow cache: whether this is a {@link #isLibraryShape()
     * library shape} whose queries are one intersection test, so that asking it again costs no
     * more than a tree's test of one primitive. Every library shape but a mesh, whose queries
     * loop over its triangles.
     *
     * @return true for an instance of exactly one of the library's shape classes other than
     *         {@link TriangleMesh}
     */
    final boolean isLibraryPrimitive() {
        return libraryPrimitive;
    }

    /** @return the light the surface gives off by itself; black by default */
    public Color getEmission() {
        return emission;
    }

    /**
     * @param emission the light the surface gives off by itself, added to what it reflects; black by default
     * @return this geometry, for chaining
     * @throws NullPointerException when emission is null
     */
    public Geometry setEmission(Color emission) {
        Objects.requireNonNull(emission, "emission");
        if (!emission.equals(this.emission)) emissionChanges++;
        this.emission = emission;
        return this;
    }

    /**
     * How many times the emission, and the material, were set to another one: counted, so that a
     * surface changed and put back during a render still shows at its end (the scene-change
     * check). Volatile: a setter may run on another thread than the render.
     */
    private volatile int emissionChanges, materialChanges;

    /** @return how many times the emission was set to another one */
    int emissionChanges() {
        return emissionChanges;
    }

    /** @return how many times the material was set to another one */
    int materialChanges() {
        return materialChanges;
    }

    /** @return the surface's coefficients (shared, see {@link #setMaterial}); all zero by default */
    public Material getMaterial() {
        return material;
    }

    /**
     * @param material the surface's coefficients; the object is shared, not copied, so changing
     *                 its fields changes every geometry using it
     * @return this geometry, for chaining
     * @throws NullPointerException when material is null
     */
    public Geometry setMaterial(Material material) {
        Objects.requireNonNull(material, "material");
        if (material != this.material) materialChanges++;
        this.material = material;
        return this;
    }

    /**
     * @param point a point on the surface (not checked: off the surface, the result is meaningless)
     * @return the outward unit normal at {@code point}
     */
    public abstract Vector getNormal(Point point);

    /**
     * Writes the unit normal at the hit point of {@code hit} (its {@code px, py, pz}) into
     * {@code hit.normal}. The library's shapes override it with their normal in doubles (a mesh
     * and a tube use the triangle or surface the hit recorded); the default, for users' own
     * shapes, asks {@link #getNormal(Point)}.
     */
    void normalAt(Hit hit) {
        courseNormal(hit);
    }

    /**
     * The normal the renderer uses: {@link #normalAt(Hit)}, unless {@link #getNormal(Point)} is
     * redefined below the class that computes the normal in doubles ({@code HookCheck}); then
     * {@code getNormal} is asked, so that a user's subclass that overrides it gets its own normal
     * while one that does not keeps the library's (both held by {@code HitTest}). The library's
     * {@link Cylinder} is such a class too: its {@code getNormal} sits below {@link Tube}'s
     * {@code normalAt}, so a cylinder is shaded with the normal of the surface nearest the point.
     */
    final void surfaceNormal(Hit hit) {
        if (courseNormal) courseNormal(hit);
        else normalAt(hit);
    }

    private void courseNormal(Hit hit) {
        Vector n = getNormal(new Point(hit.px, hit.py, hit.pz));
        hit.normal[0] = n.getX();
        hit.normal[1] = n.getY();
        hit.normal[2] = n.getZ();
    }

}
