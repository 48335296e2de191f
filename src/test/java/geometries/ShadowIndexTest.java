package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Kernels;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * {@link ShadowIndex}, the light buffer: it answers "clear" only where the tree's any-hit walk
 * would visit nothing, for the shadow rays a render makes toward its light and for any other ray;
 * and it answers so for most lit points, or it would only cost.
 */
class ShadowIndexTest {
    private static final Point CENTRE = new Point(0, 5, 0);

    /** Random bounded shapes of every kind above a floor plane (unbounded), and a small mesh. */
    private static Bvh scene(long seed, int shapes) {
        Random rnd = new Random(seed);
        Geometries g = new Geometries();
        for (Geometry shape : RandomScenes.boundedShapes(rnd, shapes, CENTRE, 8, 1.5))
            g.add(shape);
        g.add(new Plane(new Point(0, -4, 0), new Vector(0, 1, 0)));
        g.add(new TriangleMesh(new double[] { -3, 0, -3, 3, 0, -3, 3, 0, 3, -3, 0, 3 }, new int[] { 0, 1, 2, 0, 2, 3 }));
        return Bvh.build(g);
    }

    /** How many visits the any-hit walk gives for the query. */
    private static int walkVisits(Bvh tree, Hit query, double maxDistance) {
        int[] visits = { 0 };
        LeanQueries.visitHits(tree, query, maxDistance, (geometry, t) -> {
            ++visits[0];
            return true;
        });
        return visits[0];
    }

    /** Tallies of the index's answers against the walk's. */
    private static final class Tally {
        int walkClear, indexClear, crossed;

        /** Asks both; fails at once if the index says clear where the walk visits something. */
        void ask(ShadowIndex index, Bvh tree, Hit query, double maxDistance, Object what) {
            boolean clear = index.clear(query, maxDistance);
            int visits = walkVisits(tree, query, maxDistance);
            assertThat(clear && visits > 0).as("the index said clear, the walk visited %d hits: %s", visits, what).isFalse();
            if (visits == 0) ++walkClear;
            else ++crossed;
            if (clear) ++indexClear;
        }
    }

    /**
     * Shadow rays as the renderer makes them: from each surface point that a random ray from the
     * camera's side hits, toward the light, the head moved off the surface ({@code Hit#setRay}).
     */
    private static Tally shadowRays(Bvh tree, ShadowIndex index, Point light, double[] parallel, long seed) {
        Random rnd = new Random(seed);
        Tally tally = new Tally();
        double[] l = new double[3];
        for (Ray eye : RandomScenes.rays(rnd, 4000, CENTRE, 9)) {
            Hit hit = Hit.of(eye).reset(Double.POSITIVE_INFINITY);
            if (!LeanQueries.closestHit(tree, hit)) continue;
            hit.computeSurface();
            double px = hit.pointX(), py = hit.pointY(), pz = hit.pointZ();
            double distance;
            if (light != null) { // PointLight.getL and getDistance's arithmetic
                double dx = px - light.getX(), dy = py - light.getY(), dz = pz - light.getZ();
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                l[0] = dx / len;
                l[1] = dy / len;
                l[2] = dz / len;
                distance = len;
            } else {
                System.arraycopy(parallel, 0, l, 0, 3);
                distance = Double.POSITIVE_INFINITY;
            }
            Hit shadow = new Hit().setRay(px, py, pz, -l[0], -l[1], -l[2], hit.normalX(), hit.normalY(), hit.normalZ());
            tally.ask(index, tree, shadow, distance, shadow.ray());
        }
        return tally;
    }

    /** Both kinds of ray were met, and the index proved nine in ten of the lit ones clear (it is not vacuous). */
    private static void assertIndexAnswers(Tally tally) {
        assertThat(tally.crossed).as("shadowed rays").isGreaterThan(200);
        assertThat(tally.walkClear).as("lit rays").isGreaterThan(50);
        assertThat(tally.indexClear).as("lit rays the index proved clear, of %d", tally.walkClear)
                .isGreaterThanOrEqualTo(tally.walkClear * 9 / 10);
    }

