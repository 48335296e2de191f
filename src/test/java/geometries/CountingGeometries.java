package geometries;

/**
 * A geometry list that counts its any-hit walks, for tests of other packages: a walk not taken
 * is a shadow ray the renderer answered otherwise (its shadow cache). The walk is package-private,
 * so a counting subclass can only be written here.
 */
public final class CountingGeometries extends Geometries {
    private int walks;

    /** @return the any-hit walks of this list so far */
    public int walks() {
        return walks;
    }

    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        ++walks;
        return super.visitHits(query, maxDistance, visitor);
    }
}
