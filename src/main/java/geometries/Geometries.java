package geometries;

import java.lang.ref.SoftReference;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;

import primitives.Ray;

/**
 * A composite of intersectables (the course's flat list). The renderer does not walk this list
 * directly when the BVH is on: it indexes the leaves ({@link #collectLeaves}) in a {@link Bvh}.
 */
public class Geometries extends Intersectable {
    private final List<Intersectable> items = new ArrayList<>();
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
        add(geometries);
    }

    /**
     * @param geometries members to append; another {@code Geometries} is allowed (a nested group)
     * @throws NullPointerException naming the index of a null element
     */
    public void add(Intersectable... geometries) {
        for (int i = 0; i < geometries.length; ++i)
            items.add(Objects.requireNonNull(geometries[i], "geometry #" + i + " to add is null"));
    }

    /** @return a read-only view of the direct children */
    public List<Intersectable> getItems() {
        return Collections.unmodifiableList(items);
    }

    /** @return true when nothing has been added: every ray misses */
    public boolean isEmpty() {
        return items.isEmpty();
    }

    @Override
    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
        List<GeoPoint> result = null;
        for (Intersectable item : items) {
            List<GeoPoint> found = item.findGeoIntersections(ray, maxDistance);
            if (found != null) {
                if (result == null) result = new ArrayList<>(found);
                else result.addAll(found);
            }
        }
        return result;
    }

    @Override
    public boolean closestHit(Hit hit) {
        boolean found = false;
        for (int i = 0, n = items.size(); i < n; ++i)
            found |= items.get(i).closestHit(hit);
        return found;
    }

    @Override
    public boolean closestHit(Ray ray, Hit hit) {
        return closestHit(hit.setRay(ray));
    }

    @Override
    public boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
        for (int i = 0, n = items.size(); i < n; ++i)
            if (!items.get(i).visitHits(query, maxDistance, visitor)) return false;
        return true;
    }

    @Override
    public boolean visitHits(Ray ray, double maxDistance, HitVisitor visitor) {
        return visitHits(Hit.of(ray), maxDistance, visitor);
    }

    /** @return the union of the children's boxes; null when empty or when any child is unbounded */
    @Override
    public BoundingBox getBoundingBox() {
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

    @Override
    void collectLeaves(List<Intersectable> out) {
        for (Intersectable item : items) item.collectLeaves(out);
    }
}
