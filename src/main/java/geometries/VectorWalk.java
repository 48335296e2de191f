package geometries;

import static geometries.WideNodes.MAX_X;
import static geometries.WideNodes.MAX_Y;
import static geometries.WideNodes.MAX_Z;
import static geometries.WideNodes.MIN_X;
import static geometries.WideNodes.MIN_Y;
import static geometries.WideNodes.MIN_Z;
import static geometries.WideNodes.WIDTH;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The walks of a {@link Bvh}'s {@link WideNodes} with the Vector API: the four children's boxes
 * of a node tested in one 256-bit step. The only class that names {@code jdk.incubator.vector};
 * {@link Vectorization} loads it, by name, only when that module is readable, so that a JVM
 * without it never links this class.
 *
 * <p>Each lane computes exactly what the scalar {@link BoundingBox#entry} computes for that
 * child: the float bounds widened to double (exact), the same subtractions and products, and the
 * same selects ({@code a > b ? b : a}, not {@code min}, so that a 0·∞ = NaN lands where the
 * scalar test puts it). So every box is entered at the same distance, to the bit, and a walk
 * misses nothing the scalar walk finds. Which of two equally distant hits wins does not depend
 * on the order of the walk ({@link Bvh}'s tie rule), so both walks return the same hit.
 */
final class VectorWalk implements WideWalk {
    private static final VectorSpecies<Float> FLOATS = FloatVector.SPECIES_128;
    private static final VectorSpecies<Double> DOUBLES = DoubleVector.SPECIES_256;
    private static final DoubleVector ZERO = DoubleVector.zero(DOUBLES);

    /**
     * The walk for this machine: public for {@link Vectorization}'s reflective construction only.
     *
     * @throws UnsupportedOperationException on a CPU whose vectors hold fewer than four doubles,
     *                                       where the Vector API would emulate them, slower than the scalar walk
     */
    public VectorWalk() {
        int bits = DoubleVector.SPECIES_PREFERRED.vectorBitSize();
        if (bits < DOUBLES.vectorBitSize())
            throw new UnsupportedOperationException("scalar walk: this CPU's vectors hold " + bits
                    + " bits, the vector walk needs " + DOUBLES.vectorBitSize() + " (AVX2)");
    }

    /** The walk on any CPU, emulated where the vectors are narrower (the same answers): for the tests. */
    private VectorWalk(boolean anyCpu) {
    }

    /** @return the walk whatever the CPU's vectors, for the tests that it answers as the scalar walk */
    static VectorWalk anyCpu() {
        return new VectorWalk(true);
    }

    @Override
    public String description() {
        return WIDTH + "-wide vector walk (" + DOUBLES.vectorBitSize() + "-bit, jdk.incubator.vector)";
    }

    /** The bound {@code at} of the four children, widened to doubles. */
    private static DoubleVector bound(float[] nd, int at) {
        return (DoubleVector) FloatVector.fromArray(FLOATS, nd, at).convertShape(VectorOperators.F2D, DOUBLES, 0);
    }

    /**
     * The slab test of wide node {@code w}'s four children against the segment [0, limit]
     * ({@code limit} finite): the entry distances into {@code entries}.
     *
     * @return the children hit, one bit per lane
     */
    private static long test(float[] nd, int w, DoubleVector ox, DoubleVector oy, DoubleVector oz, DoubleVector ix,
                             DoubleVector iy, DoubleVector iz, double limit, double[] entries) {
        int at = WideNodes.at(w);
        DoubleVector t0 = ZERO, t1 = DoubleVector.broadcast(DOUBLES, limit);
        DoubleVector a = bound(nd, at + MIN_X).sub(ox).mul(ix), b = bound(nd, at + MAX_X).sub(ox).mul(ix);
        VectorMask<Double> swap = a.compare(VectorOperators.GT, b);
        DoubleVector near = a.blend(b, swap), far = b.blend(a, swap);
        t0 = t0.blend(near, near.compare(VectorOperators.GT, t0));
        t1 = t1.blend(far, far.compare(VectorOperators.LT, t1));
        a = bound(nd, at + MIN_Y).sub(oy).mul(iy);
        b = bound(nd, at + MAX_Y).sub(oy).mul(iy);
        swap = a.compare(VectorOperators.GT, b);
        near = a.blend(b, swap);
        far = b.blend(a, swap);
        t0 = t0.blend(near, near.compare(VectorOperators.GT, t0));
        t1 = t1.blend(far, far.compare(VectorOperators.LT, t1));
        a = bound(nd, at + MIN_Z).sub(oz).mul(iz);
        b = bound(nd, at + MAX_Z).sub(oz).mul(iz);
        swap = a.compare(VectorOperators.GT, b);
        near = a.blend(b, swap);
        far = b.blend(a, swap);
        t0 = t0.blend(near, near.compare(VectorOperators.GT, t0));
        t1 = t1.blend(far, far.compare(VectorOperators.LT, t1));
        t0.intoArray(entries, 0);
        return t0.compare(VectorOperators.LE, t1).toLong();
    }

    @Override
    public boolean closestHit(Bvh tree, float[] nd, Hit hit, int[] stack, double[] stackT) {
        DoubleVector ox = DoubleVector.broadcast(DOUBLES, hit.ox), oy = DoubleVector.broadcast(DOUBLES, hit.oy),
                oz = DoubleVector.broadcast(DOUBLES, hit.oz);
        DoubleVector ix = DoubleVector.broadcast(DOUBLES, BoundingBox.inverse(hit.dx)),
                iy = DoubleVector.broadcast(DOUBLES, BoundingBox.inverse(hit.dy)),
                iz = DoubleVector.broadcast(DOUBLES, BoundingBox.inverse(hit.dz));
        double[] entries = hit.lanes;
        int[] lanes = hit.laneOrder;
        boolean found = false;
        int top = 0, w = 0;
        while (true) {
            long bits = test(nd, w, ox, oy, oz, ix, iy, iz, Bvh.limit(hit.t), entries);
            int item = -1;
            if (bits != 0) {
                // The children hit, nearest first (equal entries in lane order): an insertion
                // sort of at most four. The nearest is visited now, the others pushed far first.
                int hits = 0;
                for (int j = 0; j < WIDTH; ++j) {
                    if ((bits & (1L << j)) == 0) continue;
                    double e = entries[j];
                    int i = hits++;
                    while (i > 0 && entries[lanes[i - 1]] > e) {
                        lanes[i] = lanes[i - 1];
                        --i;
                    }
                    lanes[i] = j;
                }
                for (int i = hits - 1; i > 0; --i) {
                    stack[top] = w * WIDTH + lanes[i];
                    stackT[top++] = entries[lanes[i]];
                }
                item = w * WIDTH + lanes[0];
            }
            while (true) {
                if (item < 0) {
                    do {
                        if (top == 0) return found;
                        --top;
                    } while (!(stackT[top] <= Bvh.limit(hit.t)));
                    item = stack[top];
                }
                int count = WideNodes.count(nd, item), link = WideNodes.link(nd, item);
                if (count == 0) {
                    w = link;
                    break;
                }
                found |= tree.closestInLeaf(link, count, hit);
                item = -1;
            }
        }
    }

    @Override
    public boolean visitHits(Bvh tree, float[] nd, Hit query, double limit, double maxDistance, HitVisitor visitor,
                             int[] stack) {
        DoubleVector ox = DoubleVector.broadcast(DOUBLES, query.ox), oy = DoubleVector.broadcast(DOUBLES, query.oy),
                oz = DoubleVector.broadcast(DOUBLES, query.oz);
        DoubleVector ix = DoubleVector.broadcast(DOUBLES, BoundingBox.inverse(query.dx)),
                iy = DoubleVector.broadcast(DOUBLES, BoundingBox.inverse(query.dy)),
                iz = DoubleVector.broadcast(DOUBLES, BoundingBox.inverse(query.dz));
        double[] entries = query.lanes;
        double bound = Bvh.limit(limit);
        int top = 0, w = 0;
        while (true) {
            long bits = test(nd, w, ox, oy, oz, ix, iy, iz, bound, entries);
            // In lane order, as the scalar walk meets them: pushed last first.
            for (int j = WIDTH - 1; j >= 0; --j)
                if ((bits & (1L << j)) != 0) stack[top++] = w * WIDTH + j;
            while (true) {
                if (top == 0) return true;
                int item = stack[--top];
                int count = WideNodes.count(nd, item), link = WideNodes.link(nd, item);
                if (count == 0) {
                    w = link;
                    break;
                }
                if (!tree.visitInLeaf(link, count, query, maxDistance, visitor)) return false;
            }
        }
    }
}
