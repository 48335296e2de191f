package renderer;

import geometries.Hit;

/**
 * The renderer's query record: a {@link Hit} whose ray the renderer sets. {@code Hit} keeps its
 * ray setters protected so that only this package (and the geometries' own code) puts rays into
 * records; everything else reads them.
 */
final class RayHit extends Hit {
    /**
     * Sets the query ray to {@code new Ray(new Point(ox, oy, oz), new Vector(dx, dy, dz))}, the
     * direction normalized (any non-zero, finite vector; not checked).
     *
     * @return this record
     */
    RayHit ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        setRay(ox, oy, oz, dx, dy, dz);
        return this;
    }

    /**
     * Sets the query ray to the secondary ray {@code new Ray(p, direction, normal)} from the surface
     * point p (px, py, pz) with the unit normal (nx, ny, nz): the direction normalized, the head
     * moved off the surface.
     *
     * @return this record
     */
    RayHit secondary(double px, double py, double pz, double dx, double dy, double dz, double nx, double ny,
                     double nz) {
        setRay(px, py, pz, dx, dy, dz, nx, ny, nz);
        return this;
    }
}
