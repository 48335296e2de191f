package geometries;

import java.lang.ref.SoftReference;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Objects;
import java.util.Set;

import primitives.Ray;

/**
 * The course's flat list of intersectables, every course year (2023&ndash;24 to 2025&ndash;26): a
 * scene test fills the scene's ({@code scene.geometries.add(sphere, triangle)}) or groups shapes in
 * one ({@code new Geometries(a, b)}). Its queries ask each member and merge the answers
 * ({@code null} when none is hit).
 *
 * <p>A composite of intersectables. The renderer does not walk this list directly when the BVH is
 * on: it indexes the leaves ({@link #collectLeaves}) in a {@link Bvh}.
 */
public class Geometries extends Intersectable {
    /**
     * The deepest nesting of lists a render takes: a list is level 1, a list inside it level 2.
     * The renderer's flat walk (and the bounding box) recurse once per level, so a much deeper
     * chain overflows a thread's stack; a render refuses it at the start, naming the depth (see
     * {@link GeometryLists#requireNestingWithinLimit}). The course's queries walk any depth. Scenes need a
     * few levels.
     */
    public static final int MAX_NESTING_DEPTH = 1000;

    private final List<Intersectable> items = new ArrayList<>();
    /** The number of {@link #add} calls so far; volatile, so that a render on another thread sees them. */
    private volatile int changes;
    /**
     * The tree {@link Bvh#of} last built over these geometries, for the next render to reuse;
     * soft, so that a scene kept but no longer rendered gives the memory back when it is short.
     */
    private SoftReference<Bvh> tree;

    /** An empty composite; {@link #add} fills it. */
    public Geometries() {
    }

    /**
     * @param geometries the first members, in order
     * @throws NullPointerException naming the index of a null element
     */
    public Geometries(Intersectable... geometries) {
        append(geometries); // not the overridable add: a subclass is not initialised yet
    }

    /**
     * @param geometries members to append; another {@code Geometries} is allowed (a nested group)
     * @throws NullPointerException naming the index of a null element
     */
    public void add(Intersectable... geometries) {
        append(geometries);
    }

    /**
     * The course spelling of "put these geometries in a bounding volume hierarchy" (2025–26
     * sources; also {@link #makeBVH()}, {@link #enableBVH()}). It does nothing, on purpose: the
     * library's tracer indexes the scene's bounded geometries in its BVH at the start of every
     * render, over the scene as it is then, and reuses the tree while the lists are unchanged
     * ({@code RayTracerBasic.setBvh(false)} is the one switch that turns it off, to compare). So
     * there is nothing to build here, and a tree made now could only go stale when shapes are
     * added after it. The call is not a change of the list: a render's scene-change check does
     * not count it.
     *
     * @return this list, for chaining
     */
    public Geometries buildBVH() {
        return this;
    }

    /**
     * Another course spelling of {@link #buildBVH()}: does nothing (see there).
     *
     * @return this list, for chaining
     */
    public Geometries makeBVH() {
        return buildBVH();
    }

    /**
     * Another course spelling of {@link #buildBVH()}: does nothing (see there).
     *
     * @return this list, for chaining
     */
    public Geometries enableBVH() {
        return buildBVH();
    }

    private void append(Intersectable... geometries) {
        for (int i = 0; i < geometries.length; ++i) {
            Objects.requireNonNull(geometries[i], "geometry #" + i + " to add is null");
            if (geometries[i] == this) throw new IllegalArgumentException("geometry #" + i + " to add is this list itself");
        }
        for (Intersectable g : geometries) items.add(g);
        changes++;
    }

    /** {@link GeometryLists#changeCount}: the number of {@link #add} calls on this list and every list within it. */
    long changeCount() {
        long count = 0;
        Set<Geometries> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        Deque<Geometries> todo = new ArrayDeque<>(List.of(this));
        while (!todo.isEmpty()) {
            Geometries g = todo.pop();
            if (!seen.add(g)) continue;
            count += g.changes;
            for (int i = 0; i < g.items.size(); ++i)
                if (g.items.get(i) instanceof Geometries nested) todo.push(nested);
        }
        return count;
    }

    /**
     * @return the levels of lists: 1 for a list of shapes, 2 when one of them is a list of
     *         shapes, and so on; more than the number of lists when one contains itself (counting
     *         then stops)
     */
    int nestingDepth() {
        return nesting().depth();
    }

    /** {@link GeometryLists#requireNestingWithinLimit}. */
    void requireNestingWithinLimit() {
        Nesting n = nesting();
        if (n.depth() > n.lists()) // a chain longer than the lists goes round a cycle
            throw new IllegalArgumentException("the geometries contain themselves: one of their " + n.lists()
                    + " Geometries lists is nested in itself, which no render can walk");
        if (n.depth() > MAX_NESTING_DEPTH) throw new IllegalArgumentException("the geometries are nested " + n.depth() + " levels deep (a Geometries in a"
                + " Geometries ...), more than the limit of " + MAX_NESTING_DEPTH
                + " (Geometries.MAX_NESTING_DEPTH): add the shapes to fewer, flatter lists");
    }

    /** The longest chain of nested lists, and the number of distinct lists. */
    private record Nesting(int depth, int lists) {
    }

