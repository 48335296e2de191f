package renderer;

import geometries.Geometry;
import geometries.HitVisitor;
import primitives.Double3;

/**
 * The shadow-ray accumulator of the any-hit walk: the product of kT of every occluder crossing
 * between a point and a light. Stops the walk once every channel is below the tracer's
 * threshold, because kT ≤ 1 means the product can only shrink further.
 */
final class Transmittance implements HitVisitor {
    double r;
    double g;
    double b;
    /** The occluder that stopped the walk alone (its kT is zero in every channel), or null. */
    Geometry opaque;
    private final double threshold;

    Transmittance(double threshold) {
        this.threshold = threshold;
    }

    Transmittance reset() {
        r = g = b = 1;
        opaque = null;
        return this;
    }

    @Override
    public boolean visit(Geometry geometry, double t) {
        Double3 kT = geometry.getMaterial().kT;
        r *= kT.getD1();
        g *= kT.getD2();
        b *= kT.getD3();
        if (r < threshold && g < threshold && b < threshold) {
            r = g = b = 0;
            if (kT.getD1() == 0 && kT.getD2() == 0 && kT.getD3() == 0) opaque = geometry;
            return false;
        }
        return true;
    }
}
