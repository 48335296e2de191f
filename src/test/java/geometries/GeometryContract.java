package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Hits.Visit;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * What every {@link Intersectable} promises, whatever its shape: the course list API, the lean
 * closest-hit query and the any-hit walk agree with each other, honour {@code maxDistance}, give
 * unit normals and stay inside the bounding box. A shape's test class implements this interface
 * and so runs all of it; so do the flat {@link Geometries} and the {@link Bvh}.
 *
 * <p>The random rays use a fixed seed: a failure reproduces, and names the ray.
 */
interface GeometryContract {
    /** Distances computed by different faces of the API must agree to this (scene units). */
    double T_TOLERANCE = 1e-9;
    int RAY_COUNT = 600;

    /** The intersectable under test. */
    Intersectable subject();

    /** A ray known to hit the subject at least once. */
    Ray knownHit();

    /** A ray known to miss the subject. */
    Ray knownMiss();

    /** The point random rays aim around. */
    Point focus();

    /** The half-size of the region around {@link #focus()} that random rays aim at. */
    double extent();

    /** False for planes, tubes and anything containing them: they have no bounding box. */
    default boolean bounded() {
        return true;
    }

    /**
     * Rays from outside aimed into the region, rays from inside it in random directions, and
     * axis-parallel rays (zero direction components are where slab tests break).
     */
    default List<Ray> randomRays() {
        Random rnd = new Random(0x5EED_0001L);
        Point c = focus();
        double e = extent();
        List<Ray> rays = new ArrayList<>(RAY_COUNT);
        Vector[] axes = { new Vector(1, 0, 0), new Vector(-1, 0, 0), new Vector(0, 1, 0), new Vector(0, -1, 0),
                new Vector(0, 0, 1), new Vector(0, 0, -1) };
        for (int i = 0; i < RAY_COUNT; ++i) {
            switch (i % 4) {
            case 0, 1 -> {
                Point from = around(rnd, c, 4 * e);
                Point to = around(rnd, c, e);
                if (from.distance(to) > 1e-6) rays.add(new Ray(from, to.subtract(from)));
            }
            case 2 -> rays.add(new Ray(around(rnd, c, e), randomDirection(rnd)));
            default -> rays.add(new Ray(around(rnd, c, 2 * e), axes[rnd.nextInt(axes.length)]));
            }
        }
        return rays;
    }

    private static Point around(Random rnd, Point c, double half) {
        return new Point(c.getX() + half * (2 * rnd.nextDouble() - 1), c.getY() + half * (2 * rnd.nextDouble() - 1),
                c.getZ() + half * (2 * rnd.nextDouble() - 1));
    }

