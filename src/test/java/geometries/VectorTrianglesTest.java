package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Hits.Visit;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * The vector leaf test ({@link VectorTriangles}) computes what the scalar triangle test computes,
 * to the bit: lane by lane against {@code Triangle.intersect}, and through whole walks against the
 * scalar walk on the meshes the Embree benchmark traces, ray by ray (the same hit or miss, the same
 * geometry and triangle, the same distance bits). The test JVM reads {@code jdk.incubator.vector}
 * (the pom's Surefire options); vectors the CPU lacks are emulated, with the same answers.
 */
@DisplayName("four or eight triangles in one vector step: the scalar test's answers, bit for bit")
class VectorTrianglesTest {
    private static final double ZERO = VectorTriangles.ZERO;
    /** Triangles in one step on this machine and JDK. */
    private static final int LANES = VectorTriangles.LANES.length();

    /** Doubles at and around every edge the kernel's tolerance tests have. */
    static Stream<Double> edges() {
        List<Double> xs = new ArrayList<>(List.of(0.0, -0.0, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                Double.MIN_VALUE, -Double.MIN_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, 0.5, 2.0, -3.0));
        for (double at : new double[] { ZERO, -ZERO, 1, 1 + ZERO, 1 - ZERO })
            for (int ulps = -3; ulps <= 3; ++ulps) {
                double x = at;
                for (int i = 0; i < Math.abs(ulps); ++i) x = ulps < 0 ? Math.nextDown(x) : Math.nextUp(x);
                xs.add(x);
            }
        return xs.stream();
    }

    @Nested
    @DisplayName("the tolerance tests, in the vector step's form")
    class Tolerance {
        @Test
        @DisplayName("the zero tolerance is Util's: 2^-40 is not zero, the double below it is")
        void sameTolerance() {
            assertThat(Util.isZero(ZERO)).isFalse();
            assertThat(Util.isZero(Math.nextDown(ZERO))).isTrue();
            assertThat(Util.isZero(-Math.nextDown(ZERO))).isTrue();
        }

        @ParameterizedTest(name = "x = {0}")
        @MethodSource("geometries.VectorTrianglesTest#edges")
        @DisplayName("alignZero(x) <= 0 is x < 2^-40; alignZero(x) >= 0 is x > -2^-40; alignZero(x) > 0 is x >= 2^-40")
        void oneComparisonEach(double x) {
            assertThat(x < ZERO).as("alignZero(%s) <= 0", x).isEqualTo(Util.alignZero(x) <= 0);
            assertThat(x > -ZERO).as("alignZero(%s) >= 0", x).isEqualTo(Util.alignZero(x) >= 0);
            assertThat(x >= ZERO).as("alignZero(%s) > 0", x).isEqualTo(Util.alignZero(x) > 0);
            double w = x - 1;
            assertThat(w > -ZERO).as("alignZero(%s - 1) >= 0", x).isEqualTo(Util.alignZero(x - 1) >= 0);
        }
    }

    @Nested
    @DisplayName("lane by lane: each lane's distance is Triangle.intersect's")
    class LaneByLane {
        private static final int LEAVES = 20_000;

        /** A leaf of 1 to LANES triangles near the origin, packed as a tree packs them, then laid out in lanes. */
        private static double[] leaf(Random rnd, int count, int first) {
            double[] packed = new double[(first + count) * BvhLeaf.PACKED + TriangleLanes.PADDING];
            for (int j = 0; j < count; ++j) {
                Triangle t;
                while (true) {
                    try {
                        // Sizes from 10^-4 to 10^2, slivers included: one vertex near the others' line.
                        double size = Math.pow(10, -4 + 6 * rnd.nextDouble());
                        Point a = RandomScenes.point(rnd, Point.ZERO, 1);
                        Point b = a.add(RandomScenes.direction(rnd).scale(size));
                        Point c = rnd.nextInt(4) == 0 ? a.add(b.subtract(a).scale(0.5)).add(RandomScenes.direction(rnd).scale(size * 1e-3))
                                : a.add(RandomScenes.direction(rnd).scale(size));
                        t = new Triangle(a, b, c);
                        break;
                    } catch (IllegalArgumentException degenerate) {
                        // drawn again
                    }
                }
                t.pack(0, packed, (first + j) * BvhLeaf.PACKED);
            }
            // Whatever follows the leaf: other numbers, which the lanes past the count read.
            for (int i = (first + count) * BvhLeaf.PACKED; i < packed.length; ++i) packed[i] = rnd.nextGaussian();
            for (int i = 0; i < first * BvhLeaf.PACKED; ++i) packed[i] = rnd.nextGaussian();
            return packed;
        }

        /** A ray at one of the leaf's triangles: through a vertex, an edge's point, its inside, or in its plane. */
        private static Hit rayAt(Random rnd, double[] scalar, int k) {
            int at = k * BvhLeaf.PACKED;
            Point a = new Point(scalar[at], scalar[at + 1], scalar[at + 2]);
            Vector e1 = new Vector(scalar[at + 3], scalar[at + 4], scalar[at + 5]);
            Vector e2 = new Vector(scalar[at + 6], scalar[at + 7], scalar[at + 8]);
            double u, v;
            switch (rnd.nextInt(4)) {
                case 0 -> { u = rnd.nextInt(2); v = u == 1 ? 0 : rnd.nextInt(2); } // a vertex
                case 1 -> { u = rnd.nextDouble(); v = rnd.nextBoolean() ? 0 : 1 - u; } // an edge
                default -> { u = rnd.nextDouble() * 0.6; v = rnd.nextDouble() * 0.4; } // inside or just past
            }
            Point target = a;
            if (u != 0) target = target.add(e1.scale(u));
            if (v != 0) target = target.add(e2.scale(v));
            Vector normal = e1.crossProduct(e2).normalize();
            Vector d = rnd.nextInt(20) == 0 ? e1.normalize() // in the plane: parallel, a zero determinant
                    : normal.add(RandomScenes.direction(rnd).scale(rnd.nextDouble() * 0.9)).normalize();
            if (rnd.nextBoolean()) d = d.scale(-1);
            double back = rnd.nextInt(10) == 0 ? 0 : Math.pow(10, -3 + 5 * rnd.nextDouble()); // 0: from on the triangle
            Point from = back == 0 ? target : target.add(d.scale(-back));
            return new Hit().setRay(new Ray(from, d)).reset(Double.POSITIVE_INFINITY);
        }

        @Test
        @DisplayName("random leaves of one triangle up to the lanes, rays through vertices, edges, insides and planes: the same bits, NaN for NaN")
        void sameDistances() {
            Random rnd = new Random(50);
            double[] out = new double[TriangleLanes.MAX_LANES];
            int written = 0, hits = 0;
            for (int n = 0; n < LEAVES; ++n) {
                int count = 1 + rnd.nextInt(LANES), first = rnd.nextInt(3);
                double[] packed = leaf(rnd, count, first);
                double[] scalar = packed.clone();
                TriangleLanes.arrange(packed, first, count, new double[TriangleLanes.MAX_LANES * BvhLeaf.PACKED]);
                Hit ray = rayAt(rnd, scalar, first + rnd.nextInt(count));
                double[] expected = new double[count];
                boolean any = false;
                for (int j = 0; j < count; ++j) {
                    expected[j] = Triangle.intersect(ray, scalar, (first + j) * BvhLeaf.PACKED);
                    any |= Util.alignZero(expected[j]) > 0;
                }
                java.util.Arrays.fill(out, -1);
                long may = VectorTriangles.distances(packed, first, count, ray, Double.POSITIVE_INFINITY, out);
                assertThat(may != 0).as("leaf %d: written when some triangle is hit in front", n).isEqualTo(any);
                if (may == 0) continue;
                assertThat(may >>> count).as("leaf %d: no lane past the leaf", n).isZero();
                for (int j = 0; j < count; ++j)
                    if (Util.alignZero(expected[j]) > 0 || Runtime.version().feature() >= 18)
                        assertThat(may >>> j & 1).as("leaf %d lane %d: hit in front, %s", n, j, expected[j])
                                .isEqualTo(Util.alignZero(expected[j]) > 0 ? 1L : 0L);
                ++written;
                for (int j = 0; j < count; ++j) {
                    if (Double.isNaN(expected[j])) {
                        assertThat(out[j]).as("leaf %d lane %d", n, j).isNaN();
                    } else {
                        assertThat(Double.doubleToRawLongBits(out[j])).as("leaf %d lane %d: %s against %s", n, j, out[j], expected[j])
                                .isEqualTo(Double.doubleToRawLongBits(expected[j]));
                        ++hits;
                    }
                }
            }
            assertThat(written).as("leaves with a hit (the test must not be vacuous)").isGreaterThan(LEAVES / 4);
            assertThat(hits).isGreaterThan(LEAVES / 4);
        }

        @Test
        @DisplayName("a bound below every hit writes nothing")
        void boundRulesOut() {
            Random rnd = new Random(51);
            double[] out = new double[TriangleLanes.MAX_LANES];
            for (int n = 0; n < 2000; ++n) {
                int count = 1 + rnd.nextInt(LANES);
                double[] packed = leaf(rnd, count, 0), scalar = packed.clone();
                TriangleLanes.arrange(packed, 0, count, new double[TriangleLanes.MAX_LANES * BvhLeaf.PACKED]);
                Hit ray = rayAt(rnd, scalar, rnd.nextInt(count));
                double least = Double.POSITIVE_INFINITY;
                for (int j = 0; j < count; ++j) {
                    double t = Triangle.intersect(ray, scalar, j * BvhLeaf.PACKED);
                    if (Util.alignZero(t) > 0) least = Math.min(least, t);
                }
                if (least == Double.POSITIVE_INFINITY) continue;
                assertThat(VectorTriangles.distances(packed, 0, count, ray, Math.nextDown(least), out)).isZero();
                assertThat(VectorTriangles.distances(packed, 0, count, ray, least, out)).as("a tie at the bound may win").isNotZero();
            }
        }
    }

    @Nested
    @DisplayName("a visitor that walks the tree again with the same record")
    class NestedVisit {
        @Test
        @DisplayName("sees the leaf's hits as a plain visitor does: the walk inside writes no distance the outer one still reads")
        void sameVisits() {
            Geometries g = new Geometries(BvhTest.gridMesh(30));
            Bvh tree = Bvh.build(g, 1, 4096, true, VectorWalk.anyCpu());
            int visits = 0;
            for (Ray ray : RandomScenes.rays(new Random(54), 2000, new Point(15, 1, 15), 16)) {
                Hit query = Hit.of(ray);
                List<Double> plain = new ArrayList<>(), nested = new ArrayList<>();
                tree.visitHits(query, Double.POSITIVE_INFINITY, (geometry, t) -> plain.add(t));
                tree.visitHits(query, Double.POSITIVE_INFINITY, (geometry, t) -> {
                    nested.add(t);
                    tree.visitHits(query, Double.POSITIVE_INFINITY, (inner, u) -> true);
                    return true;
                });
                assertThat(nested).as("visits for %s", ray).containsExactlyElementsOf(plain);
                visits += plain.size();
            }
            assertThat(visits).as("visits (the test must not be vacuous)").isGreaterThan(500);
        }
    }

    @Nested
    @TestInstance(TestInstance.Lifecycle.PER_CLASS)
    @DisplayName("ray by ray on the Embree benchmark's meshes: the vector walk's hit is the scalar walk's")
    class OnTheBenchmarkMeshes {
        /** The meshes of scripts/embree_benchmark.py (the 10^6 sphere left to the benchmark: its build takes seconds). */
        Stream<Arguments> meshes() {
            return Stream.of(Arguments.of("teapot", BenchmarkMeshes.teapot()),
                    Arguments.of("displaced sphere, 9,936 triangles", BenchmarkMeshes.displacedSphere(70, 72)),
                    Arguments.of("displaced sphere, 99,904 triangles", BenchmarkMeshes.displacedSphere(224, 224)));
        }

        /** The benchmark's view at 160 × 160, and random rays from all around and from inside. */
        private List<Ray> rays(TriangleMesh mesh) {
            List<Ray> rays = new ArrayList<>(BenchmarkMeshes.pinholeRays(mesh, 160));
            BoundingBox box = mesh.getBoundingBox();
            Point centre = new Point((box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2, (box.minZ + box.maxZ) / 2);
            double half = Math.max(box.maxX - box.minX, Math.max(box.maxY - box.minY, box.maxZ - box.minZ)) / 2;
            rays.addAll(RandomScenes.rays(new Random(52), 20_000, centre, half));
            return rays;
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("meshes")
        @DisplayName("the same hit or miss, triangle and distance bits, for every ray")
        void sameClosestHits(String name, TriangleMesh mesh) {
            Geometries g = new Geometries(mesh);
            Bvh scalar = Bvh.build(g, 1, 4096, true, null), vector = Bvh.build(g, 1, 4096, true, VectorWalk.anyCpu());
            Hit a = new Hit(), b = new Hit();
            int hits = 0;
            List<Ray> rays = rays(mesh);
            for (Ray ray : rays) {
                boolean fa = scalar.closestHit(a.setRay(ray).reset(Double.POSITIVE_INFINITY));
                boolean fb = vector.closestHit(b.setRay(ray).reset(Double.POSITIVE_INFINITY));
                assertThat(fb).as("hit or miss for %s", ray).isEqualTo(fa);
                if (!fa) continue;
                ++hits;
                assertThat(b.geometry).as("geometry for %s", ray).isSameAs(a.geometry);
                assertThat(b.primitive).as("triangle for %s", ray).isEqualTo(a.primitive);
                assertThat(Double.doubleToRawLongBits(b.t)).as("distance for %s", ray).isEqualTo(Double.doubleToRawLongBits(a.t));
            }
            assertThat(hits).as("rays that hit (the test must not be vacuous)").isGreaterThan(rays.size() / 4);
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("meshes")
        @DisplayName("the same any-hit visits, within random distances")
        void sameVisits(String name, TriangleMesh mesh) {
            Geometries g = new Geometries(mesh);
            Bvh scalar = Bvh.build(g, 1, 4096, true, null), vector = Bvh.build(g, 1, 4096, true, VectorWalk.anyCpu());
            Random rnd = new Random(53);
            List<Ray> rays = rays(mesh);
            int visits = 0;
            for (int i = 0; i < rays.size(); i += 4) {
                Ray ray = rays.get(i);
                double max = rnd.nextBoolean() ? Double.POSITIVE_INFINITY : 5 * rnd.nextDouble() * BenchmarkMeshes.size(mesh);
                List<Visit> expected = Hits.visited(scalar, ray, max);
                assertThat(Hits.visited(vector, ray, max)).as("visits within %s for %s", max, ray).containsExactlyElementsOf(expected);
                visits += expected.size();
            }
            assertThat(visits).as("visits (the test must not be vacuous)").isGreaterThan(rays.size() / 8);
        }

        @Test
        @DisplayName("a mesh's leaves are all tested in lanes in a wide tree (negative counts)")
        void leavesInLanes() {
            Bvh vector = Bvh.build(new Geometries(BenchmarkMeshes.displacedSphere(70, 72)), 1, 4096, true, VectorWalk.anyCpu());
            WideNodes wide = vector.wideNodes();
            int lanes = 0, scalar = 0;
            for (int item = 0; item < wide.count * wide.width; ++item) {
                int count = WideNodes.count(wide.node, wide.slot(item), wide.width);
                if (count < 0) ++lanes;
                if (count > 0) ++scalar;
            }
            assertThat(lanes).as("leaves of triangles in lanes").isPositive();
            assertThat(scalar).as("leaves in the scalar layout").isZero();
        }
    }
}
