package geometries;

import static geometries.BvhNodes.X;
import static geometries.BvhNodes.Y;
import static geometries.BvhNodes.Z;

import java.util.ArrayList;
import java.util.List;

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
 * <p>Immutable after {@link #build}, but for its wide part, which a long render may add once and
 * publishes whole ({@link #expectLongWalk}); any number of threads may query it. The build is
 * deterministic: the same scene gives the same tree.
 *
 * @hidden internal: a render builds and keeps the tree itself ({@code setBvh(true)}, the
 *         default); public for the renderer, the benchmarks and the Spark jobs
 */
public final class Bvh extends Intersectable {
    /**
     * Subtrees over more primitives than this are built as parallel tasks; smaller ones are not
     * worth a task (about 0.1 ms of work).
     */
    private static final int FORK_ABOVE = 4096;
    /**
     * Whether the walks count their tests into the hit record ({@link Hit#boxTests}), for the
     * benchmark's counts: {@code -Draytracer.walkCounts=true}. A constant, so that in every other
     * JVM the compilers drop the counting, and the walk counted is the walk that runs.
     */
    static final boolean COUNTING = Boolean.getBoolean("raytracer.walkCounts");

    /** The leaves this tree indexes, as collected: what it contributes to a tree built around it. */
    private final Intersectable[] leaves;
    private final Intersectable[] unbounded;
    // Per primitive, in leaf order: its owner and its index within the owner.
    private final Intersectable[] owner;
    private final int[] prim;
    // Per primitive, in leaf order: its packed kind (BvhLeaf.OWN, SPHERE or TRIANGLE) and
    // PACKED doubles of intersection data, so that a leaf's library shapes are tested from one
    // contiguous run of memory instead of one object (and its centre) each, scattered on the heap.
    private final byte[] kind;
    private final double[] packed;
    /** The node records, laid out and read as {@link BvhNodes} says. */
    private final float[] node;
    /** The exact (double) box of the root, or null when nothing is bounded. */
    private final BoundingBox rootBox;
    private final int nodeCount;
    private final int depth;
    /**
     * What the vector walk reads, or null: the binary nodes are then walked in scalar code. Made
     * with the tree when a walk is asked for by name (a test, {@code -Draytracer.simd=true}), or
     * later, while a long render walks the tree ({@link #expectLongWalk}); then published whole.
     */
    private volatile WideTree wide;
    /**
     * Whether this tree may get {@link #wide} later: at the start of a long render
     * ({@link #expectCameraRays}), or once a render's pace says it is long and the vector walk is
     * compiled ({@link #expectLongWalk}).
     */
    private final boolean widens;
    /** Set when the heap had no room for {@link #wide}: the tree keeps the scalar walk ({@link #widen}). */
    private volatile boolean noRoom;

    /**
     * The tree of {@code geometries} as they are now, for a render: the tree an earlier call
     * built is reused when the geometries still hold the same leaves (the same objects, in the
     * same order, found through every nested list) and all of them are
     * {@link LeanQueries#isLibraryShape library shapes}, whose geometry cannot change; otherwise a new tree is built (as {@link #build(Geometries)}) and
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
        Bvh tree = new Bvh(now, Runtime.getRuntime().availableProcessors(), FORK_ABOVE, true, Vectorization.eagerWalk(),
                true);
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
        return build(geometries, parallelism, forkAbove, pairs, Vectorization.eagerWalk(), true);
    }

    /**
     * As {@link #build(Geometries, int, int, boolean)}, walked by {@code walk} (null: the scalar
     * walk) from the first ray on, whatever this JVM's {@link Vectorization} chose: for the tests
     * that both walks agree.
     */
    static Bvh build(Geometries geometries, int parallelism, int forkAbove, boolean pairs, WideWalk walk) {
        return build(geometries, parallelism, forkAbove, pairs, walk, false);
    }

    /**
     * As {@link #build(Geometries, int, int, boolean, WideWalk)}; when {@code later}, a tree walked
     * in scalar code at first gets this JVM's vector walk in a long render ({@link #expectLongWalk}).
     */
    static Bvh build(Geometries geometries, int parallelism, int forkAbove, boolean pairs, WideWalk walk, boolean later) {
        if (parallelism < 1) throw new IllegalArgumentException("parallelism must be at least 1, got " + parallelism);
        List<Intersectable> collected = new ArrayList<>();
        geometries.collectLeaves(collected);
        return new Bvh(collected.toArray(new Intersectable[0]), parallelism, Math.max(1, forkAbove), pairs, walk, later);
    }

    /**
     * Indexes {@code all}, a scene's leaves (this tree keeps the array), walked by {@code walk}
     * (null: scalar) and, when {@code later}, by this JVM's vector walk once a long render asks.
     */
    private Bvh(Intersectable[] all, int parallelism, int forkAbove, boolean pairs, WideWalk walk, boolean later) {
        leaves = all;
        BvhBuilder built = BvhBuilder.index(all, parallelism, forkAbove, pairs);
        unbounded = built.unbounded;
        owner = built.owner;
        prim = built.prim;
        kind = built.kind;
        packed = built.packed;
        node = built.node;
        nodeCount = built.nodes;
        rootBox = built.rootBox;
        depth = built.maxDepth + 1;
        // A root that is a leaf has no children to test together, and a small tree is walked
        // faster in scalar code (WideWalk.minPrimitives).
        if (walk != null && nodeCount > 1 && prim.length >= walk.minPrimitives())
            wide = WideTree.of(walk, node, nodeCount, kind, packed);
        widens = later && wide == null && nodeCount > 1 && Vectorization.AVAILABLE
                && prim.length >= Vectorization.MIN_PRIMITIVES;
    }

    /**
     * This tree will be walked for seconds more (a long render, {@code RenderLoop}): a tree large
     * enough for the vector walk gets its wide part when the walk runs compiled in this JVM
     * ({@link Vectorization#COMPILED}), and until then the walk is warmed ({@link VectorWarmUp}),
     * once per JVM. Not before: the warm-up costs about a second of processor time, which a short
     * render would lose.
     */
    void expectLongWalk() {
        if (!widens || wide != null || noRoom) return;
        if (Vectorization.COMPILED.get()) widen(Vectorization.walk());
        else VectorWarmUp.start();
    }

    /**
     * A render of about {@code cameraRays} camera rays is about to start, before any of its rays
     * is traced: a tree of {@link Vectorization#MIN_PRIMITIVES} or more gets its wide part
     * now when the render is long ({@link Vectorization#FIRST_RAY_CAMERA_RAYS}), and the render takes
     * the vector walk from its first ray. A tree that already has it keeps it; a render too short
     * for this rule may still switch at its pace ({@link #expectLongWalk}).
     */
    void expectCameraRays(long cameraRays) {
        if (!widens || wide != null || noRoom
                || cameraRays < Vectorization.FIRST_RAY_CAMERA_RAYS) return;
        widen(Vectorization.walk());
    }

    /**
     * Gives this tree its wide part for {@code walk} (null: none), unless it has one: from the
     * next ray on, every thread walks it with {@code walk}. The same hits either way, so a render
     * may take it between two rays.
     */
    synchronized void widen(WideWalk walk) {
        if (wide != null || walk == null || nodeCount <= 1 || noRoom) return;
        try {
            wide = WideTree.of(walk, node, nodeCount, kind, packed);
        } catch (OutOfMemoryError e) {
            // Not a failure of the render: the wide part (72 bytes a triangle, and the wide nodes)
            // only speeds it up, and a render near the heap's limit goes on in scalar code, as
            // it began. Its arrays were never published, so they are garbage at once.
            noRoom = true;
        }
    }

    /**
     * One line for a render's summary: which walk this JVM's trees take now, the vector walk of
     * wide nodes or the scalar one, and for the scalar one why ({@code jdk.incubator.vector} not
     * readable, {@code -Draytracer.simd=false}, a CPU without 256-bit vectors, or a vector walk
     * not compiled yet: a long render takes it from its first ray, and a render with
     * seconds of work left has it compiled; {@code -Draytracer.simd=true} gives it to any render's
     * tree of {@link Vectorization#ASKED_MIN_PRIMITIVES} primitives or more).
     * A render's summary names its own tree's walk ({@link #describeWalk}) instead.
     *
     * @return the walk, in words
     */
    public static String walkDescription() {
        return Vectorization.describe();
    }

    /** @return as {@link #walkDescription()}, for this tree: its vector walk's words once it has its wide part */
    String describeWalk() {
        WideTree w = wide;
        return w != null ? w.walk().description() : Vectorization.describe();
    }

    /**
     * The bound a box's entry is compared with, for a hit bound {@code t}: {@code t} itself, or
     * the largest finite double when nothing bounds the ray, so that a missed box, whose entry is
     * +∞, never passes "entry ≤ bound". A box entered exactly at the bound is walked: it may hold
     * a primitive hit at that very distance that wins by the tie rule ({@link #closestInLeaf}).
     */
    static double limit(double t) {
        return t < Double.MAX_VALUE ? t : Double.MAX_VALUE;
    }

    /** @return whether this tree was built over exactly {@code now}: the same objects in the same order */
    private boolean indexes(Intersectable[] now) {
        if (now.length != leaves.length) return false;
        for (int i = 0; i < now.length; ++i)
            if (now[i] != leaves[i]) return false;
        return true;
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
        // The packed records, without the few doubles of padding after them (TriangleLanes.PADDING).
        WideTree w = wide;
        return BvhNodes.bytes(nodeCount) + (w == null ? 0 : w.bytes(prim.length)) + prim.length * 9L
                + (packed.length == 0 ? 0 : prim.length * (long) PACKED * Double.BYTES);
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
     * The slab test of node {@code n} against the ray segment [0, tMax], in doubles from the
     * widened float box: every hit of the exact box stays a hit, and the entry distance can only
     * come out lower, so skipping a node by it stays safe.
     *
     * @return the distance at which the ray enters the box, or +∞ when it misses it
     */
    private double entry(int n, double ox, double oy, double oz, double ix, double iy, double iz, double tMax) {
        float[] nd = node;
        int at = BvhNodes.at(n);
        return BoundingBox.entry(BvhNodes.min(nd, at, X), BvhNodes.min(nd, at, Y), BvhNodes.min(nd, at, Z),
                BvhNodes.max(nd, at, X), BvhNodes.max(nd, at, Y), BvhNodes.max(nd, at, Z), ox, oy, oz, ix, iy, iz, tMax);
    }

    /**
     * The closest hit: the unbounded leaves, then the tree's walk, the wide one ({@code walk})
     * when this tree has one, else the binary one below.
     *
     * <p>The tie rule, which makes the answer independent of the order of the walk: of hits at
     * the same distance, one found before the walk (an unbounded leaf, or by the caller) wins,
     * then the primitive first in the tree's leaf order. Boxes entered exactly at the current
     * hit's distance are therefore still walked ({@code limit}).
     */
    @Override
    boolean closestHit(Hit hit) {
        boolean found = false;
        for (Intersectable u : unbounded) found |= u.closestHit(hit);
        hit.order = -1;
        if (nodeCount == 0) return found;
        double ox = hit.ox, oy = hit.oy, oz = hit.oz;
        double ix = BoundingBox.inverse(hit.dx), iy = BoundingBox.inverse(hit.dy), iz = BoundingBox.inverse(hit.dz);
        if (COUNTING) ++hit.boxTests;
        if (!(entry(0, ox, oy, oz, ix, iy, iz, hit.t) <= limit(hit.t))) return found;
        // A walk already in progress on this record (this one's caller, through a user's shape
        // that walks a tree of its own with the record) owns the record's stack: this one then
        // takes arrays of its own. Rare (only user shapes do it), so the common walk allocates nothing.
        WideTree w = wide; // read once: another thread may publish it meanwhile
        int size = w == null ? depth : w.nodes().stackSize();
        boolean nested = hit.walking;
        int[] stack;
        double[] stackT;
        if (nested) {
            stack = new int[size];
            stackT = new double[size];
        } else {
            reserveStack(hit, size);
            stack = hit.stack;
            stackT = hit.stackT;
            hit.walking = true;
        }
        try {
            return (w != null ? w.walk().closestHit(this, w.nodes().node, w.lanes(), hit, stack, stackT)
                    : binaryClosestHit(hit, stack, stackT, ox, oy, oz, ix, iy, iz)) | found;
        } finally {
            if (!nested) hit.walking = false;
        }
    }

    /** Grows {@code hit}'s walk stacks to {@code size} entries where they are smaller (once per record and tree depth). */
    private static void reserveStack(Hit hit, int size) {
        if (hit.stack.length >= size) return;
        hit.stack = new int[size];
        hit.stackT = new double[size];
    }

    /**
     * The ordered walk of the binary nodes below the root: at an inner node both children's
     * boxes are tested; the nearer one (by entry distance) is visited first and the other pushed
     * with its entry distance, so that when popped it is skipped if a hit nearer than its box was
     * found meanwhile.
     */
    private boolean binaryClosestHit(Hit hit, int[] stack, double[] stackT, double ox, double oy, double oz,
                                     double ix, double iy, double iz) {
        boolean found = false;
        float[] nd = node;
        int top = 0;
        int n = 0;
        while (true) {
            int rec = BvhNodes.at(n);
            int count = BvhNodes.count(nd, rec);
            if (count > 0) {
                found |= closestInLeaf(BvhNodes.first(nd, rec), count, hit);
            } else {
                int left = n + 1, right = BvhNodes.right(nd, rec);
                double tMax = limit(hit.t);
                if (COUNTING) hit.boxTests += 2;
                double tl = entry(left, ox, oy, oz, ix, iy, iz, tMax);
                double tr = entry(right, ox, oy, oz, ix, iy, iz, tMax);
                // One branch where there were four: a missed child's entry is +∞, above the
                // finite tMax, so "tl <= tr" picks the child to visit whichever were hit, and the
                // other is written to the stack always but kept (top moves) only when it was hit.
                // Which children are hit, and in which order, is a coin toss per node in a big
                // scene; selects cost less than the mispredictions (3–4 % at 2×10⁶ primitives).
                if (tl <= tMax || tr <= tMax) {
                    boolean leftFirst = tl <= tr;
                    int far = leftFirst ? right : left;
                    double tf = leftFirst ? tr : tl;
                    n = leftFirst ? left : right;
                    stack[top] = far;
                    stackT[top] = tf;
                    top += tf <= tMax ? 1 : 0;
                    continue;
                }
            }
            // Pop the entries the closer hit has since put out of range. Tested before the loop
            // rather than at its top: C2 made the earlier do-while a counted loop whose limit
            // check failed on the first empty stack of every JVM, which threw the method's first
            // compile away (one C2 compile of this method fewer a launch; BENCHMARKS.md, issue 50,
            // twelfth session).
            while (top > 0 && !(stackT[top - 1] <= limit(hit.t))) --top;
            if (top == 0) return found;
            n = stack[--top];
        }
    }

    /**
     * Tests the leaf's primitives [first, first + count) for a hit nearer than {@code hit}'s, or
     * as near and first in leaf order (the tie rule, {@link #closestHit(Hit)}).
     */
    boolean closestInLeaf(int first, int count, Hit hit) {
        boolean found = false;
        if (COUNTING) hit.primitiveTests += count;
        for (int k = first, end = first + count; k < end; ++k) {
            byte kd = kind[k];
            if (kd == OWN) {
                found |= closestOwn(k, hit);
                continue;
            }
            int at = k * PACKED;
            double t = kd == SPHERE ? Sphere.distance(hit, packed[at], packed[at + 1], packed[at + 2], packed[at + 3])
                    : Triangle.intersect(hit, packed, at);
            if (inRange(t, hit.t) || t == hit.t && k < hit.order) {
                hit.set(t, (Geometry) owner[k], prim[k]);
                hit.order = k;
                found = true;
            }
        }
        return found;
    }

    /** @return the binary node records, as {@link BvhNodes} lays them out (for the benchmark's tree shape; not to be written) */
    float[] nodes() {
        return node;
    }

    /** @return the wide nodes the vector walk reads, or null when this tree is walked in scalar code (for the tests) */
    WideNodes wideNodes() {
        WideTree w = wide;
        return w == null ? null : w.nodes();
    }

    /**
     * Primitive {@code k}, a triangle of a lane leaf, hit at {@code t} (NaN: missed), offered to
     * {@code hit} with {@link #closestInLeaf}'s rule, word for word: taken when nearer, or as
     * near and first in leaf order. For the wide walk, which computes a leaf's distances together
     * and offers them in leaf order, as the scalar loop meets them.
     *
     * @return whether {@code hit} now holds it
     */
    boolean offerTriangle(int k, double t, Hit hit) {
        if (inRange(t, hit.t) || t == hit.t && k < hit.order) {
            hit.set(t, (Geometry) owner[k], prim[k]);
            hit.order = k;
            return true;
        }
        return false;
    }

    /**
     * Primitive {@code k}, a triangle of a lane leaf, hit at {@code t} (NaN: missed), given to
     * {@code visitor} when within {@code maxDistance}: {@link #visitInLeaf}'s rule for a triangle.
     *
     * @return false when the visitor stopped the walk
     */
    boolean visitTriangle(int k, double t, double maxDistance, HitVisitor visitor) {
        return !within(t, maxDistance) || visitor.visit((Geometry) owner[k], t);
    }

    /**
     * Primitive {@code k} asked through its owner's own query, which takes only a strictly
     * nearer hit: where the tie rule would let it win a tie (it comes before the current hit in
     * leaf order), the bound is raised by one ulp for the call, and a hit beyond the old bound
     * (exactly one ulp farther) is undone.
     */
    private boolean closestOwn(int k, Hit hit) {
        // The owner may walk a tree of its own with this record (a user's group), which resets
        // the order: the current hit's is kept for when the owner finds nothing.
        int order = hit.order;
        if (!(k < order)) {
            boolean found = owner[k].closestHit(prim[k], hit);
            hit.order = found ? k : order;
            return found;
        }
        double t = hit.t;
        Geometry g = hit.geometry;
        int p = hit.primitive;
        hit.t = Math.nextUp(t);
        if (owner[k].closestHit(prim[k], hit) && hit.t <= t) {
            hit.order = k;
            return true;
        }
        hit.set(t, g, p);
        hit.order = order;
        return false;
    }

    /** The stackless walk: order does not matter for an any-hit query, so skip links suffice. */
    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        for (Intersectable u : unbounded)
            if (!u.visitHits(query, maxDistance, visitor)) return false;
        double ox = query.ox, oy = query.oy, oz = query.oz;
        double ix = BoundingBox.inverse(query.dx), iy = BoundingBox.inverse(query.dy), iz = BoundingBox.inverse(query.dz);
        double limit = boxLimit(maxDistance);
        WideTree w = wide;
        if (w != null) {
            // No test of the root's box first: most shadow rays start inside it, and C2 compiled
            // the rare miss to a trap that, met seconds into a render, threw the compiled any-hit
            // walk back to the interpreter (BENCHMARKS.md, issue 50). The root's children are
            // tested in the walk's first step anyway.
            int size = w.nodes().stackSize();
            // As the closest-hit walk's stack: a walk in progress on this record keeps its own.
            if (query.walking)
                return w.walk().visitHits(this, w.nodes().node, w.lanes(), query, limit, maxDistance, visitor, new int[size]);
            reserveStack(query, size);
            query.walking = true;
            try {
                return w.walk().visitHits(this, w.nodes().node, w.lanes(), query, limit, maxDistance, visitor, query.stack);
            } finally {
                query.walking = false;
            }
        }
        float[] nd = node;
        int n = 0;
        while (n < nodeCount) {
            int rec = BvhNodes.at(n);
            int count = BvhNodes.count(nd, rec);
            if (entry(n, ox, oy, oz, ix, iy, iz, limit) == Double.POSITIVE_INFINITY) {
                n = BvhNodes.skip(count, n);
                continue;
            }
            if (count > 0 && !visitInLeaf(BvhNodes.first(nd, rec), count, query, maxDistance, visitor)) return false;
            ++n; // into an inner node's left child, or past a leaf
        }
        return true;
    }

    /** How far along a ray the walks test boxes: a little past maxDistance, so that a hit exactly at it still counts (course rule). */
    private static double boxLimit(double maxDistance) {
        return maxDistance * (1 + 1e-9) + 1e-9;
    }

    /**
     * The leaves a {@link ShadowIndex} sorts, as node numbers: every leaf node of the binary
     * tree, whose box holds its primitives. A leaf that holds a user's shape comes as
     * {@code -1 - n}: the index may not ask it (a user's shape may count its calls, and the index
     * would call it more often than the walk), so its cells are left to the walk.
     *
     * @param most the most leaves wanted
     * @return the leaf nodes, or null when there are none or more than {@code most}, or when a
     *         shape without a box (asked by every ray) is a user's
     */
    int[] shadowIndexLeaves(int most) {
        int leaves = 0;
        for (int n = 0; n < nodeCount; ++n)
            if (BvhNodes.count(node, BvhNodes.at(n)) > 0) ++leaves;
        if (leaves == 0 || leaves > most) return null;
        for (Intersectable u : unbounded)
            if (!(u instanceof Geometry g && g.isLibraryShape())) return null;
        int[] found = new int[leaves];
        for (int n = 0, i = 0; n < nodeCount; ++n) {
            int at = BvhNodes.at(n), count = BvhNodes.count(node, at);
            if (count <= 0) continue; // an inner node
            boolean library = true;
            for (int k = BvhNodes.first(node, at), end = k + count; k < end; ++k)
                library &= owner[k] instanceof Geometry g && g.isLibraryShape();
            found[i++] = library ? n : -1 - n;
        }
        return found;
    }

    /** Copies node {@code n}'s box, min x, y, z then max x, y, z, into {@code box}. */
    void leafBox(int n, float[] box) {
        System.arraycopy(node, BvhNodes.at(n), box, 0, 6);
    }

    /**
     * Whether the any-hit walk ({@link #visitHits(Hit, double, HitVisitor)}) would find no hit along
     * {@code query} within {@code maxDistance}, given that only the leaf nodes
     * {@code leaves[from..to)} can hold one: the shapes without a box, then those leaves, each
     * with the walk's own tests (its box, then its primitives).
     */
    boolean clearOf(int[] leaves, int from, int to, Hit query, double maxDistance) {
        HitVisitor first = LeanQueries.FIRST_CROSSING;
        for (Intersectable u : unbounded)
            if (!u.visitHits(query, maxDistance, first)) return false;
        if (from == to) return true;
        double ox = query.ox, oy = query.oy, oz = query.oz;
        double ix = BoundingBox.inverse(query.dx), iy = BoundingBox.inverse(query.dy), iz = BoundingBox.inverse(query.dz);
        double limit = boxLimit(maxDistance);
        float[] nd = node;
        for (int i = from; i < to; ++i) {
            int n = leaves[i];
            if (entry(n, ox, oy, oz, ix, iy, iz, limit) == Double.POSITIVE_INFINITY) continue;
            int at = BvhNodes.at(n);
            if (!visitInLeaf(BvhNodes.first(nd, at), BvhNodes.count(nd, at), query, maxDistance, first)) return false;
        }
        return true;
    }

    /** Gives {@code visitor} each hit within {@code maxDistance} of the leaf's primitives [first, first + count). */
    boolean visitInLeaf(int first, int count, Hit query, double maxDistance, HitVisitor visitor) {
        for (int k = first, end = first + count; k < end; ++k) {
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
        return true;
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
    BoundingBox getBoundingBox() {
        return unbounded.length > 0 ? null : rootBox;
    }
}
