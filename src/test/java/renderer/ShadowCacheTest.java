package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.CountingGeometries;
import geometries.Geometry;
import geometries.Hit;
import geometries.Intersectable;
import geometries.LeanQueries;
import geometries.ShadowIndex;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import primitives.Double3;
import primitives.Material;
import primitives.Point;

/** {@link ShadowCache}: the last opaque occluder per light is asked first, and the answer never changes. */
class ShadowCacheTest {
    /** @return the walk's product of kT, channel by channel */
    private static double[] channels(Transmittance t) {
        return new double[] { t.product.r(), t.product.g(), t.product.b() };
    }

    /** A user's sphere: never kept, as its class may answer differently from one call to the next. */
    private static final class UserSphere extends Sphere {
        UserSphere(Point c, double r) {
            super(c, r);
        }
    }

    private static final double THRESHOLD = RayTracerBasic.MIN_CALC_COLOR_K;

    /**
     * A cloud of shapes, opaque and partly transparent, library and user shapes and a mesh (both
     * never kept), in a cube of side 20 around the origin.
     */
    private static CountingGeometries cloud(long seed) {
        Random rnd = new Random(seed);
        CountingGeometries g = new CountingGeometries();
        for (int i = 0; i < 300; ++i) {
            Point c = new Point(rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10));
            int kind = rnd.nextInt(4);
            Double3 kT = switch (kind) {
            case 0, 1 -> Double3.ZERO; // opaque
            case 2 -> new Double3(rnd.nextDouble(0.2, 0.9)); // partly transparent
            default -> new Double3(0, 0.5, 0); // opaque but in one channel: never kept
            };
            Material m = new Material().setKt(kT);
            Geometry shape = switch (i % 5) {
            case 0, 1 -> new Sphere(c, rnd.nextDouble(0.3, 1.5));
            case 2 -> new Triangle(c, c.add(new primitives.Vector(rnd.nextDouble(1, 3), 0, 0.2)),
                    c.add(new primitives.Vector(0.1, rnd.nextDouble(1, 3), 0)));
            case 3 -> new UserSphere(c, rnd.nextDouble(0.3, 1.5));
            default -> new TriangleMesh(new double[] { c.getX(), c.getY(), c.getZ(), c.getX() + 2, c.getY(), c.getZ(),
                    c.getX(), c.getY() + 2, c.getZ() + 0.3 }, new int[] { 0, 1, 2 });
            };
            g.add(shape.setMaterial(m));
        }
        return g;
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = { 1, 2, 3 })
    @DisplayName("coherent shadow rays toward two lights: the same product of kT as the walk alone, bit for bit, and some answered without it")
    void sameAsTheWalk(long seed) {
        CountingGeometries world = cloud(seed);
        ShadowCache cache = new ShadowCache();
        Transmittance cached = new Transmittance(THRESHOLD), walked = new Transmittance(THRESHOLD);
        RayHit a = new RayHit(), b = new RayHit();
        Random rnd = new Random(seed + 100);
        int rays = 3000, blocked = 0;
        double px = 0, py = 0, pz = 0;
        for (int i = 0; i < rays; ++i) {
            // Points along a wandering path, shadowed toward two lights: neighbours share occluders.
            px = Math.max(-12, Math.min(12, px + rnd.nextGaussian()));
            py = Math.max(-12, Math.min(12, py + rnd.nextGaussian()));
            pz = Math.max(-12, Math.min(12, pz + rnd.nextGaussian()));
            int light = i % 2;
            double lx = light == 0 ? 40 : -30, ly = 50, lz = light == 0 ? 20 : -45;
            double dx = lx - px, dy = ly - py, dz = lz - pz;
            double distance = i % 3 == 0 ? Double.POSITIVE_INFINITY : Math.sqrt(dx * dx + dy * dy + dz * dz);
            a.ray(px, py, pz, dx, dy, dz);
            b.ray(px, py, pz, dx, dy, dz);
            int walks = world.walks();
            cache.trace(world, a, distance, light, null, cached);
            if (world.walks() == walks) ++blocked;
            LeanQueries.visitHits(world, b, distance, walked.reset());
            assertThat(channels(cached)).as("ray %d", i)
                    .containsExactly(channels(walked));
        }
        assertThat(blocked).as("shadow rays answered by the cache (the test must not be vacuous)").isGreaterThan(rays / 20);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = { 4, 5 })
    @DisplayName("with the lights' buffers, over a tree: the same product of kT as the walk alone, bit for bit, and most lit rays answered by the buffer")
    void withShadowIndexes(long seed) {
        CountingGeometries shapes = new CountingGeometries();
        Random rnd = new Random(seed);
        for (int i = 0; i < 200; ++i) { // library shapes only: a user's shape keeps a tree from having buffers
            Point c = new Point(rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10));
            Double3 kT = rnd.nextBoolean() ? Double3.ZERO : new Double3(rnd.nextDouble(0.2, 0.9));
            shapes.add((i % 2 == 0 ? new Sphere(c, rnd.nextDouble(0.3, 1.2))
                    : new Triangle(c, c.add(new primitives.Vector(rnd.nextDouble(1, 3), 0, 0.2)),
                            c.add(new primitives.Vector(0.1, rnd.nextDouble(1, 3), 0)))).setMaterial(new Material().setKt(kT)));
        }
        Intersectable world = geometries.Bvh.build(shapes);
        double[][] lights = { { 40, 50, 20 }, { -3, 2, 4 } };
        ShadowIndex[] indexes = new ShadowIndex[lights.length];
        for (int i = 0; i < lights.length; ++i)
            indexes[i] = LeanQueries.shadowIndexFrom(world, lights[i][0], lights[i][1], lights[i][2]);
        ShadowCache cache = new ShadowCache();
        Transmittance traced = new Transmittance(THRESHOLD), walked = new Transmittance(THRESHOLD);
        RayHit a = new RayHit(), b = new RayHit();
        int lit = 0, answered = 0;
        for (int i = 0; i < 4000; ++i) {
            int light = i % 2;
            double px = rnd.nextDouble(-12, 12), py = rnd.nextDouble(-12, 12), pz = rnd.nextDouble(-12, 12);
            double dx = lights[light][0] - px, dy = lights[light][1] - py, dz = lights[light][2] - pz;
            double distance = Math.sqrt(dx * dx + dy * dy + dz * dz);
            a.ray(px, py, pz, dx, dy, dz);
            b.ray(px, py, pz, dx, dy, dz);
            cache.trace(world, a, distance, light, indexes[light], traced);
            LeanQueries.visitHits(world, b, distance, walked.reset());
            assertThat(channels(traced)).as("ray %d", i).containsExactly(channels(walked));
            if (channels(walked)[0] == 1 && walked.opaque == null) {
                ++lit;
                if (indexes[light].clear(a, distance)) ++answered;
            }
        }
        assertThat(lit).as("lit rays").isGreaterThan(400);
        assertThat(answered).as("lit rays the buffers answered, of %d", lit).isGreaterThan(lit * 9 / 10);
    }

    @Nested
    @DisplayName("what is kept")
    class Kept {
        private final CountingGeometries world = new CountingGeometries();
        private final Hit ray = new RayHit().ray(0, 0, -10, 0, 0, 1);
        private final Transmittance tr = new Transmittance(THRESHOLD);
        private final ShadowCache cache = new ShadowCache();

        /** Traces the ray twice toward light 0: @return whether the second time was answered without a walk */
        private boolean secondAnswered() {
            cache.trace(world, ray, 100, 0, null, tr);
            int walks = world.walks();
            cache.trace(world, ray, 100, 0, null, tr);
            assertThat(channels(tr)).containsExactly(0, 0, 0);
            return world.walks() == walks;
        }

        @Test
        @DisplayName("a library sphere that stopped the ray answers the next one")
        void librarySphere() {
            world.add(new Sphere(Point.ZERO, 1));
            assertThat(secondAnswered()).isTrue();
        }

        @Test
        @DisplayName("a user's sphere and a mesh are asked through the walk every time")
        void notKept() {
            world.add(new UserSphere(Point.ZERO, 1));
            assertThat(secondAnswered()).isFalse();
            CountingGeometries meshWorld = new CountingGeometries();
            meshWorld.add(new TriangleMesh(new double[] { -1, -1, 0, 2, -1, 0, -1, 2, 0 }, new int[] { 0, 1, 2 }));
            cache.trace(meshWorld, ray, 100, 0, null, tr);
            int walks = meshWorld.walks();
            cache.trace(meshWorld, ray, 100, 0, null, tr);
            assertThat(meshWorld.walks()).isEqualTo(walks + 1);
        }

        @Test
        @DisplayName("a kept shape made transparent since is not trusted: the walk gives its kT")
        void madeTransparent() {
            Sphere s = new Sphere(Point.ZERO, 1);
            world.add(s);
            cache.trace(world, ray, 100, 0, null, tr);
            s.setMaterial(new Material().setKt(0.5));
            cache.trace(world, ray, 100, 0, null, tr);
            assertThat(tr.product.r()).isEqualTo(0.25); // the ray crosses the sphere's surface twice
        }

        @Test
        @DisplayName("each light keeps its own occluder; a ray the kept one does not cross is walked")
        void perLight() {
            world.add(new Sphere(Point.ZERO, 1));
            cache.trace(world, ray, 100, 0, null, tr);
            int walks = world.walks();
            cache.trace(world, ray, 100, 1, null, tr); // another light: nothing kept for it yet
            assertThat(world.walks()).isEqualTo(walks + 1);
            Hit past = new RayHit().ray(5, 0, -10, 0, 0, 1); // misses the sphere
            cache.trace(world, past, 100, 0, null, tr);
            assertThat(world.walks()).isEqualTo(walks + 2);
            assertThat(tr.product.r()).isEqualTo(1);
        }

        @Test
        @DisplayName("an occluder beyond the light does not count: the distance rule is the walk's")
        void beyondTheLight() {
            world.add(new Sphere(Point.ZERO, 1));
            cache.trace(world, ray, 100, 0, null, tr);
            cache.trace(world, ray, 8.5, 0, null, tr); // the sphere is entered at 9
            assertThat(tr.product.r()).isEqualTo(1);
        }
    }
}
