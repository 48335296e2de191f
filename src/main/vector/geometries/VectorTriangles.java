package geometries;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The Möller–Trumbore test of a leaf's triangles in one vector step, a triangle per lane, from
 * the leaf layout of {@link TriangleLanes}: the {@link VectorWalk}'s leaf test.
 *
 * <p>Exact: each lane computes the doubles {@code Triangle.intersect} computes for its triangle,
 * the same products, sums and quotient in the same order ({@code a·b + c·d + e·f} as
 * {@code (a·b + c·d) + e·f}; no fused multiply-add, which the scalar kernel does not use), so a
 * lane's distance is the scalar distance to the bit. Where the scalar kernel returns NaN early (a
 * determinant or a barycentric coordinate out of its tolerance), the lane computes on and its
 * distance is replaced by NaN at the end: the same answer. The distances are then offered to the
 * hit (or the visitor) one by one in leaf order, by the tree's own scalar rule, so the winner,
 * its distance and the tie rule are the scalar loop's ({@code VectorTrianglesTest}, ray by ray).
 *
 * <p>Eight lanes (512-bit vectors) where the walk's nodes are eight wide (JDK 25 on AVX-512, see
 * {@link VectorWalk}), else four (256-bit vectors, which every CPU the vector walk runs on has;
 * JDK 17 builds 512-bit masks as objects). A lane leaf holds as many ({@link TriangleLanes}).
 */
final class VectorTriangles {
    static final VectorSpecies<Double> LANES = VectorWalk.WIDE ? DoubleVector.SPECIES_512 : DoubleVector.SPECIES_256;
    /** {@code primitives.Util}'s zero tolerance, 2^-40: {@code isZero(x)} is {@code |x| < ZERO}. */
    static final double ZERO = 0x1p-40;
    /** Lane j holds j: the lanes at or past a leaf's count are not its triangles. */
    private static final DoubleVector LANE_INDEX = DoubleVector.fromArray(LANES, new double[] { 0, 1, 2, 3, 4, 5, 6, 7 }, 0);
    private static final DoubleVector NAN = DoubleVector.broadcast(LANES, Double.NaN);
    /** Whether this JDK compiles {@code VectorMask.toLong} to one instruction (from JDK 18 on). */
    private static final boolean MASK_TO_BITS = Runtime.version().feature() >= 18;

    static {
        if (LANES.length() > TriangleLanes.MAX_LANES || LANES.length() > WideNodes.MAX_WIDTH)
            throw new AssertionError("lanes " + LANES.length());
    }

    private VectorTriangles() {
    }

    /**
     * The distances of the lane leaf of {@code count} triangles from {@code first} (its numbers in
     * {@code s}, as {@link TriangleLanes} lays them out), NaN for a miss, into
     * {@code out[0 … count)}; only when one of them may be a hit nearer than {@code bound}.
     *
     * @param bound the distance no hit is taken beyond (the current hit's, for a closest hit: a
     *              tie at it may still win; +∞ for no bound)
     * @return the triangles hit at {@code t} with {@code alignZero(t) > 0} and {@code t <= bound},
     *         a bit per lane ({@code out} then written); 0 for none ({@code out} untouched). On
     *         JDK 17, every lane of the leaf when one is (no mask-to-bits instruction there)
     */
    static long distances(double[] s, int first, int count, Hit ray, double bound, double[] out) {
        // Number r of the leaf's triangles: row r, a lane per triangle (lanes past the count read
        // whatever follows). Loaded here, not in a helper: a method that returns a vector may be
        // left out of line by the compiler (JDK 17), and the vector is then an object.
        int row = TriangleLanes.row(first, count, 0);
        DoubleVector ax = DoubleVector.fromArray(LANES, s, row), ay = DoubleVector.fromArray(LANES, s, row + count),
                az = DoubleVector.fromArray(LANES, s, row + 2 * count);
        DoubleVector e1x = DoubleVector.fromArray(LANES, s, row + 3 * count),
                e1y = DoubleVector.fromArray(LANES, s, row + 4 * count), e1z = DoubleVector.fromArray(LANES, s, row + 5 * count);
        DoubleVector e2x = DoubleVector.fromArray(LANES, s, row + 6 * count),
                e2y = DoubleVector.fromArray(LANES, s, row + 7 * count), e2z = DoubleVector.fromArray(LANES, s, row + 8 * count);
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        // Triangle.intersect, lane by lane, in its order. Products are commutative in IEEE
        // arithmetic (dy·e2z is e2z·dy to the bit); only the grouping of sums matters, kept.
        DoubleVector px = e2z.mul(dy).sub(e2y.mul(dz)), py = e2x.mul(dz).sub(e2z.mul(dx)),
                pz = e2y.mul(dx).sub(e2x.mul(dy));
        DoubleVector det = e1x.mul(px).add(e1y.mul(py)).add(e1z.mul(pz));
        // isZero(det): |det| < 2^-40 (NaN is not zero, and computes on as the scalar kernel does).
        VectorMask<Double> miss = det.abs().compare(VectorOperators.LT, ZERO);
        DoubleVector inv = DoubleVector.broadcast(LANES, 1.0).div(det);
        DoubleVector tx = DoubleVector.broadcast(LANES, ray.ox).sub(ax), ty = DoubleVector.broadcast(LANES, ray.oy).sub(ay),
                tz = DoubleVector.broadcast(LANES, ray.oz).sub(az);
        DoubleVector u = tx.mul(px).add(ty.mul(py)).add(tz.mul(pz)).mul(inv);
        // alignZero(u) <= 0 is u < 2^-40, and alignZero(u - 1) >= 0 is u - 1 > -2^-40: for every
        // double, NaN included (false both ways), -0.0 and the tolerance's edges (TriangleLanesTest).
        miss = miss.or(u.compare(VectorOperators.LT, ZERO)).or(u.sub(1.0).compare(VectorOperators.GT, -ZERO));
        DoubleVector qx = e1z.mul(ty).sub(e1y.mul(tz)), qy = e1x.mul(tz).sub(e1z.mul(tx)),
                qz = e1y.mul(tx).sub(e1x.mul(ty));
        DoubleVector v = qx.mul(dx).add(qy.mul(dy)).add(qz.mul(dz)).mul(inv);
        miss = miss.or(v.compare(VectorOperators.LT, ZERO)).or(u.add(v).sub(1.0).compare(VectorOperators.GT, -ZERO));
        DoubleVector t = e2x.mul(qx).add(e2y.mul(qy)).add(e2z.mul(qz)).mul(inv).blend(NAN, miss);
        // A hit the caller may take: alignZero(t) > 0 (t >= 2^-40) and t <= bound, in a lane of the leaf.
        VectorMask<Double> may = t.compare(VectorOperators.GE, ZERO).and(t.compare(VectorOperators.LE, bound))
                .and(LANE_INDEX.compare(VectorOperators.LT, (double) count));
        if (MASK_TO_BITS) {
            long bits = may.toLong();
            if (bits != 0) t.intoArray(out, 0);
            return bits;
        }
        // JDK 17 compiles no mask-to-bits instruction: every lane of the leaf, which the caller's rule sorts out.
        if (!may.anyTrue()) return 0;
        t.intoArray(out, 0);
        return (1L << count) - 1;
    }

