package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import geometries.Intersectable.GeoPoint;
import primitives.Point;
import primitives.Ray;

/**
 * Reads the three faces of intersection (list API, closest hit, any-hit walk) into comparable
 * values, and asserts that they tell the same story about one ray.
 */
final class Hits {
    private Hits() {
    }

    /** One intersection as a value: which geometry (by identity) and how far along the ray. */
    record Visit(Geometry geometry, double t) {
        @Override
        public String toString() {
            return geometry.getClass().getSimpleName() + "@" + Integer.toHexString(System.identityHashCode(geometry)) + " t=" + t;
        }
    }

    /** @return the list API's intersections as visits sorted by distance, empty (never null) when none */
    static List<Visit> listed(Intersectable g, Ray ray, double maxDistance) {
        List<GeoPoint> points = g.findGeoIntersections(ray, maxDistance);
        List<Visit> visits = new ArrayList<>();
        if (points != null) for (GeoPoint gp : points) visits.add(new Visit(gp.geometry, gp.point.distance(ray.getHead())));
        visits.sort(Comparator.comparingDouble(Visit::t));
        return visits;
    }

    /** @return the any-hit walk's visits sorted by distance */
    static List<Visit> visited(Intersectable g, Ray ray, double maxDistance) {
        List<Visit> visits = new ArrayList<>();
        assertThat(g.visitHits(ray, maxDistance, (geometry, t) -> visits.add(new Visit(geometry, t))))
                .as("a visitor that never stops sees the walk complete").isTrue();
        visits.sort(Comparator.comparingDouble(Visit::t));
        return visits;
    }

    /** @return the closest hit below {@code tMax} as a visit, or null */
    static Visit closest(Intersectable g, Ray ray, double tMax) {
        Hit hit = new Hit().reset(tMax);
        boolean found = g.closestHit(ray, hit);
        assertThat(hit.found()).as("closestHit's return value agrees with the record").isEqualTo(found);
        if (!found) {
            assertThat(hit.getT()).as("a miss leaves the bound unchanged").isEqualTo(tMax);
            return null;
        }
        return new Visit(hit.getGeometry(), hit.getT());
    }

    /** Asserts two sorted visit lists name the same geometries at the same distances (within {@code tol}). */
    static void assertSameVisits(List<Visit> actual, List<Visit> expected, double tol, String what) {
        assertThat(actual).as(what + ": number of hits (actual %s, expected %s)", actual, expected).hasSameSizeAs(expected);
        for (int i = 0; i < expected.size(); ++i) {
            assertThat(actual.get(i).geometry()).as(what + ": geometry of hit %d of %s", i, expected).isSameAs(expected.get(i).geometry());
            assertThat(actual.get(i).t()).as(what + ": distance of hit %d", i).isCloseTo(expected.get(i).t(), org.assertj.core.api.Assertions.within(tol));
        }
    }

    /**
     * The equivalence-class assertion used by the shape tests: the list API gives exactly
     * {@code expected} (nearest first, as points), the closest-hit query finds the first of them
     * and the any-hit walk visits as many. No expected points means a miss on every face.
     */
    static void assertHits(Intersectable g, Ray ray, Point... expected) {
        List<Point> points = g.findIntersections(ray);
        Visit nearest = closest(g, ray, Double.POSITIVE_INFINITY);
        List<Visit> visits = visited(g, ray, Double.POSITIVE_INFINITY);
        if (expected.length == 0) {
            assertThat(points).as("list API on a miss (course rule: null)").isNull();
            assertThat(nearest).as("closest hit on a miss").isNull();
            assertThat(visits).as("any-hit walk on a miss").isEmpty();
            return;
        }
        assertThat(points).as("list API").isNotNull();
        List<Point> sorted = new ArrayList<>(points);
        sorted.sort(Comparator.comparingDouble(p -> p.distance(ray.getHead())));
        assertThat(sorted).as("intersection points, nearest first").containsExactly(expected);
        assertThat(nearest).as("closest hit").isNotNull();
        assertThat(ray.getPoint(nearest.t())).as("closest hit point").isEqualTo(expected[0]);
        assertThat(visits).as("any-hit walk").hasSize(expected.length);
    }
}
