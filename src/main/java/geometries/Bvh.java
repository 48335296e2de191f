package geometries;

import java.util.ArrayList;
import java.util.List;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

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

    /** The leaves this tree indexes, as collected: what it contributes to a tree built around it. */
    private final Intersectable[] leaves;
    private final Intersectable[] unbounded;
    // Per primitive, in leaf order: its owner and its index within the owner.
    private final Intersectable[] owner;
    private final int[] prim;
    // Per node, depth-first, one packed record of NODE doubles = 64 bytes, one cache line: the box
    // (min xyz, max xyz), then for a leaf its first primitive and its primitive count (> 0), for an
    // inner node its right child (the left child is the next node) and 0.
    private static final int NODE = 8;
    private final double[] node;
    // The first node after each node's subtree: the any-hit walk's skip links.
    private final int[] skip;
    private final int nodeCount;
    private final int depth;

    /**
     * Indexes the leaves of {@code geometries} as they are now: geometries added later are not in
     * the tree, so build it after the scene is complete (the renderer does, once per render).
     *
     * @param geometries the scene's geometries; bounded leaves go into the tree
     * @return the hierarchy, immutable, safe to share between render threads
     */
    public static Bvh build(Geometries geometries) {
        return new Bvh(geometries);
    }

    private Bvh(Geometries geometries) {
        List<Intersectable> leaves = new ArrayList<>();
        geometries.collectLeaves(leaves);
        List<Intersectable> free = new ArrayList<>();
        int total = 0;
        for (Intersectable leaf : leaves) {
            if (leaf.getBoundingBox() == null) free.add(leaf);
            else total += leaf.primitiveCount();
        }
        this.leaves = leaves.toArray(new Intersectable[0]);
        unbounded = free.toArray(new Intersectable[0]);

        Builder b = new Builder(total);
        for (Intersectable leaf : leaves) {
            if (leaf.getBoundingBox() == null) continue;
            for (int i = 0, n = leaf.primitiveCount(); i < n; ++i) b.addPrimitive(leaf, i, leaf.primitiveBounds(i));
        }
        b.build();
        owner = b.orderedOwner;
        prim = b.orderedPrim;
        nodeCount = b.nodes;
        node = new double[nodeCount * NODE];
        for (int i = 0; i < nodeCount; ++i) {
            System.arraycopy(b.box, i * 6, node, i * NODE, 6);
            node[i * NODE + 6] = b.firstOrRight[i];
            node[i * NODE + 7] = b.count[i];
        }
        skip = java.util.Arrays.copyOf(b.skip, nodeCount);
        depth = b.maxDepth + 1;
    }

    /** @return the number of nodes in the tree (0 when nothing is bounded) */
    public int nodeCount() {
        return nodeCount;
    }

    /** @return the number of bounded primitives indexed */
    public int primitiveTotal() {
        return prim.length;
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
        int o = n * NODE;
        double[] bx = node;
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
    public boolean closestHit(Ray ray, Hit hit) {
        boolean found = false;
        for (Intersectable u : unbounded) found |= u.closestHit(ray, hit);
        if (nodeCount == 0) return found;
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        double ox = h.getX(), oy = h.getY(), oz = h.getZ();
        double ix = BoundingBox.inverse(d.getX()), iy = BoundingBox.inverse(d.getY()), iz = BoundingBox.inverse(d.getZ());
        if (!(entry(0, ox, oy, oz, ix, iy, iz, hit.t) < hit.t)) return found;
        if (hit.stack.length < depth) {
            hit.stack = new int[depth];
            hit.stackT = new double[depth];
        }
        int[] stack = hit.stack;
        double[] stackT = hit.stackT;
        double[] nd = node;
        int top = 0;
        int n = 0;
        while (true) {
            int o = n * NODE;
            int count = (int) nd[o + 7];
            if (count > 0) {
                for (int k = (int) nd[o + 6], end = k + count; k < end; ++k)
                    found |= owner[k].closestHit(prim[k], ray, hit);
            } else {
                int left = n + 1, right = (int) nd[o + 6];
                double tl = entry(left, ox, oy, oz, ix, iy, iz, hit.t);
                double tr = entry(right, ox, oy, oz, ix, iy, iz, hit.t);
                boolean hitLeft = tl < hit.t, hitRight = tr < hit.t;
                if (hitLeft && hitRight) {
                    if (tl <= tr) {
                        stack[top] = right;
                        stackT[top++] = tr;
                        n = left;
                    } else {
                        stack[top] = left;
                        stackT[top++] = tl;
                        n = right;
                    }
                    continue;
                }
                if (hitLeft || hitRight) {
                    n = hitLeft ? left : right;
                    continue;
                }
            }
            do {
                if (top == 0) return found;
                --top;
            } while (!(stackT[top] < hit.t));
            n = stack[top];
        }
    }

    /** The stackless walk: order does not matter for an any-hit query, so skip links suffice. */
    @Override
    public boolean visitHits(Ray ray, double maxDistance, HitVisitor visitor) {
        for (Intersectable u : unbounded)
            if (!u.visitHits(ray, maxDistance, visitor)) return false;
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        double ox = h.getX(), oy = h.getY(), oz = h.getZ();
        double ix = BoundingBox.inverse(d.getX()), iy = BoundingBox.inverse(d.getY()), iz = BoundingBox.inverse(d.getZ());
        // Boxes are tested a little past maxDistance: a hit exactly at it still counts (course rule).
        double limit = maxDistance * (1 + 1e-9) + 1e-9;
        double[] nd = node;
        int n = 0;
        while (n < nodeCount) {
            if (entry(n, ox, oy, oz, ix, iy, iz, limit) != Double.POSITIVE_INFINITY) {
                int o = n * NODE;
                int count = (int) nd[o + 7];
                if (count == 0) {
                    ++n;
                    continue;
                }
                for (int k = (int) nd[o + 6], end = k + count; k < end; ++k)
                    if (!owner[k].visitHits(prim[k], ray, maxDistance, visitor)) return false;
            }
            n = skip[n];
        }
        return true;
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        List<GeoPoint> result = new ArrayList<>();
        visitHits(ray, maxDistance, (geometry, t) -> result.add(new GeoPoint(geometry, ray.getPoint(t))));
        return result;
    }

    /**
     * A tree inside a scene that is built into a tree in turn hands over its leaves, not itself:
     * the outer tree then indexes every primitive directly. (Walked as a leaf, this tree would
     * also reuse the {@link Hit#stack} the outer walk is still using.)
     */
    @Override
    void collectLeaves(List<Intersectable> out) {
        for (Intersectable leaf : leaves) out.add(leaf);
    }

    @Override
    public BoundingBox getBoundingBox() {
        if (unbounded.length > 0 || nodeCount == 0) return null;
        return new BoundingBox(node[0], node[1], node[2], node[3], node[4], node[5]);
    }

    /** The top-down binned-SAH builder; its arrays become the tree's. */
    private static final class Builder {
        private final Intersectable[] owners;
        private final int[] prims;
        private final double[] bounds; // 6 per primitive
        private final double[] centroid; // 3 per primitive
        private int added;
        private int[] order; // primitive ids, permuted into leaf order

        Intersectable[] orderedOwner;
        int[] orderedPrim;
        double[] box;
        int[] firstOrRight;
        int[] count;
        int[] skip;
        int nodes;
        int maxDepth;
        // Scratch reused by every node of the build.
        private int[] scratch;
        private final int[] binCount = new int[BINS];
        private final double[] binBox = new double[BINS * 6];
        private final double[] rightArea = new double[BINS];
        private final double[] acc = new double[6];

        Builder(int total) {
            owners = new Intersectable[total];
            prims = new int[total];
            bounds = new double[total * 6];
            centroid = new double[total * 3];
        }

        void addPrimitive(Intersectable leaf, int index, BoundingBox b) {
            int i = added++;
            owners[i] = leaf;
            prims[i] = index;
            BoundingBox p = b.padded();
            int o = i * 6;
            bounds[o] = p.minX;
            bounds[o + 1] = p.minY;
            bounds[o + 2] = p.minZ;
            bounds[o + 3] = p.maxX;
            bounds[o + 4] = p.maxY;
            bounds[o + 5] = p.maxZ;
            centroid[i * 3] = (b.minX + b.maxX) / 2;
            centroid[i * 3 + 1] = (b.minY + b.maxY) / 2;
            centroid[i * 3 + 2] = (b.minZ + b.maxZ) / 2;
        }

        void build() {
            int n = added;
            order = new int[n];
            scratch = new int[n];
            for (int i = 0; i < n; ++i) order[i] = i;
            int capacity = Math.max(1, 2 * n);
            box = new double[capacity * 6];
            firstOrRight = new int[capacity];
            count = new int[capacity];
            skip = new int[capacity];
            if (n > 0) buildNode(0, n, 0);
            orderedOwner = new Intersectable[n];
            orderedPrim = new int[n];
            for (int i = 0; i < n; ++i) {
                orderedOwner[i] = owners[order[i]];
                orderedPrim[i] = prims[order[i]];
            }
        }

        /** Builds the subtree over order[start, end) and returns its node index. */
        private int buildNode(int start, int end, int level) {
            int node = nodes++;
            if (level > maxDepth) maxDepth = level;
            double bx0 = Double.POSITIVE_INFINITY, by0 = bx0, bz0 = bx0, bx1 = Double.NEGATIVE_INFINITY, by1 = bx1, bz1 = bx1;
            double cx0 = bx0, cy0 = bx0, cz0 = bx0, cx1 = bx1, cy1 = bx1, cz1 = bx1;
            for (int i = start; i < end; ++i) {
                int p = order[i], o = p * 6, c = p * 3;
                if (bounds[o] < bx0) bx0 = bounds[o];
                if (bounds[o + 1] < by0) by0 = bounds[o + 1];
                if (bounds[o + 2] < bz0) bz0 = bounds[o + 2];
                if (bounds[o + 3] > bx1) bx1 = bounds[o + 3];
                if (bounds[o + 4] > by1) by1 = bounds[o + 4];
                if (bounds[o + 5] > bz1) bz1 = bounds[o + 5];
                if (centroid[c] < cx0) cx0 = centroid[c];
                if (centroid[c + 1] < cy0) cy0 = centroid[c + 1];
                if (centroid[c + 2] < cz0) cz0 = centroid[c + 2];
                if (centroid[c] > cx1) cx1 = centroid[c];
                if (centroid[c + 1] > cy1) cy1 = centroid[c + 1];
                if (centroid[c + 2] > cz1) cz1 = centroid[c + 2];
            }
            int o = node * 6;
            box[o] = bx0;
            box[o + 1] = by0;
            box[o + 2] = bz0;
            box[o + 3] = bx1;
            box[o + 4] = by1;
            box[o + 5] = bz1;
            int n = end - start;
            // Binned SAH over every axis whose centroids spread; for very large nodes only along
            // the widest one (as pbrt does), a third of the work for trees of nearly the same
            // quality where it matters for build time. Small and medium nodes get the full search:
            // it makes measurably better trees (fewer box tests per ray).
            double[] extentOf = { cx1 - cx0, cy1 - cy0, cz1 - cz0 };
            double[] lowOf = { cx0, cy0, cz0 };
            int widest = extentOf[0] >= extentOf[1] && extentOf[0] >= extentOf[2] ? 0 : extentOf[1] >= extentOf[2] ? 1 : 2;
            int mid = -1;
            double bestCost = Double.POSITIVE_INFINITY;
            int bestBin = -1, bestAxis = -1;
            double parentArea = (bx1 - bx0) * (by1 - by0) + (by1 - by0) * (bz1 - bz0) + (bz1 - bz0) * (bx1 - bx0);
            for (int a = 0; a < 3 && n > 1; ++a) {
                if (!(extentOf[a] > 0) || (n > FULL_SEARCH_LIMIT && a != widest)) continue;
                java.util.Arrays.fill(binCount, 0);
                for (int k = 0; k < BINS; ++k) resetBox(binBox, k);
                double lo = lowOf[a], scale = BINS / extentOf[a];
                for (int i = start; i < end; ++i) {
                    int p = order[i];
                    int k = bin(centroid[p * 3 + a], lo, scale);
                    binCount[k]++;
                    growBox(binBox, k, bounds, p);
                }
                // Sweep from the right for the areas of every right part, then from the left.
                resetBox(acc, 0);
                for (int k = BINS - 1; k > 0; --k) {
                    growBox(acc, 0, binBox, k);
                    rightArea[k] = halfArea(acc, 0);
                }
                resetBox(acc, 0);
                int leftCount = 0;
                for (int k = 0; k < BINS - 1; ++k) {
                    growBox(acc, 0, binBox, k);
                    leftCount += binCount[k];
                    int rightCount = n - leftCount;
                    if (leftCount == 0 || rightCount == 0) continue;
                    double cost = TRAVERSAL_COST + (halfArea(acc, 0) * leftCount + rightArea[k + 1] * rightCount) / parentArea;
                    if (cost < bestCost) {
                        bestCost = cost;
                        bestBin = k;
                        bestAxis = a;
                    }
                }
            }
            if (bestBin >= 0 && (bestCost < n || n > MAX_LEAF)) {
                // Stable partition through the shared scratch buffer: deterministic order.
                double lo = lowOf[bestAxis], scale = BINS / extentOf[bestAxis];
                int l = start, r = 0;
                for (int i = start; i < end; ++i) {
                    int p = order[i];
                    if (bin(centroid[p * 3 + bestAxis], lo, scale) <= bestBin) order[l++] = p;
                    else scratch[r++] = p;
                }
                System.arraycopy(scratch, 0, order, l, r);
                mid = l;
            }
            if (mid < 0 && n > MAX_LEAF) {
                // All centroids coincide: split the range in half to bound the leaf size.
                mid = start + n / 2;
            }
            if (mid < 0) {
                firstOrRight[node] = start;
                count[node] = n;
            } else {
                count[node] = 0;
                buildNode(start, mid, level + 1);
                firstOrRight[node] = buildNode(mid, end, level + 1);
            }
            skip[node] = nodes;
            return node;
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

        private static void growBox(double[] b, int k, double[] src, int s) {
            int o = k * 6, so = s * 6;
            for (int a = 0; a < 3; ++a) {
                if (src[so + a] < b[o + a]) b[o + a] = src[so + a];
                if (src[so + a + 3] > b[o + a + 3]) b[o + a + 3] = src[so + a + 3];
            }
        }

        private static double halfArea(double[] b, int k) {
            int o = k * 6;
            double dx = b[o + 3] - b[o], dy = b[o + 4] - b[o + 1], dz = b[o + 5] - b[o + 2];
            return dx * dy + dy * dz + dz * dx;
        }
    }
}