    @Nested
    @DisplayName("shadow rays toward the index's light")
    class ShadowRays {
        @ParameterizedTest(name = "seed {0}")
        @ValueSource(longs = { 1, 2, 3, 4 })
        @DisplayName("a point light above, one among the shapes: clear only where the walk visits nothing, and for most such rays")
        void pointLight(long seed) {
            Bvh tree = scene(seed, 60);
            for (Point light : List.of(new Point(4, 30, -6), new Point(1, 6, 2))) {
                ShadowIndex index = LeanQueries.shadowIndexFrom(tree, light.getX(), light.getY(), light.getZ());
                assertThat(index).as("the index of a light at %s", light).isNotNull();
                Tally tally = shadowRays(tree, index, light, null, seed);
                assertIndexAnswers(tally);

            }
        }

        @ParameterizedTest(name = "seed {0}")
        @ValueSource(longs = { 1, 2, 3, 4 })
        @DisplayName("a directional light: the same")
        void directionalLight(long seed) {
            Bvh tree = scene(seed, 60);
            double[] l = new double[3];
            Vector direction = new Vector(-1, -2.5, -1.5).normalize();
            Kernels.normalize(-direction.getX(), -direction.getY(), -direction.getZ(), l); // as Hit.setRay makes it
            ShadowIndex index = LeanQueries.shadowIndexAlong(tree, l[0], l[1], l[2]);
            assertThat(index).isNotNull();
            Tally tally = shadowRays(tree, index, null, new double[] { direction.getX(), direction.getY(), direction.getZ() }, seed);
            assertIndexAnswers(tally);
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = { 5, 6 })
    @DisplayName("any other ray, any bound: never clear where the walk visits a hit")
    void anyRay(long seed) {
        Bvh tree = scene(seed, 40);
        Random rnd = new Random(seed);
        ShadowIndex point = LeanQueries.shadowIndexFrom(tree, 2, 9, 1);
        double[] d = new double[3];
        Kernels.normalize(0.3, 1, 0.2, d);
        ShadowIndex parallel = LeanQueries.shadowIndexAlong(tree, d[0], d[1], d[2]);
        Tally tally = new Tally();
        for (Ray ray : RandomScenes.rays(rnd, 3000, CENTRE, 9)) {
            double bound = rnd.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : rnd.nextDouble(0.1, 30);
            tally.ask(point, tree, Hit.of(ray), bound, ray);
            tally.ask(parallel, tree, Hit.of(ray), bound, ray);
            // A ray ending right by the light, and one along the directional light from anywhere.
            Point head = ray.getHead();
            Vector toLight = new Point(2, 9, 1).subtract(head);
            if (toLight.length() > 1) {
                Ray toward = new Ray(head, toLight);
                tally.ask(point, tree, Hit.of(toward), toLight.length() + rnd.nextDouble(-0.3, 0.3), toward);
            }
            Hit along = new Hit().setRay(head.getX(), head.getY(), head.getZ(), d[0], d[1], d[2]);
            tally.ask(parallel, tree, along, bound, along.ray());
        }
        assertThat(tally.indexClear).as("rays the index proved clear (the test must not be vacuous)").isGreaterThan(500);
    }

