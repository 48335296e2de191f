package geometries;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveAction;

import primitives.Ray;

/**
 * A bounding volume hierarchy: just another {@link Intersectable}. Built once from the leaves of
 * a {@link Geometries} (a mesh contributes each triangle as a primitive), by the binned
 * surface-area heuristic, and flattened into arrays in depth-first order so that a walk touches
 * no objects but the primitives it tests. Containers are flattened: a {@link Geometries} hands over
 * its children's leaves (an empty one contributes nothing) and a nested {@code Bvh} its own leaves.
 * Leaves without a bounding box (planes, tubes, user shapes that define none) are kept in a short
 * list beside the tree and tested for every ray.
 *
 * <p>Immutable after {@link #build}; any number of threads may query it. The build is
 * deterministic: the same scene gives the same tree.
 */
public final class Bvh extends Intersectable {
    private static final int BINS = 16;
    private static final int MAX_LEAF = 4;
    /** Cost of visiting a node relative to testing one primitive, for the SAH. */
    private static final double TRAVERSAL_COST = 1.0;
    /** Nodes with more primitives than this are binned along their widest axis only. */
    private static final int FULL_SEARCH_LIMIT = 1 << 16;
    /**
     * Subtrees over more primitives than this are built as parallel tasks; smaller ones are not
     * worth a task (about 0.1 ms of work).
     */
    private static final int FORK_ABOVE = 4096;
    /** The builder's bounds of a range: box min xyz, max xyz, then centroid min xyz, max xyz. */
    private static final int BOUNDS = 12;
    /** Leaves or primitives per task in the build's flat loops (about 1 ms of work). */
    private static final int GRAIN = 1 << 14;

    /** The leaves this tree indexes, as collected: what it contributes to a tree built around it. */
    private final Intersectable[] leaves;
    private final Intersectable[] unbounded;
    // Per primitive, in leaf order: its owner and its index within the owner.
    private final Intersectable[] owner;
    private final int[] prim;
    // Per primitive, in leaf order: its packed kind (Intersectable.OWN, SPHERE or TRIANGLE) and
    // PACKED doubles of intersection data, so that a leaf's library shapes are tested from one
    // contiguous run of memory instead of one object (and its centre) each, scattered on the heap.
    private final byte[] kind;
    private final double[] packed;
    // Per node, depth-first, one packed record of NODE floats = 32 bytes, two nodes per cache line
    // (a node and its left child, which follows it, often share one): the box (min xyz, max xyz)
    // rounded outward to floats, so that it contains the exact box and no hit is lost, then, as
    // raw int bits, for a leaf its first primitive and its primitive count (> 0), for an inner
    // node its right child (the left child is the next node) and INNER | its skip link (the first
    // node after its subtree, where the any-hit walk goes when the box is missed; a leaf's is the
    // next node). Floats halve the bytes a walk touches, and the skip link in the record spares
    // the any-hit walk a second array, which is what a ray costs in a scene far larger than the
    // caches.
    private static final int NODE = 8;
    /**
     * Floats before node 0's record. The data of a large array starts 16 bytes (its header) past
     * a 64-byte boundary (G1 places a humongous array at the start of a region); 48 bytes more
     * put each 32-byte record inside one cache line, two to a line, where otherwise every other
     * record would straddle two lines. (About 4 % off a camera ray at 2×10⁶ primitives.) A small
     * array is only 8-byte aligned, but its tree stays in the caches anyway.
     */
    private static final int BASE = 12;
    private final float[] node;
    /** The exact (double) box of the root, or null when nothing is bounded. */
    private final BoundingBox rootBox;
    /**
     * Marks an inner node's last field (a negative int; with fewer than 0x7F800000 nodes the bits
     * are never a NaN pattern, so they survive the round trip through float).
     */
    private static final int INNER = Integer.MIN_VALUE;
    private final int nodeCount;
    private final int depth;

    /**
     * The tree of {@code geometries} as they are now, for a render: the tree an earlier call
     * built is reused when the geometries still hold the same leaves (the same objects, in the
     * same order, found through every nested list) and all of them are
     * {@link Geometry#isLibraryShape() library shapes}, whose geometry cannot change; otherwise a new tree is built (as {@link #build(Geometries)}) and
     * kept for the next call. So the renders of several cameras, or frames, of one scene build
     * it once, and any shape added anywhere in the scene is seen by the next render. The check
     * costs one pass over the leaves, far less than a build.
     *
     * @param geometries the scene's geometries; bounded leaves go into the tree
     * @return the hierarchy, immutable, safe to share between render threads
     */
    public static Bvh of(Geometries geometries) {
        List<Intersectable> collected = new ArrayList<>();
        geometries.collectLeaves(collected);
        Intersectable[] now = collected.toArray(new Intersectable[0]);
        Bvh kept = geometries.keptTree();
        if (kept != null && kept.indexes(now)) return kept;
        Bvh tree = new Bvh(now, Runtime.getRuntime().availableProcessors(), FORK_ABOVE, true);
        for (Intersectable leaf : now)
            if (!(leaf instanceof Geometry g && g.isLibraryShape())) return tree;
        geometries.keepTree(tree);
        return tree;
    }

    /**
     * Indexes the leaves of {@code geometries} as they are now: geometries added later are not in
     * the tree, so build it after the scene is complete (a render asks {@link #of}, which builds it
     * once per unchanged scene).
     * Builds on every available processor; the tree does not depend on how many.
     *
     * @param geometries the scene's geometries; bounded leaves go into the tree
     * @return the hierarchy, immutable, safe to share between render threads
     */
    public static Bvh build(Geometries geometries) {
        return build(geometries, Runtime.getRuntime().availableProcessors());
    }

    /**
     * Indexes the leaves of {@code geometries} as they are now, building subtrees of large scenes
     * in parallel. The tree is the same for every {@code parallelism}: the same nodes, boxes and
     * primitive order, hence the same answers in the same order.
     *
     * @param geometries  the scene's geometries; bounded leaves go into the tree
     * @param parallelism the number of threads the build may use; 1 builds on the calling thread
     * @return the hierarchy, immutable, safe to share between render threads
     * @throws IllegalArgumentException when {@code parallelism < 1}
     */
    public static Bvh build(Geometries geometries, int parallelism) {
        return build(geometries, parallelism, FORK_ABOVE);
    }

    /** As {@link #build(Geometries, int)}, forking subtrees over more than {@code forkAbove} primitives. */
    static Bvh build(Geometries geometries, int parallelism, int forkAbove) {
        return build(geometries, parallelism, forkAbove, true);
    }