    private static Vector randomDirection(Random rnd) {
        return new Vector(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
    }

    @Test
    @DisplayName("contract: the known hit is reported by every face of the API")
    default void knownHitIsReportedByEveryFace() {
        Ray ray = knownHit();
        List<Visit> listed = Hits.listed(subject(), ray, Double.POSITIVE_INFINITY);
        assertThat(listed).as("findGeoIntersections").isNotEmpty();
        assertThat(subject().findIntersections(ray)).as("findIntersections").hasSameSizeAs(listed);
        Visit closest = Hits.closest(subject(), ray, Double.POSITIVE_INFINITY);
        assertThat(closest).as("closestHit").isNotNull();
        assertThat(closest.t()).isCloseTo(listed.get(0).t(), within(T_TOLERANCE));
        assertThat(Hits.visited(subject(), ray, Double.POSITIVE_INFINITY)).as("visitHits").hasSameSizeAs(listed);
    }

    @Test
    @DisplayName("contract: the known miss is reported by no face of the API (lists are null)")
    default void knownMissIsReportedByNoFace() {
        Ray ray = knownMiss();
        assertThat(subject().findGeoIntersections(ray)).isNull();
        assertThat(subject().findIntersections(ray)).isNull();
        assertThat(Hits.closest(subject(), ray, Double.POSITIVE_INFINITY)).isNull();
        assertThat(Hits.visited(subject(), ray, Double.POSITIVE_INFINITY)).isEmpty();
    }

    @Test
    @DisplayName("contract: closestHit is the nearest of findGeoIntersections (same geometry, same t)")
    default void closestHitIsTheNearestListedIntersection() {
        int hits = 0;
        for (Ray ray : randomRays()) {
            List<Visit> listed = Hits.listed(subject(), ray, Double.POSITIVE_INFINITY);
            Visit closest = Hits.closest(subject(), ray, Double.POSITIVE_INFINITY);
            if (listed.isEmpty()) {
                assertThat(closest).as("closest hit for %s, which the list API misses", ray).isNull();
                continue;
            }
            ++hits;
            assertThat(closest).as("closest hit for %s, listed %s", ray, listed).isNotNull();
            assertThat(closest.geometry()).as("closest geometry for %s", ray).isSameAs(listed.get(0).geometry());
            assertThat(closest.t()).as("closest distance for %s", ray).isCloseTo(listed.get(0).t(), within(T_TOLERANCE));
        }
        assertThat(hits).as("random rays that hit (the test must not be vacuous)").isGreaterThan(RAY_COUNT / 10);
    }

    @Test
    @DisplayName("contract: visitHits visits exactly the intersections the list API returns")
    default void visitHitsVisitsExactlyTheListedIntersections() {
        for (Ray ray : randomRays())
            Hits.assertSameVisits(Hits.visited(subject(), ray, Double.POSITIVE_INFINITY),
                    Hits.listed(subject(), ray, Double.POSITIVE_INFINITY), T_TOLERANCE, "visitHits vs list for " + ray);
    }

    @Test
    @DisplayName("contract: a hit just inside maxDistance counts, one just outside does not, one exactly at it counts")
    default void maxDistanceClipsAtTheBoundary() {
        Ray ray = knownHit();
        List<Visit> all = Hits.listed(subject(), ray, Double.POSITIVE_INFINITY);
        double first = all.get(0).t();
        double eps = 1e-6;
        assertThat(subject().findGeoIntersections(ray, first - eps)).as("just outside").isNull();
        assertThat(Hits.visited(subject(), ray, first - eps)).as("any-hit walk just outside").isEmpty();
        assertThat(Hits.closest(subject(), ray, first - eps)).as("closest hit with tMax just short").isNull();

        long within = all.stream().filter(v -> v.t() <= first + eps).count();
        assertThat(subject().findGeoIntersections(ray, first + eps)).as("just inside").hasSize((int) within);
        assertThat(Hits.visited(subject(), ray, first + eps)).as("any-hit walk just inside").hasSize((int) within);
        assertThat(Hits.closest(subject(), ray, first + eps)).as("closest hit with tMax just beyond").isNotNull();
        assertThat(subject().findGeoIntersections(ray, first)).as("exactly at maxDistance (course rule: included)").isNotNull();
        assertThat(Hits.visited(subject(), ray, first)).as("any-hit walk exactly at maxDistance").isNotEmpty();
    }

    @Test
    @DisplayName("contract: maxDistance keeps exactly the hits not farther than it, for random rays")
    default void maxDistanceIsHonouredForRandomRays() {
        Random rnd = new Random(0x5EED_0002L);
        int clipped = 0;
        for (Ray ray : randomRays()) {
            List<Visit> all = Hits.listed(subject(), ray, Double.POSITIVE_INFINITY);
            if (all.isEmpty()) continue;
            double max = all.get(all.size() - 1).t() * 1.2 * rnd.nextDouble();
            // A hit within rounding of the bound could fall either side: choose another bound.
            if (all.stream().anyMatch(v -> Math.abs(v.t() - max) < 1e-7)) continue;
            List<Visit> expected = all.stream().filter(v -> v.t() < max).toList();
            clipped += all.size() - expected.size();
            Hits.assertSameVisits(Hits.listed(subject(), ray, max), expected, T_TOLERANCE, "list within " + max + " for " + ray);
            Hits.assertSameVisits(Hits.visited(subject(), ray, max), expected, T_TOLERANCE, "walk within " + max + " for " + ray);
            Visit closest = Hits.closest(subject(), ray, max);
            if (expected.isEmpty()) assertThat(closest).as("closest within %s for %s", max, ray).isNull();
            else assertThat(closest.t()).as("closest within %s for %s", max, ray).isCloseTo(expected.get(0).t(), within(T_TOLERANCE));
        }
        assertThat(clipped).as("hits removed by the bound (the test must not be vacuous)").isPositive();
    }

    @Test
    @DisplayName("contract: every course year's query (findGeo…, calculate…, calc…) lists the same hits, each year's record type")
    default void everyYearsQueryListsTheSameHits() {
        Random rnd = new Random(0x5EED_0003L);
        int hits = 0;
        for (Ray ray : randomRays()) {
            double max = rnd.nextBoolean() ? Double.POSITIVE_INFINITY : 4 * extent() * rnd.nextDouble();
            List<Intersectable.GeoPoint> geoPoints = subject().findGeoIntersections(ray, max);
            List<Intersectable.Intersection> calculated = subject().calculateIntersections(ray, max);
            List<Intersectable.Intersection> calc = subject().calcIntersections(ray, max);
            if (geoPoints == null) {
                assertThat(calculated).as("calculateIntersections for %s within %s", ray, max).isNull();
                assertThat(calc).as("calcIntersections for %s within %s", ray, max).isNull();
                continue;
            }
            ++hits;
            List<Intersectable.Intersection> expected = geoPoints.stream()
                    .map(gp -> new Intersectable.Intersection(gp.geometry, gp.point)).toList();
            assertThat(calculated).as("calculateIntersections for %s within %s", ray, max).isEqualTo(expected);
            assertThat(calc).as("calcIntersections for %s within %s", ray, max).isEqualTo(expected);
            assertThat(calc).allSatisfy(i -> assertThat(i.material).isSameAs(i.geometry.getMaterial()));
            assertThat(geoPoints).as("findGeoIntersections keeps plain GeoPoint records")
                    .allSatisfy(gp -> assertThat(gp).isExactlyInstanceOf(Intersectable.GeoPoint.class));
        }
        assertThat(hits).as("random rays that hit (the test must not be vacuous)").isGreaterThan(RAY_COUNT / 20);
    }

    @Test
    @DisplayName("contract: normals at hit points are unit length")
    default void normalsAtHitPointsAreUnitLength() {
        for (Ray ray : randomRays()) {
            List<Intersectable.GeoPoint> points = subject().findGeoIntersections(ray);
            if (points != null)
                for (Intersectable.GeoPoint gp : points)
                    assertThat(gp.geometry.getNormal(gp.point).length()).as("normal length at %s", gp).isCloseTo(1, within(1e-9));
            Hit hit = new Hit().reset(Double.POSITIVE_INFINITY);
            if (subject().closestHit(ray, hit))
                assertThat(hit.normal(hit.point(ray)).length()).as("closest-hit normal length for %s", ray).isCloseTo(1, within(1e-9));
        }
    }

    @Test
    @DisplayName("contract: every hit lies inside the bounding box (or there is none, when unbounded)")
    default void hitsLieInsideTheBoundingBox() {
        BoundingBox box = subject().getBoundingBox();
        if (!bounded()) {
            assertThat(box).as("an unbounded subject has no box").isNull();
            return;
        }
        assertThat(box).as("bounding box").isNotNull();
        for (Ray ray : randomRays()) {
            List<Point> points = subject().findIntersections(ray);
            if (points == null) continue;
            for (Point p : points) {
                double tol = 1e-9 * (1 + Math.abs(p.getX()) + Math.abs(p.getY()) + Math.abs(p.getZ()));
                assertThat(p.getX()).as("x of %s in %s", p, box).isBetween(box.getMinX() - tol, box.getMaxX() + tol);
                assertThat(p.getY()).as("y of %s in %s", p, box).isBetween(box.getMinY() - tol, box.getMaxY() + tol);
                assertThat(p.getZ()).as("z of %s in %s", p, box).isBetween(box.getMinZ() - tol, box.getMaxZ() + tol);
            }
        }
    }

    @Test
    @DisplayName("contract: a visitor returning false stops the walk at once")
    default void visitorCanStopTheWalk() {
        int[] visits = { 0 };
        boolean completed = subject().visitHits(knownHit(), Double.POSITIVE_INFINITY, (g, t) -> {
            ++visits[0];
            return false;
        });
        assertThat(completed).isFalse();
        assertThat(visits[0]).isEqualTo(1);
    }
}
