package geometries;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveAction;

/**
 * The top-down binned-SAH builder. The primitives' bounds and centroids are kept in slot order
 * (the order the leaves will list them in) and moved with every partition, so that binning a
 * node reads one contiguous range instead of gathering through a permutation. Subtrees over
 * more than {@code forkAbove} primitives are built as fork/join tasks.
 *
 * <p>Deterministic whatever the parallelism: a node's split depends only on the primitives of
 * its range, the partition is stable, and every subtree writes into node slots reserved for it
 * in advance (a subtree over n primitives has at most 2n − 1 nodes, so the right child of a
 * node whose left child covers nL primitives goes to slot {@code node + 2·nL}). A final
 * pass renumbers the slots depth-first, the layout the walks expect; it is parallel too, as
 * each subtree's place follows from the sizes. The primitives' own loops (asking their
 * bounds, in {@link #index}) run in chunks on the same pool.
 */
final class BvhBuilder {
    /**
     * The most primitives a leaf holds: a larger node is always split; one this small is split
     * only when the SAH finds a split cheaper than testing its primitives.
     */
    private static final int MAX_LEAF = 4;
    /** Nodes with more primitives than this are binned along their widest axis only. */
    private static final int FULL_SEARCH_LIMIT = 1 << 16;
    /** Doubles per range's bounds (its box and its centroids' box, as {@link BuildBoxes} names them). */
    private static final int BOUNDS = BuildBoxes.BOUNDS;
    private static final int BOX = BuildBoxes.BOX, CENTROIDS = BuildBoxes.CENTROIDS;
    private static final int LOW = BuildBoxes.LOW, HIGH = BuildBoxes.HIGH, BOX_SIZE = BuildBoxes.BOX_SIZE;
    /**
     * Leaves or primitives per chunk in the build's flat loops ({@link Ranges}): about 60 µs of work,
     * small enough that a build of 10<sup>6</sup> calls each loop's body about a thousand times,
     * which the JIT compiles whole within the first build.
     */
    private static final int GRAIN = 1 << 10;

    // Per slot, in the scene's order (never moved): the leaf and the primitive's index in it.
    private final Intersectable[] slotOwner;
    private final int[] slotPrim;
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

    // The product, read by the tree's constructor.
    /** The leaves without a box, tested beside the tree. */
    Intersectable[] unbounded;
    /** Per primitive, in leaf order: its owner and its index within the owner. */
    Intersectable[] owner;
    int[] prim;
    /** Per primitive, in leaf order: its packed kind (BvhLeaf.OWN, SPHERE or TRIANGLE) and its PACKED doubles. */
    byte[] kind;
    double[] packed;
    /** The node records, laid out as {@link BvhNodes} says. */
    float[] node;
    /** The exact (double) box of the root, or null when nothing is bounded. */
    BoundingBox rootBox;
    int nodes;
    int maxDepth;

    private BvhBuilder(int total, ForkJoinPool pool, int forkAbove, boolean pairs) {
        this.pairs = pairs;
        this.total = total;
        this.pool = pool;
        this.forkAbove = forkAbove;
        slotOwner = new Intersectable[total];
        slotPrim = new int[total];
        order = new int[total];
        bounds = new double[total * 6];
        centroid = new double[total * 3];
    }

