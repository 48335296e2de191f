package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.BvhTest.Scene;
import geometries.Hits.Visit;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The vector walk of wide nodes ({@link VectorWalk}) against the scalar walk of binary nodes, on
 * trees built alike: the same closest hit (the same geometry, primitive and distance to the bit)
 * and the same any-hit visits in the same order, for every ray. So the choice of walk can change
 * a render's speed, never its image. The test JVM reads {@code jdk.incubator.vector} (the pom's
 * Surefire options); the vector walk is emulated where the CPU's vectors are narrower.
 */
@DisplayName("the vector walk answers exactly as the scalar walk")
class WideWalkTest {
    private static final int RAYS = 3000;

    private static Bvh scalar(Geometries g) {
        return Bvh.build(g, 1, 4096, true, null);
    }

    private static Bvh vector(Geometries g) {
        assertThat(ModuleLayer.boot().findModule("jdk.incubator.vector"))
                .as("the tests run with --add-modules jdk.incubator.vector (the pom's test.jvm.args)").isPresent();
        return Bvh.build(g, 1, 4096, true, VectorWalk.anyCpu());
    }

    /**
     * A tree walked in scalar code that gets its wide part between two rays ({@link Bvh#widen}),
     * as a render's tree does once its vector walk is compiled: {@link #later} widens it.
     */
    private static Bvh widenedLater(Geometries g) {
        return Bvh.build(g, 1, 4096, true, null);
    }

    /** Widens {@code tree} at the middle of the rays, {@code i} being the ray's number. */
    private static void later(Bvh tree, int i, int rays) {
        if (i != rays / 2) return;
        assertThat(tree.wideNodes()).as("before").isNull();
        tree.widen(VectorWalk.anyCpu());
        assertThat(tree.wideNodes() != null || tree.nodeCount() <= 1).as("wide nodes after").isTrue();
    }

    /** The scenes of the tree's own tests, with meshes, lattices and degenerate boxes. */
    static Stream<Arguments> scenes() {
        return Stream.concat(BvhTest.searchScenes(), Stream.of(
                Arguments.of(new Scene("a 60×60 grid mesh", new Geometries(BvhTest.gridMesh(60)), new Point(30, 1, 30), 32)),
                Arguments.of(ties())));
    }

    /**
     * Every tie the rule must settle: each triangle of a 16×16 grid mesh twice (a mesh of the
     * same triangles, then one Triangle object per triangle), so that every hit has an equal
     * rival, and rays through the grid's vertices and edges, where neighbours tie too.
     */
    static Scene ties() {
        TriangleMesh flat = BvhTest.gridMesh(16);
        Geometries g = new Geometries(flat);
        for (int i = 0; i < flat.triangleCount(); ++i) {
            int[] v = flat.getTriangleIndices(i);
            g.add(new Triangle(flat.getVertex(v[0]), flat.getVertex(v[1]), flat.getVertex(v[2])));
        }
        return new Scene("a grid mesh and the same triangles again", g, new Point(8, 1, 8), 9);
    }