    /**
     * As {@link #build(Geometries, int, int)}, searching nodes of two primitives without bins
     * when {@code pairs} (else every node with bins; for the tests that both searches agree).
     */
    static Bvh build(Geometries geometries, int parallelism, int forkAbove, boolean pairs) {
        if (parallelism < 1) throw new IllegalArgumentException("parallelism must be at least 1, got " + parallelism);
        List<Intersectable> collected = new ArrayList<>();
        geometries.collectLeaves(collected);
        return new Bvh(collected.toArray(new Intersectable[0]), parallelism, Math.max(1, forkAbove), pairs);
    }

    /** Indexes {@code all}, a scene's leaves (this tree keeps the array). */
    private Bvh(Intersectable[] all, int parallelism, int forkAbove, boolean pairs) {
        leaves = all;
        int count = all.length;
        // Threads start on the first task, so an idle pool costs nothing.
        ForkJoinPool pool = parallelism > 1 ? new ForkJoinPool(parallelism) : null;
        int grain = Math.min(GRAIN, forkAbove); // the tests' small forkAbove splits small scenes too
        try {
            // A shape may compute its box on every call (a polygon does): ask each leaf once. A
            // bounded leaf's primitives take the slots [first[l], first[l + 1]). The boxes are
            // kept as doubles, not objects: two million of those would survive young collections
            // and be marked by every concurrent cycle the build's big arrays start.
            double[] leafBox = new double[count * 6];
            boolean[] bounded = new boolean[count];
            int[] first = new int[count + 1];
            // Set (never cleared) by any chunk that meets a packed shape; read after the join.
            boolean[] packs = new boolean[1];
            Ranges.run(pool, count, grain, (from, to) -> {
                for (int l = from; l < to; ++l) {
                    BoundingBox b = all[l].getBoundingBox();
                    if (b == null) continue;
                    bounded[l] = true;
                    if (all[l].packedKind() != OWN) packs[0] = true;
                    first[l + 1] = all[l].primitiveCount();
                    int o = l * 6;
                    leafBox[o] = b.minX;
                    leafBox[o + 1] = b.minY;
                    leafBox[o + 2] = b.minZ;
                    leafBox[o + 3] = b.maxX;
                    leafBox[o + 4] = b.maxY;
                    leafBox[o + 5] = b.maxZ;
                }
            });
            List<Intersectable> free = new ArrayList<>();
            for (int l = 0; l < count; ++l) {
                if (!bounded[l]) free.add(all[l]);
                first[l + 1] += first[l];
            }
            unbounded = free.toArray(new Intersectable[0]);

            int total = first[count];
            Builder b = new Builder(total, pool, forkAbove, pairs);
            // By slot rather than by leaf, so that the triangles of one big mesh are shared out too.
            // Each chunk also leaves the bounds of its slots (BOUNDS doubles) in chunkBounds; their
            // union is the root's, found without a pass of its own. All start empty: without a
            // pool one chunk runs the whole range, and the others' places must not count.
            double[] chunkBounds = new double[(Math.max(total, 1) + grain - 1) / grain * BOUNDS];
            for (int at = 0; at < chunkBounds.length; at += BOUNDS) Builder.resetBounds(chunkBounds, at);
            Ranges.run(pool, total, grain, (from, to) -> {
                int l = leafOfSlot(first, from);
                for (int s = from; s < to; ++s) {
                    while (s >= first[l + 1]) ++l;
                    if (first[l + 1] - first[l] == 1) {
                        b.addPrimitive(s, all[l], 0, leafBox, l * 6);
                    } else {
                        BoundingBox p = all[l].primitiveBounds(s - first[l]);
                        double[] box = { p.minX, p.minY, p.minZ, p.maxX, p.maxY, p.maxZ };
                        b.addPrimitive(s, all[l], s - first[l], box, 0);
                    }
                }
                b.unite(chunkBounds, from / grain * BOUNDS, from, to);
            });
            double[] rootBounds = new double[BOUNDS];
            b.unite(rootBounds, chunkBounds);
            b.build(rootBounds);
            // The leaves' primitives in leaf order, and each slot's place in it. A gather through
            // the final permutation, in leaf order: in one tight loop the memory system overlaps
            // its random reads (done per leaf, as the leaves were made, they cost 10 % of a build).
            int[] order = b.order;
            Intersectable[] ordered = new Intersectable[total];
            int[] orderedPrim = new int[total];
            int[] leafAt = new int[packs[0] ? total : 0];
            Ranges.run(pool, total, grain, (from, to) -> {
                for (int k = from; k < to; ++k) {
                    int s = order[k];
                    ordered[k] = b.owners[s];
                    orderedPrim[k] = b.prims[s];
                    if (leafAt.length > 0) leafAt[s] = k;
                }
            });
            owner = ordered;
            prim = orderedPrim;
            kind = new byte[total];
            packed = new double[packs[0] ? total * PACKED : 0];
            if (packs[0]) {
                // In slot order, that is the scene's order, in which its objects were most likely
                // made: the objects are read one after the other, the packed records written at
                // their leaf places. (Packing as the leaves are made read them at random: 0.5 s
                // more for a one-thread build of 2×10⁶.)
                Ranges.run(pool, total, grain, (from, to) -> {
                    for (int s = from; s < to; ++s) {
                        Intersectable leaf = b.owners[s];
                        byte k = leaf.packedKind();
                        if (k == OWN) continue;
                        kind[leafAt[s]] = k;
                        leaf.pack(b.prims[s], packed, leafAt[s] * PACKED);
                    }
                });
            }
            nodeCount = b.nodes;
            node = b.node;
            rootBox = b.rootBox;
            depth = b.maxDepth + 1;
        } finally {
            if (pool != null) pool.shutdown();
        }
    }

    /** @return whether this tree was built over exactly {@code now}: the same objects in the same order */
    private boolean indexes(Intersectable[] now) {
        if (now.length != leaves.length) return false;
        for (int i = 0; i < now.length; ++i)
            if (now[i] != leaves[i]) return false;
        return true;
    }

