package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Hits.Visit;
import primitives.Double3;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The BVH must be invisible: for any scene and any ray it answers exactly what the flat
 * {@link Geometries} answers (same geometry, same distance, same hits), only faster. Checked on
 * random scenes with fixed seeds, and on the degenerate scenes a builder gets wrong.
 */
class BvhTest {

    /** A scene with a readable name for the parameterized tests. */
    record Scene(String name, Geometries geometries, Point centre, double half) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Arguments> randomScenes() {
        return Stream.of(
                Arguments.of(scene("200 shapes spread out", 1, 200, 50, 4, false)),
                Arguments.of(scene("80 overlapping shapes", 2, 80, 8, 4, false)),
                Arguments.of(scene("400 small shapes with planes and tubes beside the tree", 3, 400, 30, 1.5, true)));
    }

    private static Scene scene(String name, long seed, int count, double half, double size, boolean unbounded) {
        Random rnd = new Random(seed);
        Geometries g = new Geometries();
        for (Geometry shape : RandomScenes.boundedShapes(rnd, count, Point.ZERO, half, size)) g.add(shape);
        if (unbounded) {
            g.add(RandomScenes.withMaterial(rnd, new Plane(new Point(0, 0, -half), new Vector(0.1, 0, 1))),
                    RandomScenes.withMaterial(rnd, new Tube(2, new Ray(new Point(0, half / 2, 0), new Vector(1, 0.2, 0)))),
                    RandomScenes.withMaterial(rnd, new Plane(new Point(half * 0.8, 0, 0), new Vector(-1, 0, 0))));
        }
        return new Scene(name, g, Point.ZERO, half);
    }

    private static final int RAYS = 1500;

    /** Asserts the same closest hits, and the same walks within {@code max} of every ray's head. */
    private static void assertSameAnswers(Intersectable tree, Intersectable flat, List<Ray> rays, double max) {
        assertSameClosestHits(tree, flat, rays);
        for (Ray ray : rays)
            Hits.assertSameVisits(Hits.visited(tree, ray, max), Hits.visited(flat, ray, max), 0, "walk for " + ray);
    }

    /** Asserts the tree and the flat list give the same closest hit: same geometry, bit-identical t. */
    private static void assertSameClosestHits(Intersectable tree, Intersectable flat, List<Ray> rays) {
        int hits = 0;
        for (Ray ray : rays) {
            Visit expected = Hits.closest(flat, ray, Double.POSITIVE_INFINITY);
            Visit actual = Hits.closest(tree, ray, Double.POSITIVE_INFINITY);
            if (expected == null) {
                assertThat(actual).as("closest hit through the tree for %s (flat: none)", ray).isNull();
                continue;
            }
            ++hits;
            assertThat(actual).as("closest hit through the tree for %s (flat: %s)", ray, expected).isNotNull();
            assertThat(actual.geometry()).as("closest geometry for %s", ray).isSameAs(expected.geometry());
            // The tree calls the same primitive test on the same ray: the distance is the same number.
            assertThat(actual.t()).as("closest distance for %s", ray).isEqualTo(expected.t());
        }
        assertThat(hits).as("rays that hit something (the test must not be vacuous)").isGreaterThan(rays.size() / 10);
    }

    /**
     * Asserts the tree's any-hit walk visits what the flat list's does (the same multiset of
     * (geometry, t)) for seeded random rays, each within an unbounded or a random distance.
     */
    private static void assertSameVisitsAsFlat(Scene scene, long seed) {
        Bvh tree = Bvh.build(scene.geometries());
        Random rnd = new Random(seed);
        for (Ray ray : RandomScenes.rays(new Random(seed + 1), RAYS, scene.centre(), scene.half())) {
            double max = rnd.nextBoolean() ? Double.POSITIVE_INFINITY : 3 * scene.half() * rnd.nextDouble();
            Hits.assertSameVisits(Hits.visited(tree, ray, max), Hits.visited(scene.geometries(), ray, max), 0,
                    "tree vs flat walk within " + max + " for " + ray);
        }
    }

    /** The shadow-ray walk: the product of kT of every occluder within maxDistance. */
    private static final class Transparency implements HitVisitor {
        double r = 1, g = 1, b = 1;
        int visits;
        private final double stopBelow;

        Transparency(double stopBelow) {
            this.stopBelow = stopBelow;
        }

        @Override
        public boolean visit(Geometry geometry, double t) {
            Double3 kT = geometry.getMaterial().kT;
            r *= kT.getD1();
            g *= kT.getD2();
            b *= kT.getD3();
            ++visits;
            return !(r < stopBelow && g < stopBelow && b < stopBelow);
        }
    }

