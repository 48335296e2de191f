package geometries;

import static geometries.WideNodes.MAX_X;
import static geometries.WideNodes.MAX_Y;
import static geometries.WideNodes.MAX_Z;
import static geometries.WideNodes.MIN_X;
import static geometries.WideNodes.MIN_Y;
import static geometries.WideNodes.MIN_Z;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The walks of a {@link Bvh}'s {@link WideNodes} with the Vector API: all children's boxes of a
 * node tested in one vector step, four children in 256-bit vectors, eight in 512-bit ones (where
 * the CPU has them and the JDK compiles their masks: measured on JDK 25, not on 17, whose 512-bit
 * masks are built as objects); a leaf of triangles laid out in lanes ({@link TriangleLanes}, a
 * negative count in its node) is tested in one vector step too ({@link VectorTriangles}), any
 * other leaf by the tree's scalar loop. With {@link VectorTriangles}, the only classes that name
 * {@code jdk.incubator.vector}; {@link Vectorization} loads this one, by name, only when that
 * module is readable, so that a JVM without it never links either.
 *
 * <p>Each lane computes exactly what the scalar {@link BoundingBox#entry} computes for that
 * child: the float bounds widened to double (exact), the same subtractions and products, and the
 * same selects ({@code a > b ? b : a}, not {@code min}, so that a 0·∞ = NaN lands where the
 * scalar test puts it). So every box it tests is entered at the same distance, to the bit.
 * Which of two equally distant hits wins does not depend on the order of the walk ({@link Bvh}'s
 * tie rule), so both walks return the same hit.
 *
 * <p>What that rests on, stated: a triangle the leaf test hits lies in every box above it by the
 * box test too. The boxes are rounded outward from the triangles' bounds, and a hit is at least
 * 2<sup>−40</sup> of its triangle inside its edges, so only rounding at a box's very edge could
 * break it. There the walks could differ: a lane leaf ({@link WideNodes#collapse}) does not test
 * the boxes of the subtree it replaces, and the two walks compare different boxes' entries with
 * the current hit in different orders. Checked ray by ray: every Embree mesh's 262,144 rays ({@code scripts/embree_benchmark.py},
 * column "= scalar"), {@code WideWalkTest}, {@code VectorTrianglesTest} and the golden images.
 *
 * <p>Per node, two or more children hit put their entries on the stack; the nearest is walked
 * first, the rest pushed in lane order, unsorted (a sort of up to eight cost more than it saved).
 */
final class VectorWalk implements WideWalk {
    /** Whether this JVM takes eight lanes of doubles (512 bits) in a step: JDK 25 or later on a CPU that has them. */
    static final boolean WIDE = Runtime.version().feature() >= 25 && DoubleVector.SPECIES_PREFERRED.vectorBitSize() >= 512;
    /** The children's bounds as doubles: one vector per bound, a lane per child. Constant to the compiler. */
    private static final VectorSpecies<Double> DOUBLES = WIDE ? DoubleVector.SPECIES_512 : DoubleVector.SPECIES_256;
    /** The same bounds as stored, floats: half the vector. */
    private static final VectorSpecies<Float> FLOATS = DOUBLES == DoubleVector.SPECIES_512 ? FloatVector.SPECIES_256
            : FloatVector.SPECIES_128;
    /** Children per wide node. */
    private static final int WIDTH = DOUBLES.length();
    private static final DoubleVector ZERO = DoubleVector.zero(DOUBLES);
    private static final DoubleVector INFINITY = DoubleVector.broadcast(DOUBLES, Double.POSITIVE_INFINITY);
    /** Whether this JDK compiles {@code VectorMask.toLong} to one instruction (from JDK 18 on). */
    private static final boolean MASK_TO_BITS = Runtime.version().feature() >= 18;
    /** Primitives a tree must index for this walk to take it. */
    private final int minPrimitives;

    /**
     * The walk for this machine: public for {@link Vectorization}'s reflective construction only.
     *
     * @throws UnsupportedOperationException on a CPU whose vectors hold fewer than four doubles,
     *                                       where the Vector API would emulate them, slower than the scalar walk
     */
    public VectorWalk() {
        minPrimitives = Vectorization.minPrimitives();
        int bits = DoubleVector.SPECIES_PREFERRED.vectorBitSize();
        if (bits < DOUBLES.vectorBitSize())
            throw new UnsupportedOperationException(bits + "-bit vectors");
    }

    /** The walk on any CPU, emulated where the vectors are narrower (the same answers): for the tests. */
    private VectorWalk(boolean anyCpu) {
        minPrimitives = 0;
    }

    /** @return the walk whatever the CPU's vectors and the tree's size, for the tests that it answers as the scalar walk */
    static VectorWalk anyCpu() {
        return new VectorWalk(true);
    }

    @Override
    public int width() {
        return WIDTH;
    }

    @Override
    public int leafLanes() {
        return VectorTriangles.LANES.length();
    }

    @Override
    public int minPrimitives() {
        return minPrimitives;
    }

    @Override
    public String description() {
        return WIDTH + "-wide vector walk (trees of " + minPrimitives + " primitives or more)";
    }

    /**
     * The slab test of the children of the wide node whose record is at {@code at} against the
     * segment [0, limit] ({@code limit} finite): the entry distances into {@code entries} (when
     * two or more are hit).
     *
     * @return the children hit, one bit per lane
     */
    private static long test(float[] nd, int at, double rx, double ry, double rz, double rix, double riy, double riz,
                             double limit, double[] entries) {
        // The ray comes in as doubles and is broadcast here, per node (one instruction each):
        // vectors passed between methods that the compiler does not inline are boxed, 0.5 kB a ray.
        DoubleVector ox = DoubleVector.broadcast(DOUBLES, rx), oy = DoubleVector.broadcast(DOUBLES, ry),
                oz = DoubleVector.broadcast(DOUBLES, rz);
        DoubleVector ix = DoubleVector.broadcast(DOUBLES, rix), iy = DoubleVector.broadcast(DOUBLES, riy),
                iz = DoubleVector.broadcast(DOUBLES, riz);
        // The three axes written out, and the float bounds widened in place: split into per-axis
        // methods, the walk ran 1.5-2.1x slower (measured; the compiler stopped inlining them
        // part of the time, and vectors crossing a call that is not inlined are boxed). So no
        // method of ours takes or returns a vector: even a one-line helper was left out of line on
        // JDK 17 once its quick-tier code had grown large, and then every vector it returned was
        // an object (220 bytes a ray, WideWalkTest).
        DoubleVector t0 = ZERO, t1 = DoubleVector.broadcast(DOUBLES, limit);
        DoubleVector a = ((DoubleVector) FloatVector.fromArray(FLOATS, nd, WideNodes.bound(at, MIN_X, WIDTH))
                .convertShape(VectorOperators.F2D, DOUBLES, 0)).sub(ox).mul(ix);
        DoubleVector b = ((DoubleVector) FloatVector.fromArray(FLOATS, nd, WideNodes.bound(at, MAX_X, WIDTH))
                .convertShape(VectorOperators.F2D, DOUBLES, 0)).sub(ox).mul(ix);
        VectorMask<Double> swap = a.compare(VectorOperators.GT, b);
        DoubleVector near = a.blend(b, swap), far = b.blend(a, swap);
        t0 = t0.blend(near, near.compare(VectorOperators.GT, t0));
        t1 = t1.blend(far, far.compare(VectorOperators.LT, t1));
        a = ((DoubleVector) FloatVector.fromArray(FLOATS, nd, WideNodes.bound(at, MIN_Y, WIDTH))
                .convertShape(VectorOperators.F2D, DOUBLES, 0)).sub(oy).mul(iy);
        b = ((DoubleVector) FloatVector.fromArray(FLOATS, nd, WideNodes.bound(at, MAX_Y, WIDTH))
                .convertShape(VectorOperators.F2D, DOUBLES, 0)).sub(oy).mul(iy);
        swap = a.compare(VectorOperators.GT, b);
        near = a.blend(b, swap);
        far = b.blend(a, swap);
        t0 = t0.blend(near, near.compare(VectorOperators.GT, t0));
        t1 = t1.blend(far, far.compare(VectorOperators.LT, t1));
        a = ((DoubleVector) FloatVector.fromArray(FLOATS, nd, WideNodes.bound(at, MIN_Z, WIDTH))
                .convertShape(VectorOperators.F2D, DOUBLES, 0)).sub(oz).mul(iz);
        b = ((DoubleVector) FloatVector.fromArray(FLOATS, nd, WideNodes.bound(at, MAX_Z, WIDTH))
                .convertShape(VectorOperators.F2D, DOUBLES, 0)).sub(oz).mul(iz);
        swap = a.compare(VectorOperators.GT, b);
        near = a.blend(b, swap);
        far = b.blend(a, swap);
        t0 = t0.blend(near, near.compare(VectorOperators.GT, t0));
        t1 = t1.blend(far, far.compare(VectorOperators.LT, t1));
        VectorMask<Double> hit = t0.compare(VectorOperators.LE, t1);
        if (MASK_TO_BITS) {
            long bits = hit.toLong();
            // The distances matter only to order two or more children.
            if ((bits & (bits - 1)) != 0) t0.intoArray(entries, 0);
            return bits;
        }
        // JDK 17 compiles no mask-to-bits instruction (the mask would be built as an object, 0.1 kB
        // a ray): the missed children's entries are made +∞ instead and the bits read back, one
        // branch a lane. Each must stay a branch. When C2's profile saw the lanes hit about half
        // the time, it compiled the plain form (bits |= (e < ∞ ? 1 : 0) << j) to conditional
        // moves: the next node's address then waited for the vector store's read-back at every
        // node, where a branch, predicted well within a tile of coherent rays, lets the processor
        // run ahead. Which form C2 chose depended on the render's first tiles: the same mesh took
        // 3.5-4.2 s or 2.4-2.7 s (BENCHMARKS.md, issue 50, third session of 2026-11-29; with
        // -XX:ConditionalMoveLimit=0 always the latter). The store in the other arm keeps C2 from
        // making it a conditional move; a missed lane's entry is never read.
        t0.blend(INFINITY, hit.not()).intoArray(entries, 0);
        long bits = 0;
        for (int j = 0; j < WIDTH; ++j) {
            if (entries[j] < Double.POSITIVE_INFINITY) bits |= 1L << j;
            else entries[j] = Double.NaN;
        }
        return bits;
    }

    @Override
    public boolean closestHit(Bvh tree, float[] nd, double[] packed, Hit hit, int[] stack, double[] stackT) {
        double ox = hit.ox, oy = hit.oy, oz = hit.oz;
        double ix = BoundingBox.inverse(hit.dx), iy = BoundingBox.inverse(hit.dy), iz = BoundingBox.inverse(hit.dz);
        double[] entries = hit.lanes;
        boolean found = false;
        int top = 0, w = 0;
        while (true) {
            int at = WideNodes.at(w, WIDTH);
            long bits = test(nd, at, ox, oy, oz, ix, iy, iz, Bvh.limit(hit.t), entries);
            int item = -1;
            long rest = bits & (bits - 1); // the children hit but the first
            if (rest == 0) {
                // None or one child hit: nothing to order.
                if (bits != 0) item = at + Long.numberOfTrailingZeros(bits);
            } else if ((rest & (rest - 1)) == 0) {
                // Two, the commonest case of several: one comparison instead of the sort (the
                // nearer first, the first in lane order of equal entries, as the sort orders them).
                int a = Long.numberOfTrailingZeros(bits), b = Long.numberOfTrailingZeros(rest);
                boolean bFirst = entries[b] < entries[a];
                int far = bFirst ? a : b;
                stack[top] = at + far;
                stackT[top++] = entries[far];
                item = at + (bFirst ? b : a);
            } else {
                // Three or more: the nearest now (the first in lane order of equal entries), the
                // others pushed in lane order, unsorted. Which hit wins does not depend on the
                // order (the tie rule), and the stack's entries still prune them; a sort of up to
                // eight cost more than the boxes it saved (BENCHMARKS.md, issue 50, item 4).
                int near = Long.numberOfTrailingZeros(bits);
                double nearest = entries[near];
                for (long left = rest; left != 0; left &= left - 1) {
                    int j = Long.numberOfTrailingZeros(left);
                    if (entries[j] < nearest) {
                        nearest = entries[j];
                        near = j;
                    }
                }
                for (long left = bits & ~(1L << near); left != 0; left &= left - 1) {
                    int j = Long.numberOfTrailingZeros(left);
                    stack[top] = at + j;
                    stackT[top++] = entries[j];
                }
                item = at + near;
            }
            while (true) {
                if (item < 0) {
                    do {
                        if (top == 0) return found;
                        --top;
                    } while (!(stackT[top] <= Bvh.limit(hit.t)));
                    item = stack[top];
                }
                int count = WideNodes.count(nd, item, WIDTH), link = WideNodes.link(nd, item, WIDTH);
                if (count == 0) {
                    w = link;
                    break;
                }
                // A leaf of triangles in lanes: one vector step (its distances over the entries,
                // which are read no more at this node); any other leaf, in scalar code.
                found |= count < 0 ? VectorTriangles.closest(tree, packed, link, -count, hit, entries)
                        : tree.closestInLeaf(link, count, hit);
                item = -1;
            }
        }
    }

    @Override
    public boolean visitHits(Bvh tree, float[] nd, double[] packed, Hit query, double limit, double maxDistance,
                             HitVisitor visitor, int[] stack) {
        double ox = query.ox, oy = query.oy, oz = query.oz;
        double ix = BoundingBox.inverse(query.dx), iy = BoundingBox.inverse(query.dy), iz = BoundingBox.inverse(query.dz);
        double[] entries = query.lanes;
        double bound = Bvh.limit(limit);
        int top = 0, w = 0;
        while (true) {
            int at = WideNodes.at(w, WIDTH);
            long bits = test(nd, at, ox, oy, oz, ix, iy, iz, bound, entries);
            // In lane order, as the scalar walk meets them: pushed last first.
            for (long rest = Long.reverse(bits); rest != 0; rest &= rest - 1)
                stack[top++] = at + 63 - Long.numberOfTrailingZeros(rest);
            while (true) {
                if (top == 0) return true;
                int item = stack[--top];
                int count = WideNodes.count(nd, item, WIDTH), link = WideNodes.link(nd, item, WIDTH);
                if (count == 0) {
                    w = link;
                    break;
                }
                if (count < 0 ? !VectorTriangles.visit(tree, packed, link, -count, query, maxDistance, visitor, entries)
                        : !tree.visitInLeaf(link, count, query, maxDistance, visitor)) return false;
            }
        }
    }
}