    /** @return the leaf whose slots [first[l], first[l + 1]) hold {@code slot} (first is non-decreasing) */
    private static int leafOfSlot(int[] first, int slot) {
        int lo = 0, hi = first.length - 2; // the answer is in [lo, hi]
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (first[mid] <= slot) lo = mid;
            else hi = mid - 1;
        }
        return lo;
    }

    /**
     * Whether {@code other} is the same tree as this one: the same nodes (boxes bit for bit, links)
     * over the same primitives in the same leaf order. For the tests of the build's determinism.
     */
    boolean sameTreeAs(Bvh other) {
        if (!java.util.Arrays.equals(node, other.node)
                || !java.util.Arrays.equals(prim, other.prim) || owner.length != other.owner.length
                || unbounded.length != other.unbounded.length || depth != other.depth)
            return false;
        for (int i = 0; i < owner.length; ++i)
            if (owner[i] != other.owner[i]) return false;
        for (int i = 0; i < unbounded.length; ++i)
            if (unbounded[i] != other.unbounded[i]) return false;
        return true;
    }

    /** @return the number of nodes in the tree (0 when nothing is bounded) */
    public int nodeCount() {
        return nodeCount;
    }

    /** @return the number of bounded primitives indexed */
    public int primitiveTotal() {
        return prim.length;
    }

    /**
     * The bytes of the arrays the walks read: 32 a node, and per primitive 9 (its owner, counted
     * as a 4-byte compressed reference, its index and its packed kind) plus {@value #PACKED} doubles
     * when the tree packs some primitive (a scene with library spheres or triangles).
     *
     * @return the tree's size in bytes, without the scene's own objects
     */
    public long indexBytes() {
        return nodeCount * (long) NODE * Float.BYTES + prim.length * 9L + packed.length * (long) Double.BYTES;
    }

    /** @return the number of unbounded geometries tested beside the tree */
    public int unboundedCount() {
        return unbounded.length;
    }

    /** @return the depth of the tree (1 for a single leaf, 0 when empty) */
    public int depth() {
        return nodeCount == 0 ? 0 : depth;
    }

    /**
     * The slab test of node {@code n} against the ray segment [0, tMax].
     *
     * @return the distance at which the ray enters the box, or +∞ when it misses it
     */
    private double entry(int n, double ox, double oy, double oz, double ix, double iy, double iz, double tMax) {
        int o = BASE + n * NODE;
        float[] bx = node;
        // Computed in doubles from the widened float box: every hit of the exact box stays a hit,
        // and the entry distance can only come out lower, so skipping a node by it stays safe.
        double t0 = 0, t1 = tMax;
        double a = (bx[o] - ox) * ix, b = (bx[o + 3] - ox) * ix;
        if (a > b) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (bx[o + 1] - oy) * iy;
        b = (bx[o + 4] - oy) * iy;
        if (a > b) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        a = (bx[o + 2] - oz) * iz;
        b = (bx[o + 5] - oz) * iz;
        if (a > b) { double s = a; a = b; b = s; }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    /**
     * The ordered walk: at an inner node both children's boxes are tested; the nearer one (by
     * entry distance) is visited first and the other pushed with its entry distance, so that
     * when popped it is skipped if a hit nearer than its box was found meanwhile.
     */
    @Override
    public boolean closestHit(Hit hit) {
        boolean found = false;
        for (Intersectable u : unbounded) found |= u.closestHit(hit);
        if (nodeCount == 0) return found;
        double ox = hit.ox, oy = hit.oy, oz = hit.oz;
        double ix = BoundingBox.inverse(hit.dx), iy = BoundingBox.inverse(hit.dy), iz = BoundingBox.inverse(hit.dz);
        if (!(entry(0, ox, oy, oz, ix, iy, iz, hit.t) < hit.t)) return found;
        // A walk already in progress on this record (this one's caller, through a user's shape
        // that walks a tree of its own with the record) owns the record's stack: this one then
        // takes arrays of its own. Rare (only user shapes do it), so the common walk stays as it was.
        boolean nested = hit.walking;
        int[] stack;
        double[] stackT;
        if (nested) {
            stack = new int[depth];
            stackT = new double[depth];
        } else {
            if (hit.stack.length < depth) {
                hit.stack = new int[depth];
                hit.stackT = new double[depth];
            }
            stack = hit.stack;
            stackT = hit.stackT;
            hit.walking = true;
        }
        try {
            float[] nd = node;
            int top = 0;
            int n = 0;
            while (true) {
                int o = BASE + n * NODE;
                int count = Float.floatToRawIntBits(nd[o + 7]);
                if (count > 0) {
                    for (int k = Float.floatToRawIntBits(nd[o + 6]), end = k + count; k < end; ++k) {
                        byte kd = kind[k];
                        if (kd == OWN) {
                            found |= owner[k].closestHit(prim[k], hit);
                            continue;
                        }
                        int at = k * PACKED;
                        double t = kd == SPHERE ? Sphere.distance(hit, packed[at], packed[at + 1], packed[at + 2], packed[at + 3])
                                : Triangle.intersect(hit, packed, at);
                        if (inRange(t, hit.t)) {
                            hit.set(t, (Geometry) owner[k], prim[k]);
                            found = true;
                        }
                    }
                } else {
                    int left = n + 1, right = Float.floatToRawIntBits(nd[o + 6]);
                    double tMax = hit.t;
                    double tl = entry(left, ox, oy, oz, ix, iy, iz, tMax);
                    double tr = entry(right, ox, oy, oz, ix, iy, iz, tMax);
                    // One branch where there were four: a missed child's entry is +∞ (or tMax, never
                    // below it), so "tl <= tr" picks the child to visit whichever were hit, and the
                    // other is written to the stack always but kept (top moves) only when it was hit.
                    // Which children are hit, and in which order, is a coin toss per node in a big
                    // scene; selects cost less than the mispredictions (3–4 % at 2×10⁶ primitives).
                    if (tl < tMax || tr < tMax) {
                        boolean leftFirst = tl <= tr;
                        int far = leftFirst ? right : left;
                        double tf = leftFirst ? tr : tl;
                        n = leftFirst ? left : right;
                        stack[top] = far;
                        stackT[top] = tf;
                        top += tf < tMax ? 1 : 0;
                        continue;
                    }
                }
                do {
                    if (top == 0) return found;
                    --top;
                } while (!(stackT[top] < hit.t));
                n = stack[top];
            }
        } finally {
            if (!nested) hit.walking = false;
        }
    }

    @Override
    public boolean closestHit(Ray ray, Hit hit) {
        return closestHit(hit.setRay(ray));
    }

    /** The stackless walk: order does not matter for an any-hit query, so skip links suffice. */
    @Override
    public boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        for (Intersectable u : unbounded)
            if (!u.visitHits(query, maxDistance, visitor)) return false;
        double ox = query.ox, oy = query.oy, oz = query.oz;
        double ix = BoundingBox.inverse(query.dx), iy = BoundingBox.inverse(query.dy), iz = BoundingBox.inverse(query.dz);
        // Boxes are tested a little past maxDistance: a hit exactly at it still counts (course rule).
        double limit = maxDistance * (1 + 1e-9) + 1e-9;
        float[] nd = node;
        int n = 0;
        while (n < nodeCount) {
            int last = Float.floatToRawIntBits(nd[BASE + n * NODE + 7]);
            if (entry(n, ox, oy, oz, ix, iy, iz, limit) == Double.POSITIVE_INFINITY) {
                n = last > 0 ? n + 1 : last & ~INNER;
                continue;
            }
            if (last > 0) {
                for (int k = Float.floatToRawIntBits(nd[BASE + n * NODE + 6]), end = k + last; k < end; ++k) {
                    byte kd = kind[k];
                    int at = k * PACKED;
                    if (kd == OWN) {
                        if (!owner[k].visitHits(prim[k], query, maxDistance, visitor)) return false;
                    } else if (kd == SPHERE) {
                        if (!Sphere.visitHits((Geometry) owner[k], query, maxDistance, visitor,
                                packed[at], packed[at + 1], packed[at + 2], packed[at + 3])) return false;
                    } else {
                        double t = Triangle.intersect(query, packed, at);
                        if (within(t, maxDistance) && !visitor.visit((Geometry) owner[k], t)) return false;
                    }
                }
            }
            ++n; // into an inner node's left child, or past a leaf
        }
        return true;
    }

    @Override
    public boolean visitHits(Ray ray, double maxDistance, HitVisitor visitor) {
        return visitHits(Hit.of(ray), maxDistance, visitor);
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        List<GeoPoint> result = new ArrayList<>();
        visitHits(ray, maxDistance, (geometry, t) -> result.add(new GeoPoint(geometry, ray.getPoint(t))));
        return result.isEmpty() ? null : result;
    }

    /**
     * A tree inside a scene that is built into a tree in turn hands over its leaves, not itself:
     * the outer tree then indexes every primitive directly, with no second walk per ray that
     * reaches it (a walk nested in another would also take a stack of its own, see
     * {@link #closestHit(Hit)}).
     */
    @Override
    void collectLeaves(List<Intersectable> out) {
        for (Intersectable leaf : leaves) out.add(leaf);
    }

    @Override
    public BoundingBox getBoundingBox() {
        return unbounded.length > 0 ? null : rootBox;
    }

    /** The largest float not above {@code d} (−∞ below the float range): a box's lower bound rounded outward. */
    static float floatBelow(double d) {
        float f = (float) d;
        return f > d ? Math.nextDown(f) : f;
    }

    /** The smallest float not below {@code d} (+∞ above the float range): a box's upper bound rounded outward. */
    static float floatAbove(double d) {
        float f = (float) d;
        return f < d ? Math.nextUp(f) : f;
    }

    /**
     * The top-down binned-SAH builder. The primitives' bounds and centroids are kept in slot order
     * (the order the leaves will list them in) and moved with every partition, so that binning a
     * node reads one contiguous range instead of gathering through a permutation. Subtrees over
     * more than {@link #forkAbove} primitives are built as fork/join tasks.
     *
     * <p>Deterministic whatever the parallelism: a node's split depends only on the primitives of
     * its range, the partition is stable, and every subtree writes into node slots reserved for it
     * in advance (a subtree over n primitives has at most 2n − 1 nodes, so the right child of a
     * node whose left child covers nL primitives goes to slot {@code node + 2·nL}). A final
     * pass renumbers the slots depth-first, the layout the walks expect; it is parallel too, as
     * each subtree's place follows from the sizes. The primitives' own loops (asking their
     * bounds, in the constructor) run in chunks on the same pool.
     */
    private static final class Builder {
        // Per slot, in the scene's order (never moved): the leaf and the primitive's index in it.
        final Intersectable[] owners;
        final int[] prims;
        private final int total;
        /** The pool subtrees are built in, or null to build on the calling thread. */
        private final ForkJoinPool pool;
        private final int forkAbove;
        /** Whether nodes of two primitives are searched without bins (but in tests). */
        private final boolean pairs;
        // Per slot, in slot order: the primitive id, its padded bounds (6) and its centroid (3).
        // Once built, order lists the primitives in leaf order.
        private int[] order;
        private double[] bounds;
        private double[] centroid;
        // The stable partition's buffers for the right part, indexed by slot like the arrays above
        // so that concurrent subtrees never share a region.
        private int[] scratchOrder;
        private double[] scratchBounds;
        private double[] scratchCentroid;
        // Per reserved node slot: the box (6) already rounded outward to floats, the primitive count
        // (> 0 for a leaf) and for a leaf its first slot, for an inner node the primitive count of
        // its left child; the number of nodes of the subtree rooted there.
        private float[] slotBox;
        private int[] slotCount;
        private int[] slotFirstOrLeft;
        private int[] slotSize;

        float[] node;
        BoundingBox rootBox;
        int nodes;
        int maxDepth;

        Builder(int total, ForkJoinPool pool, int forkAbove, boolean pairs) {
            this.pairs = pairs;
            this.total = total;
            this.pool = pool;
            this.forkAbove = forkAbove;
            owners = new Intersectable[total];
            prims = new int[total];
            order = new int[total];
            bounds = new double[total * 6];
            centroid = new double[total * 3];
        }

        /**
         * Records primitive {@code index} of {@code leaf} in slot {@code i}; its bounds are
         * {@code box[at..at + 6)} (min xyz, max xyz), padded here as {@link BoundingBox#padded()} does.
         */
        void addPrimitive(int i, Intersectable leaf, int index, double[] box, int at) {
            owners[i] = leaf;
            prims[i] = index;
            order[i] = i;
            double minX = box[at], minY = box[at + 1], minZ = box[at + 2];
            double maxX = box[at + 3], maxY = box[at + 4], maxZ = box[at + 5];
            double eps = BoundingBox.padding(minX, minY, minZ, maxX, maxY, maxZ);
            int o = i * 6;
            bounds[o] = minX - eps;
            bounds[o + 1] = minY - eps;
            bounds[o + 2] = minZ - eps;
            bounds[o + 3] = maxX + eps;
            bounds[o + 4] = maxY + eps;
            bounds[o + 5] = maxZ + eps;
            centroid[i * 3] = (minX + maxX) / 2;
            centroid[i * 3 + 1] = (minY + maxY) / 2;
            centroid[i * 3 + 2] = (minZ + maxZ) / 2;
        }

        /** Sets the bounds at {@code at} of {@code out} to those of slots [from, to). */
        void unite(double[] out, int at, int from, int to) {
            resetBounds(out, at);
            for (int i = from; i < to; ++i) growBounds(out, at, bounds, centroid, i);
        }

        /** Sets {@code out} to the union of the bounds in {@code parts}, {@link #BOUNDS} doubles each. */
        void unite(double[] out, double[] parts) {
            resetBounds(out, 0);
            for (int at = 0; at < parts.length; at += BOUNDS) {
                for (int a = 0; a < 3; ++a) {
                    out[a] = Math.min(parts[at + a], out[a]);
                    out[3 + a] = Math.max(parts[at + 3 + a], out[3 + a]);
                    out[6 + a] = Math.min(parts[at + 6 + a], out[6 + a]);
                    out[9 + a] = Math.max(parts[at + 9 + a], out[9 + a]);
                }
            }
        }

        /** Builds the tree over all slots, whose bounds are {@code rootBounds} (as {@link #unite} gives them). */
        void build(double[] rootBounds) {
            int n = total;
            scratchOrder = new int[n];
            scratchBounds = new double[n * 6];
            scratchCentroid = new double[n * 3];
            int capacity = Math.max(1, 2 * n);
            slotBox = new float[capacity * 6];
            slotCount = new int[capacity];
            slotFirstOrLeft = new int[capacity];
            slotSize = new int[capacity];
            if (n > 0) {
                rootBox = new BoundingBox(rootBounds[0], rootBounds[1], rootBounds[2], rootBounds[3], rootBounds[4], rootBounds[5]);
                Subtree root = new Subtree(0, n, 0, 0, rootBounds);
                if (pool != null && n > forkAbove) pool.invoke(root);
                else root.compute();
                maxDepth = root.maxLevel;
            }
            // The build's buffers are garbage from here on: let them go before the node array is made.
            scratchOrder = null;
            scratchBounds = null;
            scratchCentroid = null;
            bounds = null;
            centroid = null;
            nodes = n == 0 ? 0 : slotSize[0];
            node = new float[BASE + nodes * NODE];
            if (n == 0) return;
            Flatten all = new Flatten(0, 0);
            if (pool != null && nodes > forkAbove) pool.invoke(all);
            else all.compute();
        }

        /**
         * Renumbers the reserved slots of the subtree at {@code slot} depth-first (left child
         * next) into the packed node records from {@code index} on; big subtrees fork their two
         * children (their places are known from the sizes), each writing only its own records.
         */
        private final class Flatten extends RecursiveAction {
            private static final long serialVersionUID = 1L;
            private final int slot;
            private final int index;

            Flatten(int slot, int index) {
                this.slot = slot;
                this.index = index;
            }

            @Override
            protected void compute() {
                if (pool == null || slotSize[slot] <= forkAbove || slotCount[slot] > 0) {
                    flatten(slot, index);
                    return;
                }
                int right = writeNode(slot, index);
                invokeAll(new Flatten(slot + 1, index + 1), new Flatten(right, index + 1 + slotSize[slot + 1]));
            }
        }

        /** Flattens the subtree at {@code root} into the records from {@code rootIndex} on, on this thread. */
        private void flatten(int root, int rootIndex) {
            int[] stack = new int[2 * (maxDepth + 2)];
            int top = 0;
            stack[top++] = root;
            stack[top++] = rootIndex;
            while (top > 0) {
                int f = stack[--top], s = stack[--top];
                int right = writeNode(s, f);
                if (right >= 0) {
                    stack[top++] = right;
                    stack[top++] = f + 1 + slotSize[s + 1];
                    stack[top++] = s + 1;
                    stack[top++] = f + 1;
                }
            }
        }

        /**
         * Writes slot {@code s} as node record {@code f}.
         *
         * @return for an inner node the slot of its right child (its left one is {@code s + 1}); −1 for a leaf
         */
        private int writeNode(int s, int f) {
            int o = BASE + f * NODE;
            System.arraycopy(slotBox, s * 6, node, o, 6);
            int count = slotCount[s];
            // Non-negative ints below 0x7F800000 are never NaN patterns, so the bits survive
            // the round trip through float unchanged.
            if (count > 0) {
                node[o + 6] = Float.intBitsToFloat(slotFirstOrLeft[s]);
                node[o + 7] = Float.intBitsToFloat(count);
                return -1;
            }
            node[o + 6] = Float.intBitsToFloat(f + 1 + slotSize[s + 1]);
            node[o + 7] = Float.intBitsToFloat(INNER | (f + slotSize[s]));
            return s + 2 * slotFirstOrLeft[s];
        }

        /** The subtree over slots [start, end), rooted at node slot {@code slot}. */
        private final class Subtree extends RecursiveAction {
            private static final long serialVersionUID = 1L;
            private final int start;
            private final int end;
            private final int level;
            private final int slot;
            /** The subtree's box and centroid bounds, as its parent's partition found them. */
            private final double[] own;
            /** The deepest level reached in this subtree, once computed. */
            int maxLevel;

            Subtree(int start, int end, int level, int slot, double[] own) {
                this.start = start;
                this.end = end;
                this.level = level;
                this.slot = slot;
                this.own = own;
            }

            @Override
            protected void compute() {
                Binner binner = new Binner();
                int ownAt = binner.place(level, 0);
                System.arraycopy(own, 0, binner.levels, ownAt, BOUNDS);
                if (end - start <= forkAbove || pool == null) {
                    maxLevel = buildNode(binner, start, end, level, slot, ownAt);
                    return;
                }
                int mid = split(binner, start, end, level, slot, ownAt);
                if (mid < 0) {
                    maxLevel = level;
                    return;
                }
                int at = binner.place(level + 1, 0);
                double[] lb = java.util.Arrays.copyOfRange(binner.levels, at, at + BOUNDS);
                double[] rb = java.util.Arrays.copyOfRange(binner.levels, at + BOUNDS, at + 2 * BOUNDS);
                Subtree left = new Subtree(start, mid, level + 1, slot + 1, lb);
                Subtree right = new Subtree(mid, end, level + 1, slot + 2 * (mid - start), rb);
                invokeAll(left, right);
                slotSize[slot] = 1 + slotSize[left.slot] + slotSize[right.slot];
                maxLevel = Math.max(left.maxLevel, right.maxLevel);
            }
        }

        /**
         * Builds the subtree over slots [start, end) at node slot {@code slot}, sequentially.
         *
         * @return the deepest level reached
         */
        private int buildNode(Binner binner, int start, int end, int level, int slot, int ownAt) {
            int mid = split(binner, start, end, level, slot, ownAt);
            if (mid < 0) return level;
            int right = slot + 2 * (mid - start);
            // The children's bounds sit at level + 1; the left subtree writes only deeper levels,
            // so the right child's are intact when its turn comes.
            int leftDeepest = buildNode(binner, start, mid, level + 1, slot + 1, binner.place(level + 1, 0));
            int deepest = Math.max(leftDeepest, buildNode(binner, mid, end, level + 1, right, binner.place(level + 1, 1)));
            slotSize[slot] = 1 + slotSize[slot + 1] + slotSize[right];
            return deepest;
        }

        /**
         * Writes node {@code slot}'s box and decides it: a leaf (recorded here, size 1; returns −1)
         * or a split, whose partition of [start, end) it performs and whose middle it returns; the
         * partition then leaves the two children's bounds at {@code binner.place(level + 1, 0|1)}.
         *
         * @param ownAt where in {@code binner.levels} this node's box and centroid bounds are
         */
        private int split(Binner binner, int start, int end, int level, int slot, int ownAt) {
            double[] own = binner.levels;
            double bx0 = own[ownAt], by0 = own[ownAt + 1], bz0 = own[ownAt + 2];
            double bx1 = own[ownAt + 3], by1 = own[ownAt + 4], bz1 = own[ownAt + 5];
            double cx0 = own[ownAt + 6], cy0 = own[ownAt + 7], cz0 = own[ownAt + 8];
            double cx1 = own[ownAt + 9], cy1 = own[ownAt + 10], cz1 = own[ownAt + 11];
            double[] bounds = this.bounds, centroid = this.centroid;
            int o = slot * 6;
            slotBox[o] = Bvh.floatBelow(bx0);
            slotBox[o + 1] = Bvh.floatBelow(by0);
            slotBox[o + 2] = Bvh.floatBelow(bz0);
            slotBox[o + 3] = Bvh.floatAbove(bx1);
            slotBox[o + 4] = Bvh.floatAbove(by1);
            slotBox[o + 5] = Bvh.floatAbove(bz1);
            int n = end - start;
            // Binned SAH over every axis whose centroids spread; for very large nodes only along
            // the widest one (as pbrt does), a third of the work for trees of nearly the same
            // quality where it matters for build time. Small and medium nodes get the full search:
            // it makes measurably better trees (fewer box tests per ray).
            double[] extentOf = binner.extentOf, lowOf = binner.lowOf;
            extentOf[0] = cx1 - cx0;
            extentOf[1] = cy1 - cy0;
            extentOf[2] = cz1 - cz0;
            lowOf[0] = cx0;
            lowOf[1] = cy0;
            lowOf[2] = cz0;
            int widest = extentOf[0] >= extentOf[1] && extentOf[0] >= extentOf[2] ? 0 : extentOf[1] >= extentOf[2] ? 1 : 2;
            double parentArea = (bx1 - bx0) * (by1 - by0) + (by1 - by0) * (bz1 - bz0) + (bz1 - bz0) * (bx1 - bx0);
            boolean[] searched = binner.searched;
            for (int a = 0; a < 3; ++a)
                searched[a] = n > 1 && extentOf[a] > 0 && (n <= FULL_SEARCH_LIMIT || a == widest);
            // Both searches find the same split (see Binner.searchPair), the direct one without
            // binning, for the commonest node of all.
            if (n == 2 && pairs) binner.searchPair(bounds, centroid, start, lowOf, extentOf, parentArea);
            else binner.searchBinned(bounds, centroid, start, end, lowOf, extentOf, parentArea);
            double bestCost = binner.bestCost;
            int bestBin = binner.bestBin, bestAxis = binner.bestAxis;
            int mid = -1;
            if (bestBin >= 0 && (bestCost < n || n > MAX_LEAF))
                mid = partition(start, end, bestAxis, lowOf[bestAxis], BINS / extentOf[bestAxis], bestBin,
                        binner.levels(level + 1), binner.place(level + 1, 0));
            // All centroids coincide: split the range in half to bound the leaf size.
            if (mid < 0 && n > MAX_LEAF) {
                mid = start + n / 2;
                double[] children = binner.levels(level + 1);
                int at = binner.place(level + 1, 0);
                resetBounds(children, at);
                resetBounds(children, at + BOUNDS);
                for (int i = start; i < end; ++i) growBounds(children, i < mid ? at : at + BOUNDS, bounds, centroid, i);
            }
            if (mid < 0) {
                slotCount[slot] = n;
                slotFirstOrLeft[slot] = start;
                slotSize[slot] = 1;
            } else {
                slotCount[slot] = 0;
                slotFirstOrLeft[slot] = mid - start;
            }
            return mid;
        }

        /**
         * Stable partition of slots [start, end): the primitives whose centroid falls in a bin
         * up to {@code lastLeftBin} along {@code axis} first, each moved with its bounds and
         * centroid. The right part goes through the scratch buffers' slots [start, end). The same
         * pass gathers both parts' box and centroid bounds into {@code children} at the next
         * level's places, so that no child reads its range again for them.
         *
         * @return the first slot of the right part
         */
        private int partition(int start, int end, int axis, double lo, double scale, int lastLeftBin,
                              double[] children, int at) {
            double[] bounds = this.bounds, centroid = this.centroid, sBounds = scratchBounds, sCentroid = scratchCentroid;
            // The two parts' bounds are grown in locals, not in an array: in memory, each
            // primitive's twelve updates waited for the previous primitive's stores.
            double lx0 = Double.POSITIVE_INFINITY, ly0 = lx0, lz0 = lx0, lcx0 = lx0, lcy0 = lx0, lcz0 = lx0;
            double lx1 = Double.NEGATIVE_INFINITY, ly1 = lx1, lz1 = lx1, lcx1 = lx1, lcy1 = lx1, lcz1 = lx1;
            double rx0 = lx0, ry0 = lx0, rz0 = lx0, rcx0 = lx0, rcy0 = lx0, rcz0 = lx0;
            double rx1 = lx1, ry1 = lx1, rz1 = lx1, rcx1 = lx1, rcy1 = lx1, rcz1 = lx1;
            int l = start, r = start;
            for (int i = start; i < end; ++i) {
                int o = i * 6, c = i * 3;
                double b0 = bounds[o], b1 = bounds[o + 1], b2 = bounds[o + 2];
                double b3 = bounds[o + 3], b4 = bounds[o + 4], b5 = bounds[o + 5];
                double c0 = centroid[c], c1 = centroid[c + 1], c2 = centroid[c + 2];
                if (bin(centroid[c + axis], lo, scale) <= lastLeftBin) {
                    lx0 = Math.min(b0, lx0); ly0 = Math.min(b1, ly0); lz0 = Math.min(b2, lz0);
                    lx1 = Math.max(b3, lx1); ly1 = Math.max(b4, ly1); lz1 = Math.max(b5, lz1);
                    lcx0 = Math.min(c0, lcx0); lcy0 = Math.min(c1, lcy0); lcz0 = Math.min(c2, lcz0);
                    lcx1 = Math.max(c0, lcx1); lcy1 = Math.max(c1, lcy1); lcz1 = Math.max(c2, lcz1);
                    if (l != i) {
                        int lo6 = l * 6, lc = l * 3;
                        order[l] = order[i];
                        bounds[lo6] = b0; bounds[lo6 + 1] = b1; bounds[lo6 + 2] = b2;
                        bounds[lo6 + 3] = b3; bounds[lo6 + 4] = b4; bounds[lo6 + 5] = b5;
                        centroid[lc] = c0; centroid[lc + 1] = c1; centroid[lc + 2] = c2;
                    }
                    ++l;
                } else {
                    rx0 = Math.min(b0, rx0); ry0 = Math.min(b1, ry0); rz0 = Math.min(b2, rz0);
                    rx1 = Math.max(b3, rx1); ry1 = Math.max(b4, ry1); rz1 = Math.max(b5, rz1);
                    rcx0 = Math.min(c0, rcx0); rcy0 = Math.min(c1, rcy0); rcz0 = Math.min(c2, rcz0);
                    rcx1 = Math.max(c0, rcx1); rcy1 = Math.max(c1, rcy1); rcz1 = Math.max(c2, rcz1);
                    int ro = r * 6, rc = r * 3;
                    scratchOrder[r++] = order[i];
                    sBounds[ro] = b0; sBounds[ro + 1] = b1; sBounds[ro + 2] = b2;
                    sBounds[ro + 3] = b3; sBounds[ro + 4] = b4; sBounds[ro + 5] = b5;
                    sCentroid[rc] = c0; sCentroid[rc + 1] = c1; sCentroid[rc + 2] = c2;
                }
            }
            setBounds(children, at, lx0, ly0, lz0, lx1, ly1, lz1, lcx0, lcy0, lcz0, lcx1, lcy1, lcz1);
            setBounds(children, at + BOUNDS, rx0, ry0, rz0, rx1, ry1, rz1, rcx0, rcy0, rcz0, rcx1, rcy1, rcz1);
            int right = r - start;
            System.arraycopy(scratchOrder, start, order, l, right);
            System.arraycopy(scratchBounds, start * 6, bounds, l * 6, right * 6);
            System.arraycopy(scratchCentroid, start * 3, centroid, l * 3, right * 3);
            return l;
        }

        /** Writes a box (min xyz, max xyz) and a centroid box as the bounds at {@code at}. */
        private static void setBounds(double[] b, int at, double x0, double y0, double z0, double x1, double y1, double z1,
                                      double cx0, double cy0, double cz0, double cx1, double cy1, double cz1) {
            b[at] = x0;
            b[at + 1] = y0;
            b[at + 2] = z0;
            b[at + 3] = x1;
            b[at + 4] = y1;
            b[at + 5] = z1;
            b[at + 6] = cx0;
            b[at + 7] = cy0;
            b[at + 8] = cz0;
            b[at + 9] = cx1;
            b[at + 10] = cy1;
            b[at + 11] = cz1;
        }

        /** Makes the bounds at {@code at} empty: a box and a centroid box that any point grows. */
        private static void resetBounds(double[] b, int at) {
            for (int a = 0; a < 3; ++a) {
                b[at + a] = b[at + 6 + a] = Double.POSITIVE_INFINITY;
                b[at + 3 + a] = b[at + 9 + a] = Double.NEGATIVE_INFINITY;
            }
        }

        /** Grows the bounds at {@code at} by slot {@code i}'s box and centroid. */
        private static void growBounds(double[] b, int at, double[] bounds, double[] centroid, int i) {
            int o = i * 6, c = i * 3;
            for (int a = 0; a < 3; ++a) {
                b[at + a] = Math.min(bounds[o + a], b[at + a]);
                b[at + 3 + a] = Math.max(bounds[o + 3 + a], b[at + 3 + a]);
                b[at + 6 + a] = Math.min(centroid[c + a], b[at + 6 + a]);
                b[at + 9 + a] = Math.max(centroid[c + a], b[at + 9 + a]);
            }
        }

        /** One task's bins: per searched axis, BINS counts and boxes, filled in one pass over a range. */
        private static final class Binner {
            final boolean[] searched = new boolean[3];
            /** The node being split: per axis, its centroids' lowest value and their extent. */
            final double[] lowOf = new double[3];
            final double[] extentOf = new double[3];
            final int[] binCount = new int[3 * BINS];
            final double[] binBox = new double[3 * BINS * 6];
            final double[] rightArea = new double[BINS];
            /** Per axis, the bins {@link #bin} filled, as bits; the search empties them again. */
            final int[] occupied = new int[3];
            /** The cheapest split a search found: its cost, last left bin (−1 for none) and axis. */
            double bestCost;
            int bestBin;
            int bestAxis;
            /**
             * Per level of this task's recursion, the box and centroid bounds of the two children
             * split there ({@link #BOUNDS} doubles each, left then right); grown on demand.
             */
            double[] levels = new double[16 * 2 * BOUNDS];

            /**
             * The binned SAH over the searched axes of slots [start, end): fills the bins in one pass,
             * sweeps each axis from both ends, and leaves the cheapest split in {@link #bestCost},
             * {@link #bestBin} (the last bin of the left part) and {@link #bestAxis}.
             */
            void searchBinned(double[] bounds, double[] centroid, int start, int end, double[] lowOf, double[] extentOf,
                              double parentArea) {
                bin(bounds, centroid, start, end, lowOf, extentOf);
                int n = end - start;
                bestCost = Double.POSITIVE_INFINITY;
                bestBin = -1;
                bestAxis = -1;
                for (int a = 0; a < 3; ++a) {
                    if (!searched[a]) continue;
                    int base = a * BINS, mask = occupied[a];
                    occupied[a] = 0;
                    // Sweep the occupied bins from the right for the areas of every right part, then
                    // from the left. An empty bin changes neither part's box nor count: the areas and
                    // costs are the numbers a sweep over every bin computes, and an empty bin's split
                    // costs exactly what its left neighbour's does, which cannot beat it. (Small nodes,
                    // most of a tree, occupy few bins.) The unions are grown in locals.
                    double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0;
                    double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
                    for (int m = mask; m != 0; ) {
                        int k = 31 - Integer.numberOfLeadingZeros(m);
                        m ^= 1 << k;
                        int o = (base + k) * 6;
                        x0 = Math.min(binBox[o], x0);
                        y0 = Math.min(binBox[o + 1], y0);
                        z0 = Math.min(binBox[o + 2], z0);
                        x1 = Math.max(binBox[o + 3], x1);
                        y1 = Math.max(binBox[o + 4], y1);
                        z1 = Math.max(binBox[o + 5], z1);
                        rightArea[k] = halfArea(x1 - x0, y1 - y0, z1 - z0); // of bins k and above
                    }
                    x0 = y0 = z0 = Double.POSITIVE_INFINITY;
                    x1 = y1 = z1 = Double.NEGATIVE_INFINITY;
                    int leftCount = 0;
                    for (int m = mask; ; ) {
                        int k = Integer.numberOfTrailingZeros(m);
                        m &= m - 1;
                        if (m == 0) break; // the last occupied bin leaves no right part
                        int o = (base + k) * 6;
                        x0 = Math.min(binBox[o], x0);
                        y0 = Math.min(binBox[o + 1], y0);
                        z0 = Math.min(binBox[o + 2], z0);
                        x1 = Math.max(binBox[o + 3], x1);
                        y1 = Math.max(binBox[o + 4], y1);
                        z1 = Math.max(binBox[o + 5], z1);
                        leftCount += binCount[base + k];
                        consider(sahCost(halfArea(x1 - x0, y1 - y0, z1 - z0), leftCount,
                                rightArea[Integer.numberOfTrailingZeros(m)], n - leftCount, parentArea), k, a);
                    }
                    for (int m = mask; m != 0; m &= m - 1) {
                        int k = base + Integer.numberOfTrailingZeros(m);
                        binCount[k] = 0;
                        resetBox(binBox, k);
                    }
                }
            }

            /**
             * {@link #searchBinned} for the two primitives at {@code start}, without bins: every axis
             * on which their bins differ offers the same split, one primitive on each side, at the
             * same cost (a sum of two terms in either order is the same double), so the first such
             * axis is the one chosen, as the binned search (which replaces its best only by a
             * strictly cheaper split) chooses it.
             */
            void searchPair(double[] bounds, double[] centroid, int start, double[] lowOf, double[] extentOf,
                            double parentArea) {
                bestCost = Double.POSITIVE_INFINITY;
                bestBin = -1;
                bestAxis = -1;
                for (int a = 0; a < 3; ++a) {
                    if (!searched[a]) continue;
                    double scale = BINS / extentOf[a];
                    int k0 = Bvh.Builder.bin(centroid[start * 3 + a], lowOf[a], scale);
                    int k1 = Bvh.Builder.bin(centroid[(start + 1) * 3 + a], lowOf[a], scale);
                    if (k0 == k1) continue;
                    int lower = k0 < k1 ? start : start + 1;
                    consider(sahCost(halfArea(bounds, lower), 1, halfArea(bounds, 2 * start + 1 - lower), 1, parentArea),
                            Math.min(k0, k1), a);
                    return;
                }
            }

            private void consider(double cost, int bin, int axis) {
                if (cost < bestCost) {
                    bestCost = cost;
                    bestBin = bin;
                    bestAxis = axis;
                }
            }

            /** @return where the bounds of the {@code side} (0 left, 1 right) child at {@code level} are */
            int place(int level, int side) {
                int at = (2 * level + side) * BOUNDS;
                if (at + BOUNDS > levels.length) levels = java.util.Arrays.copyOf(levels, Math.max(2 * levels.length, at + 2 * BOUNDS));
                return at;
            }

            /** @return {@link #levels}, with room for both children at {@code level} */
            double[] levels(int level) {
                place(level, 1);
                return levels;
            }

            Binner() {
                for (int k = 0; k < 3 * BINS; ++k) resetBox(binBox, k);
            }

            /**
             * Fills the searched axes' bins, which are empty, from slots [start, end), in one pass
             * over the range (each slot's bounds are read once for all axes).
             */
            void bin(double[] bounds, double[] centroid, int start, int end, double[] lowOf, double[] extentOf) {
                boolean sx = searched[0], sy = searched[1], sz = searched[2];
                double lx = lowOf[0], ly = lowOf[1], lz = lowOf[2];
                double kx = BINS / extentOf[0], ky = BINS / extentOf[1], kz = BINS / extentOf[2];
                int mx = 0, my = 0, mz = 0;
                for (int i = start; i < end; ++i) {
                    int c = i * 3;
                    if (sx) mx |= add(Bvh.Builder.bin(centroid[c], lx, kx), 0, bounds, i);
                    if (sy) my |= add(Bvh.Builder.bin(centroid[c + 1], ly, ky), BINS, bounds, i);
                    if (sz) mz |= add(Bvh.Builder.bin(centroid[c + 2], lz, kz), 2 * BINS, bounds, i);
                }
                occupied[0] = mx;
                occupied[1] = my;
                occupied[2] = mz;
            }

            /** Adds slot {@code i} to bin {@code k} of the axis whose bins start at {@code base}; @return k's bit */
            private int add(int k, int base, double[] bounds, int i) {
                binCount[base + k]++;
                growBox(binBox, base + k, bounds, i);
                return 1 << k;
            }

        }

        private static int bin(double c, double lo, double scale) {
            int k = (int) ((c - lo) * scale);
            return k < 0 ? 0 : Math.min(k, BINS - 1);
        }

        private static void resetBox(double[] b, int k) {
            int o = k * 6;
            b[o] = b[o + 1] = b[o + 2] = Double.POSITIVE_INFINITY;
            b[o + 3] = b[o + 4] = b[o + 5] = Double.NEGATIVE_INFINITY;
        }

        // Math.min/max rather than compare-and-branch: whether a bound grows is data-dependent
        // and mispredicts often; the intrinsics do not branch (25 % off a 2×10⁶ build). They differ
        // from the branches only for NaN (no bound is NaN) and by preferring −0.0 to +0.0.
        private static void growBox(double[] b, int k, double[] src, int s) {
            int o = k * 6, so = s * 6;
            for (int a = 0; a < 3; ++a) {
                b[o + a] = Math.min(src[so + a], b[o + a]);
                b[o + a + 3] = Math.max(src[so + a + 3], b[o + a + 3]);
            }
        }

        /** The SAH cost of a split, relative to testing the parent's primitives: the one formula of both searches. */
        private static double sahCost(double leftArea, int leftCount, double rightArea, int rightCount, double parentArea) {
            return TRAVERSAL_COST + (leftArea * leftCount + rightArea * rightCount) / parentArea;
        }

        private static double halfArea(double[] b, int k) {
            int o = k * 6;
            return halfArea(b[o + 3] - b[o], b[o + 4] - b[o + 1], b[o + 5] - b[o + 2]);
        }

        /** The half area of a box of extents dx, dy, dz: the one formula of every SAH cost. */
        private static double halfArea(double dx, double dy, double dz) {
            return dx * dy + dy * dz + dz * dx;
        }
    }
}