    /**
     * Indexes {@code all}, a scene's leaves: asks each leaf its box once, gives each bounded
     * primitive a slot (in the scene's order), builds the tree over the slots, then lists the
     * primitives in leaf order and packs the library's spheres and triangles. The product is in
     * the builder's fields {@link #unbounded} … {@link #maxDepth}.
     *
     * @param parallelism the threads the build may use; 1 builds on the calling thread
     * @param forkAbove   subtrees over more primitives than this are built as parallel tasks (≥ 1)
     * @param pairs       whether nodes of two primitives are searched without bins
     */
    static BvhBuilder index(Intersectable[] all, int parallelism, int forkAbove, boolean pairs) {
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
                    if (all[l].packedKind() != BvhLeaf.OWN) packs[0] = true;
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

            int total = first[count];
            requireMemory(total, count, Runtime.getRuntime().maxMemory(), live(bytesNeeded(total, count)));
            try {
                return index(all, count, total, first, leafBox, packs, free, pool, grain, forkAbove, pairs);
            } catch (OutOfMemoryError e) {
                // The estimate is a floor (the rest of the program may grow meanwhile): a build that
                // runs out all the same says so in the same words, with what was live at the failure.
                Runtime runtime = Runtime.getRuntime();
                OutOfMemoryError named = new OutOfMemoryError(memoryMessage(total, bytesNeeded(total, count),
                        runtime.maxMemory(), runtime.totalMemory() - runtime.freeMemory()));
                named.initCause(e);
                throw named;
            }
        } finally {
            if (pool != null) pool.shutdown();
        }
    }

    /** The build proper, once the leaves are boxed and counted (see {@link #index(Intersectable[], int, int, boolean)}). */
    private static BvhBuilder index(Intersectable[] all, int count, int total, int[] first, double[] leafBox,
                                    boolean[] packs, List<Intersectable> free, ForkJoinPool pool, int grain,
                                    int forkAbove, boolean pairs) {
        BvhBuilder b = new BvhBuilder(total, pool, forkAbove, pairs);
        b.unbounded = free.toArray(new Intersectable[0]);
        // By slot rather than by leaf, so that the triangles of one big mesh are shared out too.
        // Each chunk also leaves the bounds of its slots (BOUNDS doubles) in chunkBounds; their
        // union is the root's, found without a pass of its own. All start empty: without a
        // pool one chunk runs the whole range, and the others' places must not count.
        double[] chunkBounds = new double[(Math.max(total, 1) + grain - 1) / grain * BOUNDS];
        for (int at = 0; at < chunkBounds.length; at += BOUNDS) BuildBoxes.emptyBounds(chunkBounds, at);
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
        unite(rootBounds, chunkBounds);
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
                ordered[k] = b.slotOwner[s];
                orderedPrim[k] = b.slotPrim[s];
                if (leafAt.length > 0) leafAt[s] = k;
            }
        });
        b.owner = ordered;
        b.prim = orderedPrim;
        byte[] kind = new byte[total];
        // A few doubles more than the records: a tree with wide nodes loads its lane leaves four
        // doubles at a time, and the last leaf's last load reaches past the records (TriangleLanes).
        double[] packed = new double[packs[0] ? total * BvhLeaf.PACKED + TriangleLanes.PADDING : 0];
        if (packs[0]) {
            // In slot order, that is the scene's order, in which its objects were most likely
            // made: the objects are read one after the other, the packed records written at
            // their leaf places. (Packing as the leaves are made read them at random: 0.5 s
            // more for a one-thread build of 2×10⁶.)
            Ranges.run(pool, total, grain, (from, to) -> {
                for (int s = from; s < to; ++s) {
                    Intersectable leaf = b.slotOwner[s];
                    byte k = leaf.packedKind();
                    if (k == BvhLeaf.OWN) continue;
                    kind[leafAt[s]] = k;
                    leaf.pack(b.slotPrim[s], packed, leafAt[s] * BvhLeaf.PACKED);
                }
            });
        }
        b.kind = kind;
        b.packed = packed;
        return b;
    }

    /**
     * Bytes the build holds at its peak per bounded primitive: the slot arrays (owner, index, order:
     * 12; bounds and centroid: 72), the partition's scratch (76) and the node slots (two per
     * primitive of 6 floats and 3 ints: 72). The tree itself is smaller than those and is made once
     * the scratch is let go.
     */
    static final long BYTES_PER_PRIMITIVE = 232;
    /** Bytes per leaf (a shape, or a whole mesh) of the first pass: its box (48), flags and offsets. */
    static final long BYTES_PER_LEAF = 57;

    /** @return the bytes a build over {@code primitives} primitives of {@code leaves} shapes holds at its peak */
    static long bytesNeeded(long primitives, long leaves) {
        return primitives * BYTES_PER_PRIMITIVE + leaves * BYTES_PER_LEAF;
    }

    /**
     * Refuses, before any of its arrays is made, a build that cannot fit: one that needs more than
     * the heap's limit minus what the rest of the program holds (a build of 4.5 million
     * triangles with too small a heap otherwise ran for a minute before it failed without a word
     * of what it was doing).
     *
     * @param primitives the bounded primitives to index
     * @param leaves     the shapes they belong to
     * @param max        the heap's limit ({@link Runtime#maxMemory()}; {@link Long#MAX_VALUE}: none)
     * @param live       bytes the rest of the program holds
     * @throws OutOfMemoryError naming the primitives, the memory needed, the limit, what was free and the remedies
     */
    static void requireMemory(long primitives, long leaves, long max, long live) {
        long needed = bytesNeeded(primitives, leaves);
        if (max != Long.MAX_VALUE && needed > max - live)
            throw new OutOfMemoryError(memoryMessage(primitives, needed, max, live));
    }

    /** The one line of a build that does not fit: what, how much, the limit, what was free, and the remedies. */
    static String memoryMessage(long primitives, long needed, long max, long live) {
        long mb = 1 << 20;
        return "the BVH over " + primitives + " primitives needs about " + (needed + mb - 1) / mb + " MB; Java may use at"
                + " most " + max / mb + " MB here, of which about " + Math.max(0, max - live) / mb + " MB were free"
                + " (give Java more memory with -Xmx, on a Spark executor --executor-memory; or render without the"
                + " BVH: setBvh(false), <render bvh=\"false\">)";
    }

    /**
     * The bytes the rest of the program holds, as far as a build of {@code needed} bytes must
     * know: what is in use now, and when that leaves too little, what is in use after one full
     * collection (garbage of the scene's loading, an earlier tree, counts as in use until then; a
     * collection costs a fraction of a second, against a build that would fail after a minute).
     */
    private static long live(long needed) {
        Runtime runtime = Runtime.getRuntime();
        long used = runtime.totalMemory() - runtime.freeMemory();
        if (runtime.maxMemory() == Long.MAX_VALUE || needed <= runtime.maxMemory() - used) return used;
        System.gc(); // the one place the library asks for a collection: before refusing a build for lack of memory
        return runtime.totalMemory() - runtime.freeMemory();
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
     * Records primitive {@code index} of {@code leaf} in slot {@code i}; its bounds are
     * {@code box[at..at + 6)} (min xyz, max xyz), padded here as {@link BoundingBox#padded()} does.
     */
    private void addPrimitive(int i, Intersectable leaf, int index, double[] box, int at) {
        slotOwner[i] = leaf;
        slotPrim[i] = index;
        order[i] = i;
        double minX = box[at], minY = box[at + 1], minZ = box[at + 2];
        double maxX = box[at + 3], maxY = box[at + 4], maxZ = box[at + 5];
        double eps = BoundingBox.padding(minX, minY, minZ, maxX, maxY, maxZ);
        BuildBoxes.set(bounds, i * BOX_SIZE, minX - eps, minY - eps, minZ - eps, maxX + eps, maxY + eps, maxZ + eps);
        centroid[i * 3] = (minX + maxX) / 2;
        centroid[i * 3 + 1] = (minY + maxY) / 2;
        centroid[i * 3 + 2] = (minZ + maxZ) / 2;
    }

    /**
     * Sets the bounds at {@code at} of {@code out} to those of slots [from, to), grown in locals:
     * in the array, each slot's twelve updates waited for the previous slot's stores.
     */
    private void unite(double[] out, int at, int from, int to) {
        double[] bounds = this.bounds, centroid = this.centroid;
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, cx0 = x0, cy0 = x0, cz0 = x0;
        double x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1, cx1 = x1, cy1 = x1, cz1 = x1;
        for (int i = from; i < to; ++i) {
            int o = i * BOX_SIZE, c = i * 3;
            x0 = Math.min(bounds[o], x0);
            y0 = Math.min(bounds[o + 1], y0);
            z0 = Math.min(bounds[o + 2], z0);
            x1 = Math.max(bounds[o + 3], x1);
            y1 = Math.max(bounds[o + 4], y1);
            z1 = Math.max(bounds[o + 5], z1);
            cx0 = Math.min(centroid[c], cx0);
            cy0 = Math.min(centroid[c + 1], cy0);
            cz0 = Math.min(centroid[c + 2], cz0);
            cx1 = Math.max(centroid[c], cx1);
            cy1 = Math.max(centroid[c + 1], cy1);
            cz1 = Math.max(centroid[c + 2], cz1);
        }
        BuildBoxes.set(out, at + BOX, x0, y0, z0, x1, y1, z1);
        BuildBoxes.set(out, at + CENTROIDS, cx0, cy0, cz0, cx1, cy1, cz1);
    }

    /** Sets {@code out} to the union of the bounds in {@code parts}, {@link #BOUNDS} doubles each. */
    private static void unite(double[] out, double[] parts) {
        BuildBoxes.emptyBounds(out, 0);
        for (int at = 0; at < parts.length; at += BOUNDS) BuildBoxes.growBounds(out, 0, parts, at);
    }

    /** Builds the tree over all slots, whose bounds are {@code rootBounds} (as {@link #unite} gives them). */
    private void build(double[] rootBounds) {
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
            int low = BOX + LOW, high = BOX + HIGH;
            rootBox = new BoundingBox(rootBounds[low], rootBounds[low + 1], rootBounds[low + 2],
                    rootBounds[high], rootBounds[high + 1], rootBounds[high + 2]);
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
        node = BvhNodes.allocate(nodes);
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

        /**
         * Subtrees of more than {@link #GRAIN} nodes are split, on one thread too: a build of
         * 10<sup>6</sup> primitives then calls {@link #flatten(int, int)} about two thousand
         * times, which the JIT compiles whole in the first build. Called once, it got an
         * on-stack-replacement compile that trapped at its loop's end, and the next build in the
         * JVM ran its loop interpreted until it was compiled again.
         */
        @Override
        protected void compute() {
            if (slotCount[slot] > 0 || slotSize[slot] <= GRAIN) {
                flatten(slot, index);
                return;
            }
            int right = writeNode(slot, index);
            Flatten left = new Flatten(slot + 1, index + 1), rest = new Flatten(right, index + 1 + slotSize[slot + 1]);
            if (pool != null && slotSize[slot] > forkAbove) {
                invokeAll(left, rest);
            } else {
                left.compute();
                rest.compute();
            }
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
        int at = BvhNodes.at(f);
        BvhNodes.writeBox(node, at, slotBox, s * 6);
        int count = slotCount[s];
        if (count > 0) {
            BvhNodes.writeLeaf(node, at, slotFirstOrLeft[s], count);
            return -1;
        }
        // The right child follows the left child's subtree; the skip link, the whole subtree.
        BvhNodes.writeInner(node, at, f + 1 + slotSize[s + 1], f + slotSize[s]);
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
            BvhBinner binner = new BvhBinner();
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
    private int buildNode(BvhBinner binner, int start, int end, int level, int slot, int ownAt) {
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
    private int split(BvhBinner binner, int start, int end, int level, int slot, int ownAt) {
        double[] own = binner.levels;
        int box = ownAt + BOX, centroids = ownAt + CENTROIDS;
        double[] bounds = this.bounds, centroid = this.centroid;
        int o = slot * BOX_SIZE;
        for (int a = 0; a < 3; ++a) {
            slotBox[o + LOW + a] = BvhNodes.floatBelow(own[box + LOW + a]);
            slotBox[o + HIGH + a] = BvhNodes.floatAbove(own[box + HIGH + a]);
        }
        int n = end - start;
        // Binned SAH over every axis whose centroids spread; for very large nodes only along
        // the widest one (as pbrt does), a third of the work for trees of nearly the same
        // quality where it matters for build time. Small and medium nodes get the full search:
        // it makes measurably better trees (fewer box tests per ray).
        double[] extentOf = binner.extentOf, lowOf = binner.lowOf;
        for (int a = 0; a < 3; ++a) {
            extentOf[a] = BuildBoxes.extent(own, centroids, a);
            lowOf[a] = own[centroids + LOW + a];
        }
        int widest = extentOf[0] >= extentOf[1] && extentOf[0] >= extentOf[2] ? 0 : extentOf[1] >= extentOf[2] ? 1 : 2;
        double parentArea = BuildBoxes.halfArea(own, box);
        boolean[] searched = binner.searched;
        for (int a = 0; a < 3; ++a)
            searched[a] = n > 1 && extentOf[a] > 0 && (n <= FULL_SEARCH_LIMIT || a == widest);
        // Both searches find the same split (see BvhBinner.searchPair), the direct one without
        // binning, for the commonest node of all.
        if (n == 2 && pairs) binner.searchPair(bounds, centroid, start, lowOf, extentOf, parentArea);
        else binner.searchBinned(bounds, centroid, start, end, lowOf, extentOf, parentArea);
        double bestCost = binner.bestCost;
        int bestBin = binner.bestBin, bestAxis = binner.bestAxis;
        int mid = -1;
        if (bestBin >= 0 && (bestCost < n || n > MAX_LEAF))
            mid = partition(start, end, bestAxis, lowOf[bestAxis], BvhBinner.BINS / extentOf[bestAxis], bestBin,
                    binner.bestBoxes, binner.levels(level + 1), binner.place(level + 1, 0));
        // All centroids coincide: split the range in half to bound the leaf size.
        if (mid < 0 && n > MAX_LEAF) {
            mid = start + n / 2;
            double[] children = binner.levels(level + 1);
            int at = binner.place(level + 1, 0);
            BuildBoxes.emptyBounds(children, at);
            BuildBoxes.emptyBounds(children, at + BOUNDS);
            for (int i = start; i < end; ++i) growBounds(children, i < mid ? at : at + BOUNDS, i);
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
     * pass gathers both parts' centroid bounds into {@code children} at the next level's places,
     * beside the parts' boxes, which the search already found ({@code boxes}: the left part's,
     * then the right part's), so that no child reads its range again for them.
     *
     * @return the first slot of the right part
     */
    private int partition(int start, int end, int axis, double lo, double scale, int lastLeftBin, double[] boxes,
                          double[] children, int at) {
        double[] bounds = this.bounds, centroid = this.centroid, sBounds = scratchBounds, sCentroid = scratchCentroid;
        // The two parts' boxes are the search's (its sweeps found them); their centroids' bounds
        // are grown here, in locals, not in an array: in memory, each primitive's updates waited
        // for the previous primitive's stores.
        double lcx0 = Double.POSITIVE_INFINITY, lcy0 = lcx0, lcz0 = lcx0;
        double lcx1 = Double.NEGATIVE_INFINITY, lcy1 = lcx1, lcz1 = lcx1;
        double rcx0 = lcx0, rcy0 = lcx0, rcz0 = lcx0;
        double rcx1 = lcx1, rcy1 = lcx1, rcz1 = lcx1;
        int l = start, r = start;
        for (int i = start; i < end; ++i) {
            int o = i * BOX_SIZE, c = i * 3; // b0 … b2 the box's low corner, b3 … b5 its high one (BuildBoxes)
            double b0 = bounds[o], b1 = bounds[o + 1], b2 = bounds[o + 2];
            double b3 = bounds[o + 3], b4 = bounds[o + 4], b5 = bounds[o + 5];
            double c0 = centroid[c], c1 = centroid[c + 1], c2 = centroid[c + 2];
            if (BvhBinner.binOf(centroid[c + axis], lo, scale) <= lastLeftBin) {
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
                rcx0 = Math.min(c0, rcx0); rcy0 = Math.min(c1, rcy0); rcz0 = Math.min(c2, rcz0);
                rcx1 = Math.max(c0, rcx1); rcy1 = Math.max(c1, rcy1); rcz1 = Math.max(c2, rcz1);
                int ro = r * 6, rc = r * 3;
                scratchOrder[r++] = order[i];
                sBounds[ro] = b0; sBounds[ro + 1] = b1; sBounds[ro + 2] = b2;
                sBounds[ro + 3] = b3; sBounds[ro + 4] = b4; sBounds[ro + 5] = b5;
                sCentroid[rc] = c0; sCentroid[rc + 1] = c1; sCentroid[rc + 2] = c2;
            }
        }
        int left = at, right = at + BOUNDS;
        System.arraycopy(boxes, 0, children, left + BOX, BOX_SIZE);
        BuildBoxes.set(children, left + CENTROIDS, lcx0, lcy0, lcz0, lcx1, lcy1, lcz1);
        System.arraycopy(boxes, BOX_SIZE, children, right + BOX, BOX_SIZE);
        BuildBoxes.set(children, right + CENTROIDS, rcx0, rcy0, rcz0, rcx1, rcy1, rcz1);
        int rightCount = r - start;
        System.arraycopy(scratchOrder, start, order, l, rightCount);
        System.arraycopy(scratchBounds, start * 6, bounds, l * 6, rightCount * 6);
        System.arraycopy(scratchCentroid, start * 3, centroid, l * 3, rightCount * 3);
        return l;
    }

    /** Grows the bounds at {@code at} of {@code b} by slot {@code i}'s box and centroid. */
    private void growBounds(double[] b, int at, int i) {
        BuildBoxes.grow(b, at + BOX, bounds, i * BOX_SIZE);
        BuildBoxes.growToPoint(b, at + CENTROIDS, centroid, i * 3);
    }
}
