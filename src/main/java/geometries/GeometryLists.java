package geometries;

/**
 * What a render asks of a scene's geometry lists before and after it renders: how often they
 * were added to, how often a geometry's surface was set to another, and whether they nest within
 * the limit. Static, and apart from {@link Geometries}, so that a
 * student completing {@code scene.geometries.} sees the course's methods only; the renderer, in
 * another package, calls these.
 *
 * @hidden internal: the renderer's checks of a scene; a scene test adds to its lists and renders
 */
public final class GeometryLists {
    private GeometryLists() {
    }

    /**
     * How many times {@code list} and the lists nested in it, at any depth, were added to: a
     * render notes it when it starts and compares it when it ends, to tell that the scene changed
     * while it rendered. Walks the nested lists without recursion, each once.
     *
     * @param list a scene's geometry list
     * @return the number of {@link Geometries#add} calls on the list and every list within it, so far
     */
    public static long changeCount(Geometries list) {
        return list.changeCount();
    }

    /**
     * Checks the nesting a render can take: at most {@link Geometries#MAX_NESTING_DEPTH} levels.
     *
     * @param list a scene's geometry list
     * @throws IllegalArgumentException naming the depth and the limit when the lists are nested
     *                                  deeper, or saying so when a list contains itself
     */
    public static void requireNestingWithinLimit(Geometries list) {
        list.requireNestingWithinLimit();
    }

    /**
     * How many times a geometry's emission was set to another one, so far: a render notes it when
     * it starts and compares it when it ends, so that a change put back within the render is seen too.
     *
     * @param geometry a geometry of a scene
     * @return the number of such changes
     */
    public static int emissionChanges(Geometry geometry) {
        return geometry.emissionChanges();
    }

    /**
     * How many times a geometry's material was set to another one, so far (see {@link #emissionChanges}).
     *
     * @param geometry a geometry of a scene
     * @return the number of such changes
     */
    public static int materialChanges(Geometry geometry) {
        return geometry.materialChanges();
    }
}