    @Test
    @DisplayName("a shape beside the light's own ray, within the shadow ray's move off the surface: the ray is not clear")
    void besideTheLightsRay() {
        // The point (0, 0, 0) under a light at (0, 10, 0), on a surface tilted 45°: the shadow ray
        // starts 0.1 along the normal, at x = 0.0707, and runs parallel to the light's ray x = 0.
        // A small sphere near the light lies on the shadow ray only, in another direction from the light.
        Sphere small = new Sphere(new Point(0.0707, 9.9, 0), 0.02);
        Bvh tree = Bvh.build(new Geometries(small, new Sphere(new Point(-5, 3, 0), 1)));
        ShadowIndex index = LeanQueries.shadowIndexFrom(tree, 0, 10, 0);
        double n = Math.sqrt(0.5);
        Hit shadow = new Hit().setRay(0, 0, 0, 0, 1, 0, n, n, 0);
        assertThat(shadow.headX()).isEqualTo(0.1 * n);
        assertThat(walkVisits(tree, shadow, 10)).isPositive();
        assertThat(index.clear(shadow, 10)).isFalse();
        Hit beside = new Hit().setRay(0, 0, 0, 0, 1, 0, -n, n, 0); // moved to x = -0.0707: clear
        assertThat(index.clear(beside, 10)).isTrue();
    }

    @Test
    @DisplayName("rays along the edges and corners of the cube of directions, where two or three faces meet: a sphere on each is found")
    void facesEdgesAndCorners() {
        Geometries spheres = new Geometries();
        List<Vector> directions = new java.util.ArrayList<>();
        for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
                for (int z = -1; z <= 1; ++z)
                    if (x != 0 || y != 0 || z != 0) directions.add(new Vector(x, y, z).normalize());
        for (Vector d : directions)
            spheres.add(new Sphere(Point.ZERO.add(d.scale(5)), 0.3));
        Bvh tree = Bvh.build(spheres);
        ShadowIndex index = LeanQueries.shadowIndexFrom(tree, 0, 0, 0);
        for (Vector d : directions) {
            Point from = Point.ZERO.add(d.scale(8));
            Hit shadow = Hit.of(new Ray(from, d.scale(-1)));
            assertThat(walkVisits(tree, shadow, 8)).as("the walk along %s", d).isPositive();
            assertThat(index.clear(shadow, 8)).as("along %s", d).isFalse();
            // Just past the light, outward again: nothing there.
            Hit beyond = Hit.of(new Ray(Point.ZERO.add(d.scale(12)), d.scale(-1)));
            assertThat(index.clear(beyond, 12)).as("the ray from 12 along %s", d).isFalse(); // crosses the sphere at 5 too
        }
    }

    @Test
    @DisplayName("a user's shape: its cells are left to the walk, so the index never asks it; the other cells answer")
    void userShape() {
        int[] asked = { 0 };
        Sphere user = new Sphere(new Point(5, 0, 0), 1) {
            @Override
            protected java.util.List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                ++asked[0];
                return super.findGeoIntersectionsHelper(ray, maxDistance);
            }
        };
        Bvh tree = Bvh.build(new Geometries(new Sphere(new Point(-5, 0, 0), 1), user));
        ShadowIndex index = LeanQueries.shadowIndexFrom(tree, 0, 10, 0);
        assertThat(index).isNotNull();
        Random rnd = new Random(8);
        int userCells = 0, answered = 0;
        for (int i = 0; i < 2000; ++i) {
            Point from = new Point(rnd.nextDouble(-8, 8), -3, rnd.nextDouble(-3, 3));
            Vector toLight = new Point(0, 10, 0).subtract(from);
            Hit shadow = Hit.of(new Ray(from, toLight));
            int before = asked[0];
            boolean clear = index.clear(shadow, toLight.length());
            assertThat(asked[0]).as("calls to the user's shape by the index").isEqualTo(before);
            if (clear) {
                ++answered;
                assertThat(walkVisits(tree, shadow, toLight.length())).isZero();
            } else if (from.getX() > 2) ++userCells;
        }
        assertThat(answered).as("rays answered away from the user's shape").isGreaterThan(500);
        assertThat(userCells).as("rays toward the user's shape, left to the walk").isGreaterThan(100);
        walkVisits(tree, Hit.of(new Ray(new Point(5, -3, 0), new Vector(0, 1, 0))), 20);
        assertThat(asked[0]).as("the walk asks the user's shape (the count works)").isPositive();
    }

    @Nested
    @DisplayName("rays that are not the index's")
    class NotItsRays {
        private final Bvh tree = scene(7, 20);

