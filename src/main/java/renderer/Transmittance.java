package renderer;

import geometries.Geometry;
import geometries.HitVisitor;
import primitives.Double3;
import primitives.Rgb;

/**
 * The shadow-ray accumulator of the any-hit walk: the product of kT of every occluder crossing
 * between a point and a light. Stops the walk once every channel is below the tracer's
 * threshold, because kT ≤ 1 means the product can only shrink further.
 */
final class Transmittance implements HitVisitor {
    /** The product of kT so far, per channel: 1 before the walk, 0 once it stopped below the threshold. */
    final Rgb product = new Rgb();
    /** The occluder that stopped the walk alone (its kT is zero in every channel), or null. */
    Geometry opaque;
    private final double threshold;

    Transmittance(double threshold) {
        this.threshold = threshold;
    }

    Transmittance reset() {
        product.set(1, 1, 1);
        opaque = null;
        return this;
    }

    @Override
    public boolean visit(Geometry geometry, double t) {
        Double3 kT = geometry.getMaterial().kT;
        if (product.scale(kT).lowerThan(threshold)) {
            product.setZero();
            if (kT.isZero()) opaque = geometry;
            return false;
        }
        return true;
    }
}