    /**
     * Walks the lists level by level, each list once per level, without recursion. A chain longer
     * than the number of lists goes round a cycle: the walk stops there.
     */
    private Nesting nesting() {
        Set<Geometries> all = Collections.newSetFromMap(new IdentityHashMap<>());
        all.add(this);
        Set<Geometries> level = all;
        int depth = 1;
        while (true) {
            Set<Geometries> next = Collections.newSetFromMap(new IdentityHashMap<>());
            for (Geometries g : level)
                for (int i = 0; i < g.items.size(); ++i)
                    if (g.items.get(i) instanceof Geometries nested) next.add(nested);
            if (next.isEmpty() || depth > all.size()) return new Nesting(depth, all.size());
            all.addAll(next);
            level = next;
            ++depth;
        }
    }

    /** @return a read-only view of the direct children */
    public List<Intersectable> getItems() {
        return Collections.unmodifiableList(items);
    }

    /** @return true when nothing has been added: every ray misses */
    public boolean isEmpty() {
        return items.isEmpty();
    }

    /**
     * The course's query over every item, nested lists included, in the order of the items (a
     * nested list's points where the list stands). Nested plain {@code Geometries} are walked with
     * an explicit stack, not by recursion, so a nest of any depth is answered (10,000 levels
     * overflowed the thread's stack); a subclass of {@code Geometries} is asked through its own
     * query, as any other item.
     *
     * @throws IllegalArgumentException when a list is nested in itself (the walk would not end)
     */
    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        List<GeoPoint> result = null;
        Geometries list = this;
        int next = 0;
        // The lists above the current one and where each resumes; made at the first nested list.
        Deque<Geometries> parents = null;
        int[] resume = null;
        Set<Geometries> onPath = null; // the lists being walked: meeting one again is a cycle
        while (true) {
            if (next < list.items.size()) {
                Intersectable item = list.items.get(next++);
                if (item instanceof Geometries nested && nested.getClass() == Geometries.class) {
                    if (parents == null) {
                        parents = new ArrayDeque<>();
                        resume = new int[16];
                        onPath = Collections.newSetFromMap(new IdentityHashMap<>());
                        onPath.add(this);
                    }
                    if (!onPath.add(nested))
                        throw new IllegalArgumentException("the geometries contain themselves: a Geometries list is"
                                + " nested in itself, " + (parents.size() + 1) + " levels down, so no query can walk them");
                    if (parents.size() == resume.length) resume = Arrays.copyOf(resume, 2 * resume.length);
                    resume[parents.size()] = next;
                    parents.push(list);
                    list = nested;
                    next = 0;
                } else {
                    List<GeoPoint> found = item.findGeoIntersections(ray, maxDistance);
                    if (found != null) {
                        if (result == null) result = new ArrayList<>(found);
                        else result.addAll(found);
                    }
                }
            } else {
                if (parents == null || parents.isEmpty()) return result;
                onPath.remove(list);
                list = parents.pop();
                next = resume[parents.size()];
            }
        }
    }

    @Override
    boolean closestHit(Hit hit) {
        if (!answersInDoubles()) return super.closestHit(hit); // a subclass's own hook answers
        boolean found = false;
        for (int i = 0, n = items.size(); i < n; ++i)
            found |= items.get(i).closestHit(hit);
        return found;
    }

    @Override
    boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        if (!answersInDoubles()) return super.visitHits(query, maxDistance, visitor);
        for (int i = 0, n = items.size(); i < n; ++i)
            if (!items.get(i).visitHits(query, maxDistance, visitor)) return false;
        return true;
    }

    /**
     * @return the union of the children's boxes; null when empty or when any child is unbounded
     */
    @Override
    BoundingBox getBoundingBox() {
        BoundingBox box = null;
        for (Intersectable item : items) {
            BoundingBox b = item.getBoundingBox();
            if (b == null) return null;
            box = box == null ? b : box.union(b);
        }
        return box;
    }

    /** @return the tree last kept by {@link #keepTree}, or null when none is (or it was collected) */
    synchronized Bvh keptTree() {
        return tree == null ? null : tree.get();
    }

    /** Keeps {@code built} for {@link Bvh#of} to check and reuse. */
    synchronized void keepTree(Bvh built) {
        tree = new SoftReference<>(built);
    }

    /**
     * The leaves of this list and of every list in it, in order, walked with a stack of its own
     * rather than recursion: a chain of lists as deep as the memory holds does not overflow the
     * thread's stack (a render refuses one deeper than {@link #MAX_NESTING_DEPTH} before).
     */
    @Override
    void collectLeaves(List<Intersectable> out) {
        if (!answersInDoubles()) { // a user's list with a hook of its own is asked as one leaf
            out.add(this);
            return;
        }
        requireNestingWithinLimit(); // a list within itself would be walked without end
        Deque<Geometries> lists = new ArrayDeque<>();
        Deque<Integer> positions = new ArrayDeque<>();
        lists.push(this);
        positions.push(0);
        while (!lists.isEmpty()) {
            Geometries g = lists.peek();
            int i = positions.pop();
            if (i >= g.items.size()) {
                lists.pop();
                continue;
            }
            positions.push(i + 1);
            Intersectable item = g.items.get(i);
            if (item instanceof Geometries nested && nested.answersInDoubles()) {
                lists.push(nested);
                positions.push(0);
            } else {
                item.collectLeaves(out);
            }
        }
    }
}