    /**
     * The closest-hit test of the lane leaf of {@code count} triangles from {@code first}: each
     * distance offered to {@code hit} in leaf order by the tree's rule ({@link Bvh#offerTriangle}).
     *
     * @param scratch room for {@link TriangleLanes#MAX_LANES} distances
     * @return whether a triangle of the leaf now holds the hit
     */
    static boolean closest(Bvh tree, double[] s, int first, int count, Hit hit, double[] scratch) {
        boolean found = false;
        for (long may = distances(s, first, count, hit, hit.t, scratch); may != 0; may &= may - 1) {
            int j = Long.numberOfTrailingZeros(may);
            found |= tree.offerTriangle(first + j, scratch[j], hit);
        }
        return found;
    }

    /**
     * The any-hit visit of the lane leaf: each hit within {@code maxDistance} to {@code visitor}
     * in leaf order ({@link Bvh#visitTriangle}).
     *
     * @param scratch room for {@link TriangleLanes#MAX_LANES} distances
     * @return false when the visitor stopped the walk
     */
    static boolean visit(Bvh tree, double[] s, int first, int count, Hit query, double maxDistance, HitVisitor visitor,
                         double[] scratch) {
        // No bound here: within(t, max) is asked lane by lane; the vector step rules out the
        // leaves where no triangle is hit in front of the ray, most of them.
        long may = distances(s, first, count, query, Double.POSITIVE_INFINITY, scratch);
        // Read out before any visitor runs: one may query a tree with this record, whose walk
        // writes the same scratch. (Where no lane may hit, these are stale and never read.)
        double t0 = scratch[0], t1 = scratch[1], t2 = scratch[2], t3 = scratch[3];
        double t4 = scratch[4], t5 = scratch[5], t6 = scratch[6], t7 = scratch[7];
        // One loop, the distances shifted down a lane a turn, up to the last lane that may hit (the
        // lanes between are refused by visitTriangle's rule, as before), and no early return for
        // a leaf missed: C2 compiles a branch that its profile never saw taken to a trap, and the
        // first tiles of a render saw no shadow ray stopped at lane 3 or 6, or no leaf missed
        // after its box was hit. Each of those, met later, threw the compiled any-hit walk back to
        // the interpreter, where vector code is slow: seven times in the first two seconds of the
        // teapot scene on JDK 25 when each lane had its branch (BENCHMARKS.md, issue 50).
        for (int k = first; may != 0; may >>>= 1, ++k) {
            if (!tree.visitTriangle(k, t0, maxDistance, visitor)) return false;
            t0 = t1;
            t1 = t2;
            t2 = t3;
            t3 = t4;
            t4 = t5;
            t5 = t6;
            t6 = t7;
        }
        return true;
    }
}