    @Nested
    @DisplayName("random scenes: the tree answers exactly as the flat list")
    class AgainstTheFlatList {
        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#randomScenes")
        @DisplayName("closest hit: same geometry and same t")
        void closestHit(Scene scene) {
            Bvh tree = Bvh.build(scene.geometries());
            assertSameClosestHits(tree, scene.geometries(), RandomScenes.rays(new Random(100), RAYS, scene.centre(), scene.half()));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#randomScenes")
        @DisplayName("shadow transparency: the same kT product within maxDistance, and the same early stop")
        void transparencyProduct(Scene scene) {
            Bvh tree = Bvh.build(scene.geometries());
            Random rnd = new Random(200);
            int occluded = 0, stopped = 0;
            for (Ray ray : RandomScenes.rays(new Random(201), RAYS, scene.centre(), scene.half())) {
                double max = 3 * scene.half() * rnd.nextDouble();
                Transparency flat = new Transparency(-1), viaTree = new Transparency(-1);
                scene.geometries().visitHits(ray, max, flat);
                tree.visitHits(ray, max, viaTree);
                assertThat(viaTree.visits).as("occluders of %s within %s", ray, max).isEqualTo(flat.visits);
                assertThat(new double[] { viaTree.r, viaTree.g, viaTree.b }).as("kT product for %s within %s", ray, max)
                        .containsExactly(new double[] { flat.r, flat.g, flat.b }, org.assertj.core.data.Offset.offset(1e-12));
                if (flat.visits > 0) ++occluded;

                // With a threshold the walk stops as soon as the product falls below it; the order of the
                // occluders differs, but since every kT ≤ 1 whether it stops at all does not.
                Transparency flatStop = new Transparency(0.4), treeStop = new Transparency(0.4);
                boolean flatDone = scene.geometries().visitHits(ray, max, flatStop);
                boolean treeDone = tree.visitHits(ray, max, treeStop);
                assertThat(treeDone).as("walk completed for %s within %s", ray, max).isEqualTo(flatDone);
                if (!flatDone) ++stopped;
            }
            assertThat(occluded).as("occluded rays").isGreaterThan(RAYS / 10);
            assertThat(stopped).as("walks stopped early").isPositive();
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#randomScenes")
        @DisplayName("visitHits: the same multiset of (geometry, t)")
        void visitHits(Scene scene) {
            assertSameVisitsAsFlat(scene, 300);
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#randomScenes")
        @DisplayName("the build is deterministic: the same scene gives the same tree")
        void deterministicBuild(Scene scene) {
            Bvh first = Bvh.build(scene.geometries()), second = Bvh.build(scene.geometries());
            assertThat(second.nodeCount()).isEqualTo(first.nodeCount());
            assertThat(second.depth()).isEqualTo(first.depth());
            assertThat(second.primitiveTotal()).isEqualTo(first.primitiveTotal());
            // The same tree walks the same leaves in the same order: identical visit sequences.
            for (Ray ray : RandomScenes.rays(new Random(400), 200, scene.centre(), scene.half())) {
                List<Visit> a = new ArrayList<>(), b = new ArrayList<>();
                first.visitHits(ray, Double.POSITIVE_INFINITY, (g, t) -> a.add(new Visit(g, t)));
                second.visitHits(ray, Double.POSITIVE_INFINITY, (g, t) -> b.add(new Visit(g, t)));
                assertThat(b).as("visit order for %s", ray).containsExactlyElementsOf(a);
            }
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#randomScenes")
        @DisplayName("the tree is a real hierarchy: every primitive indexed, depth logarithmic")
        void treeShape(Scene scene) {
            Bvh tree = Bvh.build(scene.geometries());
            int bounded = (int) scene.geometries().getItems().stream().filter(g -> g.getBoundingBox() != null).count();
            assertThat(tree.primitiveTotal()).isEqualTo(bounded);
            assertThat(tree.unboundedCount()).isEqualTo(scene.geometries().getItems().size() - bounded);
            assertThat(tree.nodeCount()).isBetween(bounded / 4, 2 * bounded - 1);
            assertThat(tree.depth()).isLessThanOrEqualTo(4 * (32 - Integer.numberOfLeadingZeros(bounded)));
        }
    }

    /**
     * Flat boxes (axis-aligned triangles, zero thickness along one axis), nearly point-like spheres
     * and large triangles, far from the origin (coordinates of a few million, where the boxes'
     * padding and the slab test's rounding matter).
     */
    static Scene degenerateBoxes() {
        Random rnd = new Random(7);
        Point c = new Point(3e6, -2e6, 5e6);
        double half = 20;
        Geometries g = new Geometries();
        for (int i = 0; i < 150; ++i) {
            Point p = RandomScenes.point(rnd, c, half);
            double a = 1 + 4 * rnd.nextDouble(), b = 1 + 4 * rnd.nextDouble();
            Geometry shape = switch (i % 3) {
                case 0 -> new Triangle(p, p.add(new Vector(a, 0, 0)), p.add(new Vector(0, b, 0))); // flat in z
                case 1 -> new Triangle(p, p.add(new Vector(0, a, 0)), p.add(new Vector(0, 0, b))); // flat in x
                default -> new Sphere(p, 1e-3 * (1 + rnd.nextDouble())); // nearly a point
            };
            g.add(RandomScenes.withMaterial(rnd, shape));
        }
        return new Scene("flat and point-like boxes at coordinates of millions", g, c, half);
    }

    static Stream<Arguments> parallelScenes() {
        return Stream.concat(randomScenes(), Stream.of(Arguments.of(degenerateBoxes())));
    }

    /** A side × side grid of quads, two triangles each, as one mesh, its heights in {0, 1, 2}. */
    static TriangleMesh gridMesh(int side) {
        double[] pos = new double[(side + 1) * (side + 1) * 3];
        for (int i = 0, p = 0; i <= side; ++i)
            for (int j = 0; j <= side; ++j) {
                pos[p++] = j;
                pos[p++] = (i * j) % 3;
                pos[p++] = i;
            }
        int[] idx = new int[side * side * 6];
        for (int i = 0, q = 0; i < side; ++i)
            for (int j = 0; j < side; ++j) {
                int a = i * (side + 1) + j, b = a + 1, c = a + side + 1, d = c + 1;
                idx[q++] = a;
                idx[q++] = b;
                idx[q++] = c;
                idx[q++] = b;
                idx[q++] = d;
                idx[q++] = c;
            }
        return new TriangleMesh(pos, idx);
    }

    /** Scenes with many equal costs for the split searches: lattices of equal shapes, a grid mesh. */
    static Stream<Arguments> searchScenes() {
        Geometries lattice = new Geometries();
        for (int i = 0; i < 12; ++i)
            for (int j = 0; j < 12; ++j)
                for (int k = 0; k < 3; ++k)
                    lattice.add(new Sphere(new Point(2 * i, 2 * j, 2 * k), 0.8));
        Geometries stacked = new Geometries();
        for (int i = 0; i < 40; ++i) stacked.add(new Sphere(new Point(i % 5, 0, 0), 1 + i % 3)); // 5 centroids, 8 each
        return Stream.concat(parallelScenes(), Stream.of(
                Arguments.of(new Scene("a 12×12×3 lattice of equal spheres", lattice, new Point(11, 11, 2), 14)),
                Arguments.of(new Scene("40 spheres on 5 centres", stacked, Point.ZERO, 8)),
                Arguments.of(new Scene("a 20×20 grid mesh", new Geometries(gridMesh(20)), new Point(10, 1, 10), 12))));
    }

    @Nested
    @DisplayName("the parallel build: the same tree on any number of threads")
    class ParallelBuild {
        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#parallelScenes")
        @DisplayName("1 and 2 threads, forking at every node or above the default size, give the same tree")
        void sameTree(Scene scene) {
            Bvh sequential = Bvh.build(scene.geometries(), 1);
            assertThat(sequential.nodeCount()).isGreaterThan(1);
            assertThat(Bvh.build(scene.geometries(), 1, 1).sameTreeAs(sequential)).as("1 thread, chunks of one primitive").isTrue();
            assertThat(Bvh.build(scene.geometries(), 2, 1).sameTreeAs(sequential)).as("2 threads, a task per node").isTrue();
            assertThat(Bvh.build(scene.geometries(), 2, 16).sameTreeAs(sequential)).as("2 threads, tasks above 16").isTrue();
            assertThat(Bvh.build(scene.geometries(), 3, 1).sameTreeAs(sequential)).as("3 threads").isTrue();
            assertThat(Bvh.build(scene.geometries()).sameTreeAs(sequential)).as("the default").isTrue();
        }

        @ParameterizedTest(name = "{0} thread(s), tasks above {1}")
        @CsvSource({"1, 1", "1, 4096", "2, 1", "2, 16", "3, 1"})
        @DisplayName("the tree's box is exactly the union of its shapes' padded boxes, however the build is cut up")
        void rootBoxIsTheUnion(int threads, int forkAbove) {
            // Far from the origin on every axis, so that any box left empty or zero in the
            // build's pieces would show.
            Geometries shapes = new Geometries();
            Random rnd = new Random(77);
            BoundingBox expected = null;
            for (int i = 0; i < 300; ++i) {
                Sphere s = new Sphere(new Point(100 + 50 * rnd.nextDouble(), -300 + 20 * rnd.nextDouble(), 40 + rnd.nextDouble()),
                        0.1 + rnd.nextDouble());
                shapes.add(s);
                BoundingBox padded = s.getBoundingBox().padded();
                expected = expected == null ? padded : expected.union(padded);
            }
            BoundingBox b = Bvh.build(shapes, threads, forkAbove).getBoundingBox();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(expected.getMinX(), expected.getMinY(), expected.getMinZ(),
                            expected.getMaxX(), expected.getMaxY(), expected.getMaxZ());
        }

        @Test
        @DisplayName("a different scene is a different tree (the comparison can fail)")
        void differentTree() {
            Scene a = degenerateBoxes();
            Geometries fewer = new Geometries();
            a.geometries().getItems().stream().skip(1).forEach(fewer::add);
            assertThat(Bvh.build(fewer, 2, 1).sameTreeAs(Bvh.build(a.geometries(), 1))).isFalse();
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#parallelScenes")
        @DisplayName("a tree built with a task per node answers as brute force: closest hits and every occluder")
        void answersAsBruteForce(Scene scene) {
            Bvh tree = Bvh.build(scene.geometries(), 2, 1);
            List<Ray> rays = RandomScenes.rays(new Random(600), RAYS, scene.centre(), scene.half());
            assertSameClosestHits(tree, scene.geometries(), rays);
            Random rnd = new Random(601);
            for (Ray ray : rays.subList(0, 500)) {
                double max = 3 * scene.half() * rnd.nextDouble();
                Hits.assertSameVisits(Hits.visited(tree, ray, max), Hits.visited(scene.geometries(), ray, max), 0,
                        "tree vs flat walk within " + max + " for " + ray);
            }
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#searchScenes")
        @DisplayName("pairs searched without bins get the split the binned search gives them")
        void pairSearchAgreesWithBins(Scene scene) {
            Bvh binned = Bvh.build(scene.geometries(), 1, 1, false);
            assertThat(Bvh.build(scene.geometries(), 1).sameTreeAs(binned)).as("1 thread").isTrue();
            assertThat(Bvh.build(scene.geometries(), 2, 1).sameTreeAs(binned)).as("2 threads, a task per node").isTrue();
        }

        @Test
        @DisplayName("a shape failing to give its box fails the build with its own exception, the first in scene order")
        void failingShape() {
            IllegalStateException first = new IllegalStateException("box of shape 40");
            IllegalStateException later = new IllegalStateException("box of shape 90");
            Geometries g = new Geometries();
            for (int i = 0; i < 120; ++i) {
                RuntimeException failure = i == 40 ? first : i == 90 ? later : null;
                g.add(new Sphere(new Point(i, 0, 0), 0.5) {
                    @Override
                    public BoundingBox getBoundingBox() {
                        if (failure != null) throw failure;
                        return super.getBoundingBox();
                    }
                });
            }
            for (int threads = 1; threads <= 2; ++threads) {
                int parallelism = threads;
                assertThatThrownBy(() -> Bvh.build(g, parallelism, 1)).as(threads + " threads").isSameAs(first);
            }
        }

        @Test
        @DisplayName("parallelism below 1 is rejected, naming the value")
        void badParallelism() {
            org.assertj.core.api.Assertions.assertThatIllegalArgumentException()
                    .isThrownBy(() -> Bvh.build(new Geometries(), 0)).withMessageContaining("0");
        }
    }

    @Nested
    @DisplayName("degenerate scenes")
    class Degenerate {
        private final List<Ray> rays = RandomScenes.rays(new Random(500), 500, Point.ZERO, 10);

        @Test
        @DisplayName("an empty scene: no node, no hit on any face")
        void empty() {
            Bvh tree = Bvh.build(new Geometries());
            assertThat(tree.nodeCount()).isZero();
            assertThat(tree.depth()).isZero();
            assertThat(tree.primitiveTotal()).isZero();
            assertThat(tree.getBoundingBox()).isNull();
            Hits.assertHits(tree, new Ray(Point.ZERO, new Vector(1, 0, 0)));
        }

        @Test
        @DisplayName("a scene of empty lists: no node, no hit")
        void emptyLists() {
            Bvh tree = Bvh.build(new Geometries(new Geometries(), new Geometries(new Geometries())));
            assertThat(tree.nodeCount()).isZero();
            assertThat(tree.unboundedCount()).isZero();
            Hits.assertHits(tree, new Ray(Point.ZERO, new Vector(1, 0, 0)));
        }

        @Test
        @DisplayName("only unbounded geometries: no node, all of them beside the tree")
        void onlyUnbounded() {
            Geometries flat = new Geometries(new Plane(new Point(0, 0, -5), new Vector(0, 0, 1)),
                    new Plane(new Point(0, 7, 0), new Vector(0.2, 1, 0)), new Tube(1, new Ray(new Point(3, 0, 0), new Vector(0, 1, 1))),
                    new Tube(2, new Ray(new Point(-4, 0, 0), new Vector(0, 0, 1))));
            Bvh tree = Bvh.build(flat);
            assertThat(tree.nodeCount()).isZero();
            assertThat(tree.unboundedCount()).isEqualTo(4);
            assertThat(tree.getBoundingBox()).isNull();
            assertSameAnswers(tree, flat, rays, 12);
        }

        @Test
        @DisplayName("a single primitive: one leaf")
        void single() {
            Geometries flat = new Geometries(new Sphere(new Point(1, 2, 3), 2));
            Bvh tree = Bvh.build(flat);
            assertThat(tree.nodeCount()).isEqualTo(1);
            assertThat(tree.depth()).isEqualTo(1);
            assertSameClosestHits(tree, flat, RandomScenes.rays(new Random(501), 300, new Point(1, 2, 3), 2));
        }

        /**
         * Spheres, squares, axis-aligned triangles and cylinders whose boxes are all centred on one
         * point: no split plane separates the centroids, yet the tree must stay shallow and correct.
         */
        @Test
        @DisplayName("all primitives at one spot (coincident centroids): builds, stays shallow, answers correctly")
        void coincidentCentroids() {
            Random rnd = new Random(502);
            Point c = new Point(1, -1, 2);
            Geometries flat = new Geometries();
            for (int i = 0; i < 20; ++i) {
                flat.add(new Sphere(c, 0.5 + 0.25 * i));
                double a = 0.3 + 0.2 * i;
                // Box [-a,a]×[-a,a]×[-k,k] around c; each triangle in its own plane z = (k/a)·x, so
                // overlapping triangles never tie at the same distance.
                double k = 0.03 * (i + 1) * a;
                flat.add(new Triangle(c.add(new Vector(-a, -a, -k)), c.add(new Vector(a, -a, k)), c.add(new Vector(0, a, 0))));
                Vector n = RandomScenes.direction(rnd);
                Vector u = n.crossProduct(Vector.AXIS_X).normalize().scale(a), w = n.crossProduct(u);
                flat.add(new Polygon(c.add(u), c.add(w), c.add(u.scale(-1)), c.add(w.scale(-1))));
                Vector v = RandomScenes.direction(rnd);
                double h = 0.5 + 0.3 * i;
                flat.add(new Cylinder(0.1 + 0.05 * i, new Ray(c.add(v.scale(-h / 2)), v), h));
            }
            Bvh tree = Bvh.build(flat);
            assertThat(tree.primitiveTotal()).isEqualTo(80);
            assertThat(tree.nodeCount()).as("leaves are bounded in size, so the tree splits").isGreaterThan(1);
            // Rounding makes the centroids differ in the last bits, so the splits are not exact halves;
            // the bound only rules out a tree that degenerates towards a list.
            assertThat(tree.depth()).as("the tree stays shallow").isLessThanOrEqualTo(3 * 7);
            List<Ray> near = RandomScenes.rays(new Random(503), RAYS, c, 3);
            assertSameClosestHits(tree, flat, near);
            for (Ray ray : near.subList(0, 300))
                Hits.assertSameVisits(Hits.visited(tree, ray, 4), Hits.visited(flat, ray, 4), 0, "walk for " + ray);
        }

        @Test
        @DisplayName("nested lists are flattened: every leaf indexed once, same answers")
        void nestedListsAreFlattened() {
            Random rnd = new Random(504);
            List<Geometry> shapes = RandomScenes.boundedShapes(rnd, 40, Point.ZERO, 10, 3);
            Geometries nested = new Geometries();
            Geometries level = nested;
            for (int i = 0; i < shapes.size(); ++i) {
                if (i % 8 == 0) {
                    Geometries deeper = new Geometries();
                    level.add(deeper, new Geometries()); // an empty list beside every level
                    level = deeper;
                }
                level.add(shapes.get(i));
            }
            Bvh tree = Bvh.build(nested);
            assertThat(tree.primitiveTotal()).isEqualTo(40);
            assertThat(tree.unboundedCount()).isZero();
            Geometries flat = new Geometries(shapes.toArray(new Intersectable[0]));
            assertSameClosestHits(tree, flat, rays);
            assertSameClosestHits(tree, nested, rays);
        }

        @Test
        @DisplayName("a tree inside a scene that is itself built into a tree")
        void treeInsideATree() {
            Random rnd = new Random(505);
            Geometries group = new Geometries();
            for (Geometry g : RandomScenes.boundedShapes(rnd, 60, Point.ZERO, 10, 3)) group.add(g);
            Geometries others = new Geometries();
            for (Geometry g : RandomScenes.boundedShapes(rnd, 60, Point.ZERO, 10, 3)) others.add(g);
            Geometries scene = new Geometries(Bvh.build(group), others);
            Geometries flat = new Geometries(group, others);
            Bvh outer = Bvh.build(scene);
            assertSameClosestHits(outer, flat, rays);
            assertSameClosestHits(scene, flat, rays); // the inner tree queried through a flat list
            assertThat(outer.primitiveTotal()).as("the inner tree's shapes are indexed directly").isEqualTo(120);
            for (Ray ray : rays)
                Hits.assertSameVisits(Hits.visited(outer, ray, 15), Hits.visited(flat, ray, 15), 0, "walk for " + ray);
        }

        @Test
        // The walk this guards against does not fail, it loops forever: the bound makes it a failure.
        @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
        @DisplayName("a user's shape that walks a tree of its own with the outer walk's record")
        void userShapeWalkingItsOwnTree() {
            Random rnd = new Random(506);
            Geometries scene = new Geometries();
            Geometries flat = new Geometries();
            for (int c = 0; c < 8; ++c) {
                Geometries parts = new Geometries();
                Point centre = new Point(rnd.nextDouble(-8, 8), rnd.nextDouble(-8, 8), rnd.nextDouble(-8, 8));
                for (Geometry g : RandomScenes.boundedShapes(rnd, 30, centre, 3, 1.5)) {
                    parts.add(g);
                    flat.add(g);
                }
                scene.add(new Cluster(Bvh.build(parts)));
            }
            for (Geometry g : RandomScenes.boundedShapes(rnd, 60, Point.ZERO, 10, 3)) {
                scene.add(g);
                flat.add(g);
            }
            Bvh outer = Bvh.build(scene);
            assertThat(outer.primitiveTotal()).as("each cluster is one primitive of the outer tree").isEqualTo(68);
            // The inner walks run in the middle of the outer one, on the same Hit record.
            assertSameClosestHits(outer, flat, rays);
        }

        @Test
        @DisplayName("a shape that throws in the middle of nested walks leaves the record usable")
        void throwingShapeInsideNestedWalks() {
            Geometries parts = new Geometries(new Sphere(new Point(0, 0, -20), 1), new Thrower(new Point(0, 0, 0), 1));
            Bvh outer = Bvh.build(new Geometries(new Cluster(Bvh.build(parts)), new Sphere(new Point(5, 0, 0), 1)));
            Hit hit = new Hit().setRay(0, 0, 10, 0, 0, -1).reset(Double.POSITIVE_INFINITY);
            assertThatThrownBy(() -> outer.closestHit(hit)).isInstanceOf(IllegalStateException.class);
            assertThat(hit.walking).as("no walk is in progress on the record any more").isFalse();
            assertThat(outer.closestHit(hit.setRay(5, 0, 10, 0, 0, -1).reset(Double.POSITIVE_INFINITY))).isTrue();
            assertThat(hit.getT()).isEqualTo(9);
        }

        @Test
        @DisplayName("axis-aligned shapes hit by axis-parallel rays (signed zero directions, flat boxes)")
        void axisAlignedRays() {
            Geometries flat = new Geometries();
            for (int i = 0; i < 10; ++i)
                for (int j = 0; j < 10; ++j)
                    flat.add(new Polygon(new Point(i, j, 0), new Point(i + 1, j, 0), new Point(i + 1, j + 1, 0), new Point(i, j + 1, 0)));
            flat.add(new Triangle(new Point(0, 0, 3), new Point(10, 0, 3), new Point(0, 10, 3)));
            Bvh tree = Bvh.build(flat);
            List<Ray> axial = new ArrayList<>();
            Random rnd = new Random(506);
            for (int k = 0; k < 500; ++k) {
                // Straight down, and straight up as a shadow ray is built (scale(-1) makes -0.0 components).
                double x = 10 * rnd.nextDouble(), y = 10 * rnd.nextDouble();
                axial.add(new Ray(new Point(x, y, 5), new Vector(0, 0, -1)));
                axial.add(new Ray(new Point(x, y, -1), new Vector(0, 0, -1).scale(-1)));
                axial.add(new Ray(new Point(-1, y, 1.5 * rnd.nextDouble()), new Vector(1, 0, 0)));
            }
            assertSameAnswers(tree, flat, axial, 4);
        }

        @Test
        @DisplayName("the tree's box encloses every bounded shape; none when something is unbounded")
        void boundingBox() {
            Geometries shapes = new Geometries(new Sphere(new Point(0, 0, 0), 1), new Sphere(new Point(5, -3, 2), 2));
            BoundingBox b = Bvh.build(shapes).getBoundingBox();
            assertThat(b.getMinX()).isLessThanOrEqualTo(-1);
            assertThat(b.getMinY()).isLessThanOrEqualTo(-5);
            assertThat(b.getMaxZ()).isGreaterThanOrEqualTo(4);
            assertThat(b.getMaxX()).isCloseTo(7, org.assertj.core.data.Offset.offset(1e-6));
            shapes.add(new Plane(Point.ZERO, Vector.AXIS_Z));
            assertThat(Bvh.build(shapes).getBoundingBox()).isNull();
        }
    }

    static Stream<Arguments> awkwardScenes() {
        return Stream.of(
                Arguments.of(scene("far from the origin (floats 0.001 apart there)", 11, new Point(1.1e4, -7.3e3, 3.1e3), 10, 1)),
                Arguments.of(scene("beyond the float range (boxes of infinite float bounds)", 12, new Point(1e39, -2e39, 5e38), 1e37, 1e36)),
                Arguments.of(scene("tiny shapes, almost point boxes", 13, new Point(0.1, 0.2, 0.3), 1e-3, 1e-4)),
                Arguments.of(scene("huge shapes around small ones", 14, new Point(-0.3, 0.7, 0.1), 1e4, 3e3)));
    }

    private static Scene scene(String name, long seed, Point centre, double half, double size) {
        Geometries g = new Geometries();
        for (Geometry shape : RandomScenes.boundedShapes(new Random(seed), 300, centre, half, size)) g.add(shape);
        return new Scene(name, g, centre, half);
    }

    @Nested
    @DisplayName("float nodes: boxes rounded outward, so no hit is lost and none is gained")
    class FloatNodes {
        @ParameterizedTest(name = "{0}")
        @org.junit.jupiter.params.provider.ValueSource(doubles = { 0, -0.0, 0.1, -0.1, 1 / 3.0, -1e-300, 4.9e-324, 1e-45,
                16777217, -16777217, 3.4028235677973366e38, 1e39, -1e39, 1e300, -1e300 })
        @DisplayName("a bound becomes the nearest float on its outer side")
        void roundedOutward(double d) {
            float below = BvhNodes.floatBelow(d), above = BvhNodes.floatAbove(d);
            assertThat((double) below).as("lower bound of %s", d).isLessThanOrEqualTo(d);
            assertThat((double) Math.nextUp(below)).as("the float above the lower bound of %s", d).isGreaterThan(d);
            assertThat((double) above).as("upper bound of %s", d).isGreaterThanOrEqualTo(d);
            assertThat((double) Math.nextDown(above)).as("the float below the upper bound of %s", d).isLessThan(d);
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#awkwardScenes")
        @DisplayName("closest hit: same geometry and same t as the flat list")
        void closestHit(Scene scene) {
            assertSameClosestHits(Bvh.build(scene.geometries()), scene.geometries(),
                    RandomScenes.rays(new Random(700), RAYS, scene.centre(), scene.half()));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.BvhTest#awkwardScenes")
        @DisplayName("visitHits: the same multiset of (geometry, t) as the flat list")
        void visitHits(Scene scene) {
            assertSameVisitsAsFlat(scene, 701);
        }

        @Test
        @DisplayName("flat boxes at coordinates no float can hold, hit by axis-parallel rays")
        void flatBoxesBetweenFloats() {
            Geometries flat = new Geometries();
            for (int i = 0; i < 10; ++i)
                for (int j = 0; j < 10; ++j) {
                    double x = 0.1 * i + 0.01, y = 0.1 * j + 0.01, z = 0.1 * ((i + j) % 3) + 0.1;
                    flat.add(new Polygon(new Point(x, y, z), new Point(x + 0.1, y, z), new Point(x + 0.1, y + 0.1, z), new Point(x, y + 0.1, z)));
                }
            Bvh tree = Bvh.build(flat);
            List<Ray> axial = new ArrayList<>();
            Random rnd = new Random(703);
            for (int k = 0; k < 500; ++k) {
                double x = 0.01 + rnd.nextDouble(), y = 0.01 + rnd.nextDouble();
                axial.add(new Ray(new Point(x, y, 5), new Vector(0, 0, -1)));
                axial.add(new Ray(new Point(x, y, -1), new Vector(0, 0, -1).scale(-1)));
                // Grazing: in the plane of a row of polygons.
                axial.add(new Ray(new Point(-1, y, 0.1 * rnd.nextInt(3) + 0.1), new Vector(1, 0, 0)));
            }
            assertSameAnswers(tree, flat, axial, 6);
        }

        @Test
        @DisplayName("the tree's box is the exact double box, not the widened float one")
        void exactRootBox() {
            BoundingBox b = Bvh.build(new Geometries(new Sphere(new Point(0.1, 0.2, 0.3), 0.7))).getBoundingBox();
            BoundingBox exact = new Sphere(new Point(0.1, 0.2, 0.3), 0.7).getBoundingBox().padded();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(exact.getMinX(), exact.getMinY(), exact.getMinZ(), exact.getMaxX(), exact.getMaxY(), exact.getMaxZ());
        }
    }

    /**
     * A user's group of shapes with a tree of its own, answering the outer walk's closest-hit
     * query by walking that tree with the same record.
     */
    private static final class Cluster extends Geometry {
        private final Bvh inner;

        Cluster(Bvh inner) {
            this.inner = inner;
        }

        @Override
        public boolean closestHit(Hit hit) {
            return inner.closestHit(hit);
        }

        @Override
        public boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
            return inner.visitHits(query, maxDistance, visitor);
        }

        @Override
        public BoundingBox getBoundingBox() {
            return inner.getBoundingBox();
        }

        @Override
        public Vector getNormal(Point point) {
            throw new UnsupportedOperationException("a cluster's hits report its parts");
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            return inner.findGeoIntersections(ray, maxDistance);
        }
    }

    /** A user's sphere whose closest-hit query fails. */
    private static final class Thrower extends Sphere {
        Thrower(Point center, double radius) {
            super(center, radius);
        }

        @Override
        public boolean closestHit(Hit hit) {
            throw new IllegalStateException("a user's shape failed");
        }
    }

    /** A user's sphere that is never hit: it overrides both hooks the renderer's walks call. */
    private static final class Ghost extends Sphere {
        Ghost(Point center, double radius) {
            super(center, radius);
        }

        @Override
        public boolean closestHit(Hit hit) {
            return false;
        }

        @Override
        public boolean visitHits(Hit query, double maxDistance, HitVisitor visitor) {
            return true;
        }
    }

    /** A user's triangle that is never hit. */
    private static final class GhostTriangle extends Triangle {
        GhostTriangle(Point a, Point b, Point c) {
            super(a, b, c);
        }

        @Override
        double distanceTo(Hit query) {
            return Double.NaN;
        }
    }

    @Nested
    @DisplayName("packed primitives: library spheres and triangles are tested from the tree's own numbers")
    class Packed {
        @Test
        @DisplayName("only the library's own sphere, triangle and mesh triangles pack; subclasses and polygons keep their hooks")
        void kinds() {
            Point a = new Point(0, 0, 0), b = new Point(1, 0, 0), c = new Point(0, 1, 0);
            assertThat(new Sphere(a, 1).packedKind()).isEqualTo(BvhLeaf.SPHERE);
            assertThat(new Triangle(a, b, c).packedKind()).isEqualTo(BvhLeaf.TRIANGLE);
            assertThat(new Ghost(a, 1).packedKind()).isEqualTo(BvhLeaf.OWN);
            assertThat(new GhostTriangle(a, b, c).packedKind()).isEqualTo(BvhLeaf.OWN);
            assertThat(new Polygon(a, b, c).packedKind()).isEqualTo(BvhLeaf.OWN);
            double[] v = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            int[] tri = { 0, 1, 2 };
            assertThat(new TriangleMesh(v, tri).packedKind()).isEqualTo(BvhLeaf.TRIANGLE);
            assertThat(new TriangleMesh(v, tri) {
            }.packedKind()).as("a user's mesh subclass").isEqualTo(BvhLeaf.OWN);
        }

        @Test
        @DisplayName("a subclass's overridden hooks are called: its shapes are not hit, the library's are")
        void subclassesAreAsked() {
            Geometries g = new Geometries();
            List<Geometry> real = new ArrayList<>();
            for (int i = 0; i < 20; ++i) {
                Point p = new Point(3 * i, 0, 0);
                if (i % 2 == 0) {
                    g.add(new Ghost(p, 1), new GhostTriangle(p.add(new Vector(0, -1, 2)), p.add(new Vector(1, 1, 2)), p.add(new Vector(-1, 1, 2))));
                } else {
                    Geometry s = new Sphere(p, 1), t = new Triangle(p.add(new Vector(0, -1, 2)), p.add(new Vector(1, 1, 2)), p.add(new Vector(-1, 1, 2)));
                    g.add(s, t);
                    real.add(s);
                    real.add(t);
                }
            }
            Bvh tree = Bvh.build(g);
            for (int i = 0; i < 20; ++i) {
                Ray down = new Ray(new Point(3 * i, 0, 10), new Vector(0, 0, -1));
                Visit closest = Hits.closest(tree, down, Double.POSITIVE_INFINITY);
                List<Visit> visits = Hits.visited(tree, down, Double.POSITIVE_INFINITY);
                if (i % 2 == 0) {
                    assertThat(closest).as("closest hit over ghosts %d", i).isNull();
                    assertThat(visits).as("walk over ghosts %d", i).isEmpty();
                } else {
                    assertThat(closest).as("closest hit over shapes %d", i).isNotNull();
                    assertThat(closest.geometry()).as("the triangle above sphere %d", i).isSameAs(real.get(i));
                    assertThat(visits).extracting(Visit::geometry).as("walk over shapes %d", i)
                            .containsExactlyInAnyOrder(real.get(i), real.get(i - 1), real.get(i - 1));
                }
            }
        }

        @Test
        @DisplayName("the packed numbers take memory only when something is packed")
        void indexBytes() {
            Geometries polygons = new Geometries();
            for (int i = 0; i < 50; ++i)
                polygons.add(new Polygon(new Point(i, 0, 0), new Point(i + 0.5, 0, 0), new Point(i + 0.5, 1, 0), new Point(i, 1, 0)));
            Bvh own = Bvh.build(polygons, 1, 4096, true, null); // binary nodes only: the scalar walk
            assertThat(own.indexBytes()).isEqualTo(own.nodeCount() * 32L + 50 * 9L);
            Bvh mesh = Bvh.build(new Geometries(gridMesh(20)), 1, 4096, true, null);
            assertThat(mesh.indexBytes()).isEqualTo(mesh.nodeCount() * 32L + mesh.primitiveTotal() * (9L + 72));
            Geometries spheres = new Geometries();
            for (int i = 0; i < 50; ++i) spheres.add(new Sphere(new Point(i, 0, 0), 0.4));
            Bvh packed = Bvh.build(spheres, 1, 4096, true, null);
            assertThat(packed.indexBytes()).isEqualTo(packed.nodeCount() * 32L + 50 * (9L + 72));
        }
    }

    @Nested
    @DisplayName("Bvh.of: one tree per unchanged scene, a new one when a shape is added anywhere")
    class Reuse {
        private final Geometries inner = new Geometries(new Sphere(new Point(5, 0, 0), 1));
        private final Geometries scene = new Geometries(new Sphere(Point.ZERO, 1),
                new Triangle(new Point(0, 0, 3), new Point(1, 0, 3), new Point(0, 1, 3)), inner,
                new Plane(new Point(0, 0, -5), new Vector(0, 0, 1)));

        @Test
        @DisplayName("the same library shapes: the same tree, which answers as a fresh build")
        void reused() {
            Bvh first = Bvh.of(scene);
            assertThat(Bvh.of(scene)).isSameAs(first);
            assertThat(first.sameTreeAs(Bvh.build(scene))).isTrue();
        }

        @Test
        @DisplayName("a shape added at the top or deep inside a nested list: a new tree that finds it")
        void rebuiltWhenAdded() {
            Bvh first = Bvh.of(scene);
            Ray ray = new Ray(new Point(-10, 10, 0), new Vector(1, 0, 0));
            assertThat(Hits.closest(first, ray, Double.POSITIVE_INFINITY)).isNull();
            Sphere deep = new Sphere(new Point(0, 10, 0), 1);
            inner.add(new Geometries(deep));
            Bvh second = Bvh.of(scene);
            assertThat(second).isNotSameAs(first);
            assertThat(Hits.closest(second, ray, Double.POSITIVE_INFINITY).geometry()).isSameAs(deep);
            Sphere top = new Sphere(new Point(-5, 10, 0), 1);
            scene.add(top);
            assertThat(Hits.closest(Bvh.of(scene), ray, Double.POSITIVE_INFINITY).geometry()).isSameAs(top);
        }

        @Test
        @DisplayName("a user's shape anywhere in the scene: never reused, as it may move between renders")
        void userShapesRebuilt() {
            inner.add(new Ghost(new Point(0, 20, 0), 1));
            Bvh first = Bvh.of(scene);
            assertThat(Bvh.of(scene)).isNotSameAs(first);
        }

        @Test
        @DisplayName("another list of the same shapes keeps its own tree")
        void perList() {
            Geometries other = new Geometries(scene.getItems().toArray(new Intersectable[0]));
            Bvh first = Bvh.of(scene);
            Bvh second = Bvh.of(other);
            assertThat(second).isNotSameAs(first);
            assertThat(second.sameTreeAs(first)).isTrue();
            assertThat(Bvh.of(scene)).isSameAs(first);
        }
    }

    @Nested
    @DisplayName("contract: a tree of bounded shapes")
    class BoundedContract extends ContractScenes.SceneContract {
        private final Bvh tree = Bvh.build(ContractScenes.bounded());

        @Override
        public Intersectable subject() {
            return tree;
        }
    }

    @Nested
    @DisplayName("contract: a tree of nested lists with planes and tubes beside it")
    class MixedContract extends ContractScenes.SceneContract {
        private final Bvh tree = Bvh.build(ContractScenes.mixed());

        @Override
        public Intersectable subject() {
            return tree;
        }

        @Override
        public boolean bounded() {
            return false;
        }
    }
}