        @Test
        @DisplayName("a point light's: a ray that does not end at the light is never clear, even through empty space")
        void notEndingAtTheLight() {
            ShadowIndex index = LeanQueries.shadowIndexFrom(tree, 0, 100, 0);
            Hit up = new Hit().setRay(0, 50, 0, 0, 1, 0);
            assertThat(index.clear(up, 50)).isTrue(); // ends at the light: clear, nothing up there
            assertThat(index.clear(up, 49)).isFalse(); // ends a unit short
            assertThat(index.clear(up, Double.POSITIVE_INFINITY)).isFalse();
        }

        @Test
        @DisplayName("a directional light's: a ray along any other direction is never clear")
        void otherDirection() {
            ShadowIndex index = LeanQueries.shadowIndexAlong(tree, 0, 1, 0);
            Hit up = new Hit().setRay(0, 50, 0, 0, 1, 0);
            assertThat(index.clear(up, Double.POSITIVE_INFINITY)).isTrue();
            Hit tilted = new Hit().setRay(0, 50, 0, Math.nextUp(0.0), 1, 0);
            assertThat(index.clear(tilted, Double.POSITIVE_INFINITY)).isFalse();
        }
    }

    @Nested
    @DisplayName("not built")
    class NotBuilt {
        @Test
        @DisplayName("a world that is not a tree, or a user's shape without a box (every ray asks it)")
        void notExact() {
            Geometries list = new Geometries(new Sphere(new Point(0, 0, 0), 1));
            assertThat(LeanQueries.shadowIndexFrom(list, 0, 10, 0)).isNull();
            Geometries withUserPlane = new Geometries(new Sphere(new Point(0, 0, 0), 1),
                    new Plane(new Point(0, -5, 0), new Vector(0, 1, 0)) {
                    });
            assertThat(LeanQueries.shadowIndexFrom(Bvh.build(withUserPlane), 0, 10, 0)).isNull();
            assertThat(LeanQueries.shadowIndexAlong(Bvh.build(withUserPlane), 0, 1, 0)).isNull();
        }

        @Test
        @DisplayName("nothing bounded, or a light at infinity")
        void nothingToSort() {
            Bvh planeOnly = Bvh.build(new Geometries(new Plane(Point.ZERO, new Vector(0, 1, 0))));
            assertThat(LeanQueries.shadowIndexFrom(planeOnly, 0, 10, 0)).isNull();
            Bvh one = Bvh.build(new Geometries(new Sphere(Point.ZERO, 1)));
            assertThat(LeanQueries.shadowIndexFrom(one, 0, Double.POSITIVE_INFINITY, 0)).isNull();
            assertThat(LeanQueries.shadowIndexAlong(one, 0, 0, 0)).isNull();
        }

        @Test
        @DisplayName("a mesh of more leaves than its cells could sort")
        void tooManyLeaves() {
            int side = 200; // 2 x 200 x 200 triangles in a plane: far more leaves than 6 x 32 x 32 cells hold
            double[] positions = new double[(side + 1) * (side + 1) * 3];
            for (int i = 0, k = 0; i <= side; ++i)
                for (int j = 0; j <= side; ++j) {
                    positions[k++] = i;
                    positions[k++] = 0;
                    positions[k++] = j;
                }
            int[] indices = new int[side * side * 6];
            for (int i = 0, k = 0; i < side; ++i)
                for (int j = 0; j < side; ++j) {
                    int a = i * (side + 1) + j;
                    indices[k++] = a;
                    indices[k++] = a + 1;
                    indices[k++] = a + side + 1;
                    indices[k++] = a + 1;
                    indices[k++] = a + side + 2;
                    indices[k++] = a + side + 1;
                }
            Bvh tree = Bvh.build(new Geometries(new TriangleMesh(positions, indices)));
            assertThat(LeanQueries.shadowIndexFrom(tree, 100, 50, 100)).isNull();
        }
    }
}
