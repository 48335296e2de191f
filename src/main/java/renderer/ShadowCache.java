package renderer;

import java.util.Arrays;

import geometries.Geometry;
import geometries.Hit;
import geometries.Intersectable;
import geometries.LeanQueries;
import geometries.ShadowIndex;
import primitives.Double3;

/**
 * A worker's last opaque occluder per light (Haines and Greenberg's shadow cache): the shape
 * that stopped the previous shadow ray toward a light usually stops the next one too (the next
 * pixel, the next sample of a soft light's disk), so it is asked before the walk. The light's
 * buffer ({@link ShadowIndex}), where it has one, is asked before both: it answers the lit points.
 *
 * <p>Exact: when a shape whose kT is zero in every channel crosses the shadow ray within its
 * distance, the product of kT along that ray is 0 whatever else is on it, which is what the walk
 * would return; when it does not cross it, the walk runs as before. Only
 * {@link LeanQueries#isLibraryShape library shapes} of one primitive are kept: asking them is one
 * intersection test, and they have no side effects (a mesh would be a walk of its own; a user's
 * class may do anything).
 */
final class ShadowCache {
    /** Per light (the tracer's light order): the last opaque occluder found, or null. */
    private Geometry[] last = new Geometry[0];

    /**
     * The product of kT along {@code shadow} up to {@code distance} toward light {@code light}, into
     * {@code tr} (as {@code LeanQueries.visitHits(world, shadow, distance, tr.reset())} would leave it): the
     * reset value when the light's {@code index} (null: none) proves the ray clear, 0 when the
     * light's last opaque occluder crosses the ray, else the walk, whose opaque occluder, if it
     * found one, is kept for the next ray.
     */
    void trace(Intersectable world, Hit shadow, double distance, int light, ShadowIndex index, Transmittance tr) {
        tr.reset();
        // A lit point, most shadow rays: the walk would visit nothing, and tr stays as reset.
        // Asked before the last occluder, which then costs a test only where there is a shadow.
        if (index != null && index.clear(shadow, distance)) return;
        if (blocks(light, shadow, distance)) {
            tr.product.setZero();
            return;
        }
        LeanQueries.visitHits(world, shadow, distance, tr);
        Geometry occluder = tr.opaque;
        // A mesh is kept out: asking it again would be a walk of its own over its triangles.
        if (occluder == null || !LeanQueries.isLibraryPrimitive(occluder)) return;
        if (light >= last.length) last = Arrays.copyOf(last, light + 1);
        last[light] = occluder;
    }

    /** @return whether light {@code light}'s last opaque occluder, still opaque, crosses the ray within the distance */
    private boolean blocks(int light, Hit shadow, double distance) {
        if (light >= last.length) return false;
        Geometry g = last[light];
        if (g == null || !opaque(g)) return false;
        return LeanQueries.crosses(g, shadow, distance); // the walk's acceptance rule, the walk's arithmetic
    }

    /** @return whether {@code g} lets no light through, in any channel */
    private static boolean opaque(Geometry g) {
        Double3 kT = g.getMaterial().kT;
        return kT.getD1() == 0 && kT.getD2() == 0 && kT.getD3() == 0;
    }
}