    /** Random rays into the scene, and rays straight down through the lattice points and half-points. */
    private static List<Ray> rays(Scene scene, long seed) {
        List<Ray> rays = new ArrayList<>(RandomScenes.rays(new Random(seed), RAYS, scene.centre(), scene.half()));
        Point c = scene.centre();
        int h = (int) Math.ceil(scene.half());
        for (int i = -2 * h; i <= 2 * h; ++i)
            for (int j = -2 * h; j <= 2 * h; j += 3)
                rays.add(new Ray(new Point(c.getX() + i / 2.0, c.getY() + 50, c.getZ() + j / 2.0), new Vector(0, -1, 0)));
        return rays;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    @DisplayName("the same closest hit for every ray: geometry, primitive and distance")
    void sameClosestHits(Scene scene) {
        Bvh s = scalar(scene.geometries()), v = vector(scene.geometries()), c = widenedLater(scene.geometries());
        Hit a = new Hit(), b = new Hit();
        int hits = 0;
        List<Ray> rays = rays(scene, 11);
        for (int i = 0; i < rays.size(); ++i) {
            Ray ray = rays.get(i);
            later(c, i, rays.size());
            boolean fa = s.closestHit(a.setRay(ray).reset(Double.POSITIVE_INFINITY));
            for (Bvh wide : List.of(v, c)) {
                String walk = wide == v ? "vector walk" : "tree widened at ray " + rays.size() / 2;
                boolean fb = wide.closestHit(b.setRay(ray).reset(Double.POSITIVE_INFINITY));
                assertThat(fb).as("%s: hit or miss for %s", walk, ray).isEqualTo(fa);
                if (!fa) continue;
                assertThat(b.geometry).as("%s: geometry for %s", walk, ray).isSameAs(a.geometry);
                assertThat(b.primitive).as("%s: primitive for %s", walk, ray).isEqualTo(a.primitive);
                assertThat(Double.doubleToRawLongBits(b.t)).as("%s: distance for %s", walk, ray)
                        .isEqualTo(Double.doubleToRawLongBits(a.t));
            }
            if (fa) ++hits;
        }
        assertThat(hits).as("rays that hit (the test must not be vacuous)").isGreaterThan(RAYS / 10);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    @DisplayName("the same any-hit visits in the same order, within random distances")
    void sameVisits(Scene scene) {
        Bvh s = scalar(scene.geometries()), v = vector(scene.geometries()), c = widenedLater(scene.geometries());
        Random rnd = new Random(5);
        int visits = 0;
        List<Ray> rays = rays(scene, 12);
        for (int i = 0; i < rays.size(); ++i) {
            Ray ray = rays.get(i);
            later(c, i, rays.size());
            double max = rnd.nextBoolean() ? Double.POSITIVE_INFINITY : 3 * scene.half() * rnd.nextDouble();
            List<Visit> expected = Hits.visited(s, ray, max);
            assertThat(Hits.visited(v, ray, max)).as("visits within %s for %s", max, ray).containsExactlyElementsOf(expected);
            assertThat(Hits.visited(c, ray, max)).as("tree widened at the middle ray: visits within %s for %s", max, ray)
                    .containsExactlyElementsOf(expected);
            visits += expected.size();
        }
        assertThat(visits).as("visits (the test must not be vacuous)").isGreaterThan(RAYS / 20);
    }

    @Test
    @DisplayName("the wide nodes cost 32 bytes a child, beside the binary ones (and the lanes' copy, TriangleLanesTest)")
    void wideBytes() {
        Geometries g = new Geometries(BvhTest.gridMesh(20));
        WideNodes wide = vector(g).wideNodes();
        assertThat(wide.bytes()).as("bytes of the wide nodes").isEqualTo(wide.count * 8L * wide.width * Float.BYTES)
                .isPositive();
        long extra = vector(g).indexBytes() - scalar(g).indexBytes();
        assertThat(extra).as("what the tree counts for them and the lanes' copy")
                .isEqualTo(wide.bytes() + scalar(g).primitiveTotal() * (long) BvhLeaf.PACKED * Double.BYTES);
    }

    @Test
    @DisplayName("a tree smaller than the walk takes keeps binary nodes only (walked in scalar code), a larger one gets wide nodes")
    void smallTreesStayScalar() {
        assumeTrue(Vectorization.walk() != null, "no vector walk on this CPU or JVM: " + Bvh.walkDescription());
        WideWalk walk = Vectorization.walk(); // this CPU's walk, with the render's threshold
        int side = (int) Math.ceil(Math.sqrt(walk.minPrimitives() / 2.0)) + 1; // 2·side² triangles ≥ the threshold
        Geometries big = new Geometries(BvhTest.gridMesh(side));
        assertThat(Bvh.build(big, 1, 4096, true, walk).indexBytes()).isGreaterThan(scalar(big).indexBytes());
        if (walk.minPrimitives() > 1) {
            Geometries small = new Geometries(new Sphere(new Point(0, 0, 0), 1), new Sphere(new Point(3, 0, 0), 1),
                    new Sphere(new Point(6, 0, 0), 1));
            assertThat(Bvh.build(small, 1, 4096, true, walk).indexBytes()).isEqualTo(scalar(small).indexBytes());
        }
    }

    @Test
    @DisplayName("the vector walk allocates nothing per ray once compiled (AllocationTest's bound: 16 bytes), closest and any"
            + " hit, in a fresh JVM")
    void allocatesNothingPerRay() throws Exception {
        assumeTrue(java.lang.management.ManagementFactory.getThreadMXBean() instanceof com.sun.management.ThreadMXBean,
                "this JVM counts no allocation per thread");
        assumeTrue(Vectorization.walk() != null, "no vector walk on this CPU or JVM: " + Bvh.walkDescription());
        assumeTrue(VectorWarmUp.optimizingCompiler(), "this JVM does not compile with C2");
        // In a JVM of its own (FreshJvm says why): its walk is compiled within a second or so.
        double least = Double.parseDouble(FreshJvm.run(WideWalkTest.class, FreshJvm.withVectorModule()));
        assertThat(least).as("bytes allocated per ray (a closest-hit and an any-hit query)").isLessThan(16);
    }

    /** Prints the least bytes allocated per ray by the vector walk over passes of the same rays, for the case above. */
    public static void main(String[] args) {
        System.out.println(leastBytesPerRay());
    }

    /**
     * Passes of the same rays until the walk runs compiled (the interpreter makes every vector an
     * object): the least of the passes after the first 30 is the compiled walk's. A loaded machine
     * compiles later, so the passes go on until one is under the bound, for up to two minutes: a walk
     * that never stops allocating gives the least it reached.
     */
    private static double leastBytesPerRay() {
        var threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        Scene scene = new Scene("a 60×60 grid mesh", new Geometries(BvhTest.gridMesh(60)), new Point(30, 1, 30), 32);
        Bvh tree = vector(scene.geometries());
        List<Ray> rays = rays(scene, 14);
        double[] rayDoubles = new double[rays.size() * 6];
        for (int i = 0; i < rays.size(); ++i) {
            Ray r = rays.get(i);
            double[] d = { r.getHead().getX(), r.getHead().getY(), r.getHead().getZ(), r.getDirection().getX(),
                    r.getDirection().getY(), r.getDirection().getZ() };
            System.arraycopy(d, 0, rayDoubles, i * 6, 6);
        }
        Hit hit = new Hit();
        HitVisitor count = (g, t) -> true;
        double least = Double.POSITIVE_INFINITY;
        long deadline = System.nanoTime() + java.util.concurrent.TimeUnit.MINUTES.toNanos(2);
        for (int pass = 0; pass <= 30 || !(least < 16) && System.nanoTime() < deadline; ++pass) {
            long before = threads.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < rays.size(); ++i) {
                int o = i * 6;
                hit.setRay(rayDoubles[o], rayDoubles[o + 1], rayDoubles[o + 2], rayDoubles[o + 3], rayDoubles[o + 4],
                        rayDoubles[o + 5]).reset(Double.POSITIVE_INFINITY);
                tree.closestHit(hit);
                tree.visitHits(hit, 20, count);
            }
            if (pass >= 30) least = Math.min(least, (threads.getCurrentThreadAllocatedBytes() - before) / (double) rays.size());
        }
        return least;
    }

    @Nested
    @DisplayName("the tie rule")
    class TieRule {
        @Test
        @DisplayName("the scene of ties ties: every hit has a rival at the same distance (what the walks' agreement settles)")
        void everyHitTies() {
            Scene scene = ties();
            Bvh s = scalar(scene.geometries());
            Hit hit = new Hit();
            int ties = 0;
            for (Ray ray : rays(scene, 13)) {
                if (!s.closestHit(hit.setRay(ray).reset(Double.POSITIVE_INFINITY))) continue;
                // The triangle's twin, packed alike, is hit at the same distance to the bit.
                List<Visit> all = Hits.visited(s, ray, hit.t);
                long rivals = all.stream().filter(x -> x.t() == hit.t).count();
                assertThat(rivals).as("hits at the winner's distance for %s", ray).isGreaterThanOrEqualTo(2);
                ++ties;
            }
            assertThat(ties).isGreaterThan(RAYS / 10);
        }

        @Test
        @DisplayName("a hit found before the walk wins a tie against the tree")
        void earlierHitWins() {
            Triangle t = new Triangle(new Point(0, 0, 0), new Point(4, 0, 0), new Point(0, 0, 4));
            Triangle twin = new Triangle(new Point(0, 0, 0), new Point(4, 0, 0), new Point(0, 0, 4));
            Geometries g = new Geometries(twin);
            for (Bvh tree : List.of(scalar(g), vector(g))) {
                Hit hit = new Hit().setRay(new Ray(new Point(1, 5, 1), new Vector(0, -1, 0)));
                hit.reset(Double.POSITIVE_INFINITY);
                assertThat(t.closestHit(hit)).isTrue();
                assertThat(tree.closestHit(hit)).as("the tree finds nothing nearer").isFalse();
                assertThat(hit.geometry).isSameAs(t);
            }
        }
    }
}
