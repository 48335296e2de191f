package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.offset;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.function.Supplier;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;
import scene.io.ObjReader;

@DisplayName("TriangleMesh")
class TriangleMeshTest {

    /** The unit tetrahedron (0,0,0), x, y, z; every face wound so that its normal points outward. */
    static TriangleMesh tetrahedron() {
        double[] p = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        int[] t = { 0, 2, 1, /* z = 0 */ 0, 1, 3, /* y = 0 */ 0, 3, 2, /* x = 0 */ 1, 2, 3 /* slanted */ };
        return new TriangleMesh(p, t);
    }

    /**
     * Random triangles over a pool of shared random vertices in [-1, 1]^3: they overlap and cross,
     * which exercises the closest-hit order. Degenerate picks are skipped.
     */
    static TriangleMesh randomMesh(long seed, int vertices, int triangles) {
        Random random = new Random(seed);
        double[] p = new double[3 * vertices];
        for (int i = 0; i < p.length; ++i) p[i] = 2 * random.nextDouble() - 1;
        int[] t = new int[3 * triangles];
        for (int k = 0; k < triangles;) {
            int a = random.nextInt(vertices), b = random.nextInt(vertices), c = random.nextInt(vertices);
            if (TriangleMesh.isDegenerate(p, a, b, c)) continue;
            t[3 * k] = a;
            t[3 * k + 1] = b;
            t[3 * k + 2] = c;
            ++k;
        }
        return new TriangleMesh(p, t);
    }

    /**
     * A UV sphere of the given radius around the origin, stacks × slices quads (fans at the poles),
     * wound outward; with the exact unit normals of the sphere when {@code smooth}.
     */
    static TriangleMesh sphere(double radius, int stacks, int slices, boolean smooth) {
        int rings = stacks - 1; // rings of vertices between the poles
        double[] p = new double[3 * (rings * slices + 2)];
        for (int r = 0; r < rings; ++r) {
            double theta = Math.PI * (r + 1) / stacks;
            for (int s = 0; s < slices; ++s) {
                double phi = 2 * Math.PI * s / slices;
                int o = 3 * (r * slices + s);
                p[o] = radius * Math.sin(theta) * Math.cos(phi);
                p[o + 1] = radius * Math.cos(theta);
                p[o + 2] = radius * Math.sin(theta) * Math.sin(phi);
            }
        }
        int north = rings * slices, south = north + 1;
        p[3 * north + 1] = radius;
        p[3 * south + 1] = -radius;
        List<Integer> t = new ArrayList<>();
        for (int s = 0; s < slices; ++s) {
            int s1 = (s + 1) % slices;
            t.addAll(List.of(north, s1, s));
            for (int r = 0; r + 1 < rings; ++r) {
                int a = r * slices + s, b = r * slices + s1, c = (r + 1) * slices + s, d = (r + 1) * slices + s1;
                t.addAll(List.of(a, b, d, a, d, c));
            }
            int last = (rings - 1) * slices;
            t.addAll(List.of(south, last + s, last + s1));
        }
        int[] indices = t.stream().mapToInt(Integer::intValue).toArray();
        double[] normals = null;
        if (smooth) {
            normals = p.clone();
            for (int i = 0; i < normals.length; ++i) normals[i] /= radius;
        }
        return new TriangleMesh(p, indices, normals);
    }

    /** The triangles of {@code mesh} as {@link Triangle} objects, in triangle order. */
    static Triangle[] asTriangles(TriangleMesh mesh) {
        Triangle[] result = new Triangle[mesh.triangleCount()];
        for (int k = 0; k < result.length; ++k) {
            int[] v = mesh.getTriangleIndices(k);
            result[k] = new Triangle(mesh.getVertex(v[0]), mesh.getVertex(v[1]), mesh.getVertex(v[2]));
        }
        return result;
    }

    static Point centroid(Triangle triangle) {
        List<Point> v = triangle.vertices;
        return new Point((v.get(0).getX() + v.get(1).getX() + v.get(2).getX()) / 3,
                (v.get(0).getY() + v.get(1).getY() + v.get(2).getY()) / 3,
                (v.get(0).getZ() + v.get(1).getZ() + v.get(2).getZ()) / 3);
    }

    static Vector randomDirection(Random random) {
        while (true) {
            double x = 2 * random.nextDouble() - 1, y = 2 * random.nextDouble() - 1, z = 2 * random.nextDouble() - 1;
            double len2 = x * x + y * y + z * z;
            if (len2 > 0.01 && len2 <= 1) return new Vector(x, y, z);
        }
    }

    /**
     * Random rays from heads in [-2, 2]^3: half in random directions, half aimed at a random point of
     * the [-1, 1]^3 box so that most of them hit something.
     */
    static List<Ray> randomRays(long seed, int count) {
        Random random = new Random(seed);
        List<Ray> rays = new ArrayList<>(count);
        while (rays.size() < count) {
            Point head = new Point(4 * random.nextDouble() - 2, 4 * random.nextDouble() - 2, 4 * random.nextDouble() - 2);
            if (rays.size() % 2 == 0) {
                rays.add(new Ray(head, randomDirection(random)));
            } else {
                Point target = new Point(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1);
                if (!target.equals(head)) rays.add(new Ray(head, target.subtract(head)));
            }
        }
        return rays;
    }

    @Nested
    @DisplayName("construction")
    class Construction {
        @Test
        @DisplayName("counts triangles and vertices, unused vertices included")
        void counts() {
            TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5 }, new int[] { 0, 1, 2 });
            assertThat(mesh.triangleCount()).isEqualTo(1);
            assertThat(mesh.vertexCount()).isEqualTo(4);
            assertThat(mesh.hasVertexNormals()).isFalse();
            assertThat(tetrahedron().triangleCount()).isEqualTo(4);
        }

        @Test
        @DisplayName("the bounding box covers the triangles but not an unused vertex")
        void boundingBox() {
            TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 2, -1, 5, 5, 5 }, new int[] { 0, 1, 2 });
            BoundingBox box = mesh.getBoundingBox();
            assertThat(new double[] { box.getMinX(), box.getMinY(), box.getMinZ(), box.getMaxX(), box.getMaxY(), box.getMaxZ() })
                    .containsExactly(0, 0, -1, 1, 2, 0);
        }

        @Test
        @DisplayName("copies its arrays: changing them afterwards does not change the mesh")
        void defensiveCopies() {
            double[] p = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            int[] t = { 0, 1, 2 };
            double[] n = { 0, 0, 1, 0, 0, 1, 0, 0, 1 };
            TriangleMesh mesh = new TriangleMesh(p, t, n);
            p[3] = 7;
            t[1] = 0;
            n[2] = -1;
            assertThat(mesh.getVertex(1)).isEqualTo(new Point(1, 0, 0));
            assertThat(mesh.getTriangleIndices(0)).containsExactly(0, 1, 2);
            assertThat(mesh.getVertexNormal(0)).isEqualTo(new Vector(0, 0, 1));
        }

        @Test
        @DisplayName("normalizes the vertex normals it is given")
        void normalizesNormals() {
            TriangleMesh mesh = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 },
                    new double[] { 0, 0, 3, 0, 4, 3, 1e-3, 0, 0 });
            assertThat(mesh.hasVertexNormals()).isTrue();
            assertThat(mesh.getVertexNormal(0)).isEqualTo(new Vector(0, 0, 1));
            assertThat(mesh.getVertexNormal(1)).isEqualTo(new Vector(0, 0.8, 0.6));
            assertThat(mesh.getVertexNormal(2)).isEqualTo(new Vector(1, 0, 0));
        }

        @Test
        @DisplayName("accessors check their index; a flat mesh has no vertex normals")
        void accessors() {
            TriangleMesh mesh = tetrahedron();
            assertThatThrownBy(() -> mesh.getVertex(4)).isInstanceOf(IndexOutOfBoundsException.class).hasMessageContaining("4");
            assertThatThrownBy(() -> mesh.getTriangleIndices(-1)).isInstanceOf(IndexOutOfBoundsException.class);
            assertThatThrownBy(() -> mesh.getVertexNormal(0)).isInstanceOf(IllegalStateException.class)
                    .hasMessageContaining("no vertex normals");
        }

        static Stream<Arguments> invalid() {
            double[] three = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
            double[] four = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
            return Stream.of(
                    Arguments.of("positions length not a multiple of 3",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(new double[] { 0, 0, 0, 1, 0 }, new int[] { 0, 1, 2 }),
                            "positions length 5 is not a multiple of 3"),
                    Arguments.of("indices length not a multiple of 3",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(three, new int[] { 0, 1, 2, 0 }),
                            "indices length 4 is not a multiple of 3"),
                    Arguments.of("no triangle",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(three, new int[0]), "at least one triangle"),
                    Arguments.of("index past the last vertex",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(three, new int[] { 0, 1, 3 }),
                            "triangle 0 has vertex index 3 outside 0..2"),
                    Arguments.of("negative index",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(four, new int[] { 0, 1, 2, 0, -1, 3 }),
                            "triangle 1 has vertex index -1 outside 0..3"),
                    Arguments.of("non-finite coordinate",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(new double[] { 0, 0, 0, Double.NaN, 0, 0, 0, 1, 0 },
                                    new int[] { 0, 1, 2 }),
                            "vertex 1 (NaN,0.0,0.0) has a non-finite coordinate"),
                    Arguments.of("a vertex repeated in a triangle",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(four, new int[] { 0, 1, 2, 3, 1, 3 }),
                            "triangle 1 (vertices 3 (0.0,0.0,1.0), 1 (1.0,0.0,0.0), 3 (0.0,0.0,1.0)) is degenerate: two vertices coincide"),
                    Arguments.of("two vertices at the same place",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 1, 0, 0 },
                                    new int[] { 0, 1, 2 }),
                            "triangle 0 (vertices 0 (0.0,0.0,0.0), 1 (1.0,0.0,0.0), 2 (1.0,0.0,0.0)) is degenerate: two vertices coincide"),
                    Arguments.of("collinear vertices",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(new double[] { 0, 0, 0, 1, 1, 1, 2, 2, 2 },
                                    new int[] { 0, 1, 2 }),
                            "triangle 0 (vertices 0 (0.0,0.0,0.0), 1 (1.0,1.0,1.0), 2 (2.0,2.0,2.0)) is degenerate: its vertices are collinear"),
                    Arguments.of("normals not one per vertex",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(three, new int[] { 0, 1, 2 }, new double[] { 0, 0, 1 }),
                            "normals length 3 must equal positions length 9"),
                    Arguments.of("zero normal",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(three, new int[] { 0, 1, 2 },
                                    new double[] { 0, 0, 1, 0, 0, 1, 0, 0, 0 }),
                            "normal of vertex 2 (0.0,0.0,0.0) must be finite and non-zero"),
                    Arguments.of("infinite normal",
                            (Supplier<TriangleMesh>) () -> new TriangleMesh(three, new int[] { 0, 1, 2 },
                                    new double[] { 0, 0, 1, 0, Double.POSITIVE_INFINITY, 1, 0, 0, 1 }),
                            "normal of vertex 1 (0.0,Infinity,1.0) must be finite and non-zero"));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("invalid")
        @DisplayName("rejects, naming the culprit:")
        void rejects(String what, Supplier<TriangleMesh> construction, String message) {
            assertThatThrownBy(construction::get).isInstanceOf(IllegalArgumentException.class).hasMessageContaining(message);
        }

        @Test
        @DisplayName("rejects null arrays")
        void rejectsNull() {
            assertThatThrownBy(() -> new TriangleMesh(null, new int[] { 0, 1, 2 })).isInstanceOf(NullPointerException.class)
                    .hasMessageContaining("positions");
            assertThatThrownBy(() -> new TriangleMesh(new double[9], null)).isInstanceOf(NullPointerException.class)
                    .hasMessageContaining("indices");
        }

        /** The triangle (0,0,0), (s,0,0), (x·s, h·s, 0): scale s, apex offset x and height h relative to s. */
        @ParameterizedTest(name = "{0}: degenerate = {4}")
        @CsvSource({
                "ordinary,              1,     0.3,  1,     false",
                "coincident apex,       1,     1,    0,     true",
                "collinear apex,        1,     2,    0,     true",
                "sliver 1e-9 thin,      1,     0.5,  1e-9,  false",
                "sliver 1e-11 thin,     1,     0.5,  1e-11, true",
                "small (1e-5),          1e-5,  0,    1,     false",
                "tiny (1e-7),           1e-7,  0,    1,     true",
                "large (1e6),           1e6,   0.5,  1,     false" })
        @DisplayName("isDegenerate agrees with the Triangle constructor:")
        void degeneracyAgreesWithTriangle(String what, double s, double x, double h, boolean degenerate) {
            double[] p = { 0, 0, 0, s, 0, 0, x * s, h * s, 0 };
            assertThat(TriangleMesh.isDegenerate(p, 0, 1, 2)).isEqualTo(degenerate);
            Supplier<Triangle> triangle = () -> new Triangle(new Point(p[0], p[1], p[2]), new Point(p[3], p[4], p[5]),
                    new Point(p[6], p[7], p[8]));
            if (degenerate) {
                assertThatThrownBy(triangle::get).isInstanceOf(IllegalArgumentException.class);
                assertThatThrownBy(() -> new TriangleMesh(p, new int[] { 0, 1, 2 })).isInstanceOf(IllegalArgumentException.class)
                        .hasMessageContaining("triangle 0").hasMessageContaining("degenerate");
            } else {
                assertThatCode(triangle::get).doesNotThrowAnyException();
                assertThatCode(() -> new TriangleMesh(p, new int[] { 0, 1, 2 })).doesNotThrowAnyException();
            }
        }
    }

    @Nested
    @DisplayName("gives the same hits as the same triangles as Triangle objects")
    @TestInstance(TestInstance.Lifecycle.PER_CLASS)
    class SameAsTriangles {
        private final TriangleMesh mesh = randomMesh(42, 150, 300);
        private final Triangle[] triangles = asTriangles(mesh);
        private final List<Ray> rays = randomRays(7, 3000);

        private int indexOf(Geometry geometry) {
            for (int k = 0; k < triangles.length; ++k)
                if (triangles[k] == geometry) return k;
            return -1;
        }

        /** Closest hits of {@code meshSide} and {@code triangleSide}: same distance bits, same triangle. */
        private void assertSameClosestHits(Intersectable meshSide, Intersectable triangleSide) {
            Random bounds = new Random(3);
            int hits = 0;
            for (int i = 0; i < rays.size(); ++i) {
                Ray ray = rays.get(i);
                // Every third query starts with a finite bound, as a reflection query in a scene would.
                double tMax = i % 3 == 0 ? 4 * bounds.nextDouble() : Double.POSITIVE_INFINITY;
                Hit a = new Hit().reset(tMax), b = new Hit().reset(tMax);
                boolean foundA = meshSide.closestHit(ray, a), foundB = triangleSide.closestHit(ray, b);
                assertThat(foundA).as("found for %s", ray).isEqualTo(foundB);
                if (!foundA) continue;
                ++hits;
                assertThat(a.getGeometry()).isSameAs(mesh);
                assertThat(a.getT()).as("t for %s", ray).isEqualTo(b.getT());
                assertThat(a.primitive).as("triangle for %s", ray).isEqualTo(indexOf(b.getGeometry()));
            }
            assertThat(hits).as("rays that hit (the comparison must not be vacuous)").isGreaterThan(rays.size() / 3);
        }

        @Test
        @DisplayName("closest hit, as a flat list")
        void closestHitFlat() {
            assertSameClosestHits(mesh, new Geometries(triangles));
        }

        @Test
        @DisplayName("closest hit, through a BVH (one primitive per triangle)")
        void closestHitBvh() {
            Bvh meshBvh = Bvh.build(new Geometries(mesh));
            assertThat(meshBvh.primitiveTotal()).isEqualTo(mesh.triangleCount());
            assertSameClosestHits(meshBvh, Bvh.build(new Geometries(triangles)));
        }

        private static List<Double> visited(Intersectable geometry, Ray ray, double maxDistance) {
            List<Double> ts = new ArrayList<>();
            geometry.visitHits(ray, maxDistance, (g, t) -> ts.add(t));
            ts.sort(null);
            return ts;
        }

        @Test
        @DisplayName("any-hit walk: the same distances, within the same maximum distance, flat and through a BVH")
        void visitHits() {
            Intersectable flatTriangles = new Geometries(triangles);
            Bvh meshBvh = Bvh.build(new Geometries(mesh));
            Random random = new Random(5);
            int visits = 0;
            for (Ray ray : rays) {
                double maxDistance = random.nextBoolean() ? Double.POSITIVE_INFINITY : 4 * random.nextDouble();
                List<Double> expected = visited(flatTriangles, ray, maxDistance);
                assertThat(visited(mesh, ray, maxDistance)).as("flat mesh, %s", ray).isEqualTo(expected);
                assertThat(visited(meshBvh, ray, maxDistance)).as("mesh BVH, %s", ray).isEqualTo(expected);
                visits += expected.size();
            }
            assertThat(visits).isGreaterThan(rays.size());
        }

        @Test
        @DisplayName("the walk stops when the visitor says so")
        void visitStops() {
            Ray through = new Ray(new Point(0.1, 0.1, -1), new Vector(0, 0, 1));
            TriangleMesh stack = new TriangleMesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1 },
                    new int[] { 0, 1, 2, 3, 4, 5 });
            int[] calls = { 0 };
            assertThat(stack.visitHits(through, Double.POSITIVE_INFINITY, (g, t) -> ++calls[0] < 0)).isFalse();
            assertThat(calls[0]).isEqualTo(1);
        }

        @Test
        @DisplayName("course list API: the same intersection points")
        void findGeoIntersections() {
            Geometries flatTriangles = new Geometries(triangles);
            for (Ray ray : rays) {
                List<Intersectable.GeoPoint> expected = flatTriangles.findGeoIntersections(ray);
                List<Intersectable.GeoPoint> actual = mesh.findGeoIntersections(ray);
                if (expected == null) {
                    assertThat(actual).isNull();
                    continue;
                }
                assertThat(actual).hasSameSizeAs(expected).allSatisfy(gp -> assertThat(gp.geometry).isSameAs(mesh));
                assertThat(sortedDistances(actual, ray)).isEqualTo(sortedDistances(expected, ray));
            }
        }

        private static List<Double> sortedDistances(List<Intersectable.GeoPoint> points, Ray ray) {
            List<Double> d = new ArrayList<>();
            for (Intersectable.GeoPoint gp : points) d.add(gp.point.distance(ray.getHead()));
            d.sort(null);
            return d;
        }
    }

    @Nested
    @DisplayName("primitive hooks for the BVH")
    class PrimitiveHooks {
        private final TriangleMesh mesh = randomMesh(11, 40, 60);
        private final Triangle[] triangles = asTriangles(mesh);

        @Test
        @DisplayName("one primitive per triangle, bounded like the Triangle")
        void bounds() {
            assertThat(mesh.primitiveCount()).isEqualTo(60);
            BoundingBox all = null;
            for (int k = 0; k < triangles.length; ++k) {
                BoundingBox expected = triangles[k].getBoundingBox(), actual = mesh.primitiveBounds(k);
                assertThat(actual).usingRecursiveComparison().as("triangle %d", k).isEqualTo(expected);
                all = all == null ? expected : all.union(expected);
            }
            assertThat(mesh.getBoundingBox()).usingRecursiveComparison().isEqualTo(all);
        }

        @Test
        @DisplayName("a mesh of one triangle is bounded like that triangle (the BVH then uses the mesh's box for it)")
        void oneTriangle() {
            double[] positions = new double[3 * mesh.vertexCount()]; // all 40 vertices, 3 of them used
            for (int i = 0; i < mesh.vertexCount(); ++i) {
                Point p = mesh.getVertex(i);
                positions[3 * i] = p.getX();
                positions[3 * i + 1] = p.getY();
                positions[3 * i + 2] = p.getZ();
            }
            for (int k = 0; k < triangles.length; ++k) {
                TriangleMesh one = new TriangleMesh(positions, mesh.getTriangleIndices(k));
                assertThat(one.getBoundingBox()).usingRecursiveComparison().as("triangle %d", k)
                        .isEqualTo(one.primitiveBounds(0)).isEqualTo(triangles[k].getBoundingBox());
            }
        }

        @Test
        @DisplayName("a primitive query tests only its own triangle and records its index")
        void primitiveQueries() {
            for (int k = 0; k < triangles.length; ++k) {
                Vector normal = triangles[k].getNormal(centroid(triangles[k]));
                Point head = centroid(triangles[k]).add(normal.scale(3));
                Ray ray = new Ray(head, normal.scale(-1));
                Hit hit = new Hit().reset(Double.POSITIVE_INFINITY);
                assertThat(mesh.closestHit(k, ray, hit)).as("triangle %d", k).isTrue();
                assertThat(hit.primitive).isEqualTo(k);
                assertThat(hit.getT()).isCloseTo(3, offset(1e-9));
                List<Double> seen = new ArrayList<>();
                assertThat(mesh.visitHits(k, ray, Double.POSITIVE_INFINITY, (g, t) -> seen.add(t))).isTrue();
                assertThat(seen).containsExactly(hit.getT());
                // Another triangle is tested alone: it reports only its own crossing of the ray, if any.
                int other = (k + 1) % triangles.length;
                Hit otherHit = new Hit().reset(Double.POSITIVE_INFINITY);
                assertThat(mesh.closestHit(other, ray, otherHit)).isEqualTo(triangles[other].closestHit(ray, new Hit().reset(
                        Double.POSITIVE_INFINITY)));
            }
        }
    }

    @Nested
    @DisplayName("normals")
    class Normals {
        @Test
        @DisplayName("flat: at every hit, exactly the normal of the same Triangle")
        void flatMatchesTriangle() {
            TriangleMesh mesh = randomMesh(13, 100, 200);
            Triangle[] triangles = asTriangles(mesh);
            Intersectable world = new Geometries(triangles);
            int hits = 0;
            for (Ray ray : randomRays(17, 1000)) {
                Hit a = new Hit().reset(Double.POSITIVE_INFINITY), b = new Hit().reset(Double.POSITIVE_INFINITY);
                if (!mesh.closestHit(ray, a)) continue;
                world.closestHit(ray, b);
                ++hits;
                Point p = a.point(ray);
                Vector expected = b.normal(p), actual = a.normal(p);
                assertThat(new double[] { actual.getX(), actual.getY(), actual.getZ() })
                        .containsExactly(expected.getX(), expected.getY(), expected.getZ());
            }
            assertThat(hits).isGreaterThan(200);
        }

        @ParameterizedTest(name = "face {0}: point {1} gives normal {2}")
        @CsvSource(delimiter = ';', value = {
                "z = 0;    0.2 0.3 0;      0 0 -1",
                "y = 0;    0.2 0 0.3;      0 -1 0",
                "x = 0;    0 0.2 0.3;      -1 0 0",
                "slanted;  0.3 0.3 0.4;    1 1 1",
                "x = 0, point just outside;  -1e-3 0.2 0.3;  -1 0 0",
                "slanted, point beyond it;   1 1 1;  1 1 1" })
        @DisplayName("getNormal without a hit: the face containing (or nearest to) the point")
        void getNormalFindsTheFace(String face, String point, String normal) {
            double[] p = parse(point), n = parse(normal);
            assertThat(tetrahedron().getNormal(new Point(p[0], p[1], p[2]))).isEqualTo(new Vector(n[0], n[1], n[2]).normalize());
        }

        private static double[] parse(String xyz) {
            String[] parts = xyz.trim().split("\\s+");
            return new double[] { Double.parseDouble(parts[0]), Double.parseDouble(parts[1]), Double.parseDouble(parts[2]) };
        }

        // One triangle in the plane z = 0 with tilted vertex normals (given unnormalized).
        private final double[] a = { 0, 0, 0 }, b = { 4, 0, 0 }, c = { 0, 4, 0 };
        private final double[] na = { 0, 0, 2 }, nb = { 1, 0, 1 }, nc = { 0, -3, 3 };
        private final TriangleMesh smooth = new TriangleMesh(concat(a, b, c), new int[] { 0, 1, 2 }, concat(na, nb, nc));

        private static double[] concat(double[]... parts) {
            double[] r = new double[3 * parts.length];
            for (int i = 0; i < parts.length; ++i) System.arraycopy(parts[i], 0, r, 3 * i, 3);
            return r;
        }

        /** The blend computed independently: the weighted sum of the unit vertex normals, normalized. */
        private Vector expectedSmooth(double wa, double wb, double wc) {
            double[] sum = new double[3];
            double[][] normals = { na, nb, nc };
            double[] weights = { wa, wb, wc };
            for (int i = 0; i < 3; ++i) {
                double[] n = normals[i];
                double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                for (int j = 0; j < 3; ++j) sum[j] += weights[i] * n[j] / length;
            }
            return new Vector(sum[0], sum[1], sum[2]).normalize();
        }

        private Point at(double wa, double wb, double wc) {
            return new Point(wa * a[0] + wb * b[0] + wc * c[0], wa * a[1] + wb * b[1] + wc * c[1], 0);
        }

        @ParameterizedTest(name = "barycentric ({0}, {1}, {2})")
        @CsvSource({ "1, 0, 0", "0, 1, 0", "0, 0, 1", "0.5, 0.5, 0", "0.25, 0.25, 0.5", "0.6, 0.3, 0.1" })
        @DisplayName("smooth: the barycentric blend of the vertex normals, through getNormal and through a hit")
        void smoothBlend(double wa, double wb, double wc) {
            Vector expected = expectedSmooth(wa, wb, wc);
            Point p = at(wa, wb, wc);
            assertClose(smooth.getNormal(p), expected);
            if (wa > 0 && wb > 0 && wc > 0) { // a ray through a vertex or an edge misses (course rule)
                Ray ray = new Ray(new Point(p.getX(), p.getY(), 5), new Vector(0, 0, -1));
                Hit hit = new Hit().reset(Double.POSITIVE_INFINITY);
                assertThat(smooth.closestHit(ray, hit)).isTrue();
                assertClose(hit.normal(hit.point(ray)), expected);
            }
        }

        @Test
        @DisplayName("smooth, where the vertex normals cancel: the face normal")
        void cancellingNormals() {
            TriangleMesh mesh = new TriangleMesh(concat(a, b, c), new int[] { 0, 1, 2 },
                    concat(new double[] { 1, 0, 0 }, new double[] { -1, 0, 0 }, new double[] { 0, 0, 1 }));
            assertThat(mesh.getNormal(at(0.5, 0.5, 0))).isEqualTo(new Vector(0, 0, 1));
        }

        private static void assertClose(Vector actual, Vector expected) {
            assertThat(actual.getX()).isCloseTo(expected.getX(), offset(1e-12));
            assertThat(actual.getY()).isCloseTo(expected.getY(), offset(1e-12));
            assertThat(actual.getZ()).isCloseTo(expected.getZ(), offset(1e-12));
        }
    }

    @Nested
    @DisplayName("renders pixel for pixel like the same Triangle objects")
    @TestInstance(TestInstance.Lifecycle.PER_CLASS)
    class Rendering {
        private static final int SIZE = 64;
        private TriangleMesh teapot;

        @BeforeAll
        void load() throws IOException {
            teapot = ObjReader.readResource("/models/teapot.obj");
        }

        /** The course's teapot benchmark settings (camera, material, light) at a small resolution. */
        private ImageWriter render(String name, boolean bvh, Geometry... geometries) {
            Scene scene = new Scene(name);
            Material material = new Material().setKd(0.5).setKs(0.5).setShininess(60);
            for (Geometry g : geometries) g.setEmission(new Color(200, 0, 0)).setMaterial(material);
            scene.geometries.add(geometries);
            scene.lights.add(new PointLight(new Color(500, 500, 500), new Point(100, 0, -100)).setKq(1e-6));
            ImageWriter image = new ImageWriter("mesh/" + name, SIZE, SIZE);
            Camera.getBuilder().setLocation(new Point(0, 0, -1000)).setDirection(Point.ZERO, Vector.AXIS_Y)
                    .setVpSize(200, 200).setVpDistance(1000).setImageWriter(image)
                    .setRayTracer(new RayTracerBasic(scene).setBvh(bvh)).setSummary(false).build().renderImage();
            return image;
        }

        private static void assertSamePixels(ImageWriter actual, ImageWriter expected) {
            for (int y = 0; y < SIZE; ++y)
                for (int x = 0; x < SIZE; ++x)
                    assertThat(Integer.toHexString(actual.getRgb(x, y))).as("%s pixel (%d,%d)", actual.getImageName(), x, y)
                            .isEqualTo(Integer.toHexString(expected.getRgb(x, y)));
        }

        /** Guards against a vacuous comparison: the object covers part of the image, shaded in many tones. */
        private static void assertShowsAShadedObject(ImageWriter image) {
            Set<Integer> colours = new HashSet<>();
            int covered = 0;
            for (int y = 0; y < SIZE; ++y)
                for (int x = 0; x < SIZE; ++x) {
                    colours.add(image.getRgb(x, y));
                    if (image.getRgb(x, y) != 0) ++covered;
                }
            assertThat(covered).isBetween(SIZE * SIZE / 10, SIZE * SIZE * 9 / 10);
            assertThat(colours).hasSizeGreaterThan(50);
        }

        @Test
        @DisplayName("the teapot as a mesh and as 992 Triangles, with the BVH on and off: four identical images")
        void teapot() {
            ImageWriter meshBvh = render("teapot-mesh", true, teapot);
            meshBvh.writeToImage();
            assertShowsAShadedObject(meshBvh);
            assertSamePixels(render("teapot-triangles", true, asTriangles(teapot)), meshBvh);
            assertSamePixels(render("teapot-mesh-flat-list", false, teapot), meshBvh);
            assertSamePixels(render("teapot-triangles-flat-list", false, asTriangles(teapot)), meshBvh);
        }

        @Test
        @DisplayName("a smooth-shaded sphere: the same with the BVH on and off, and unlike its flat-shaded self")
        void smoothSphere() {
            ImageWriter smooth = render("sphere-smooth", true, sphere(80, 12, 24, true));
            smooth.writeToImage();
            assertShowsAShadedObject(smooth);
            assertSamePixels(render("sphere-smooth-flat-list", false, sphere(80, 12, 24, true)), smooth);
            ImageWriter flat = render("sphere-flat", true, sphere(80, 12, 24, false));
            int differing = 0;
            for (int y = 0; y < SIZE; ++y)
                for (int x = 0; x < SIZE; ++x)
                    if (flat.getRgb(x, y) != smooth.getRgb(x, y)) ++differing;
            assertThat(differing).as("pixels where smooth shading changes the colour").isGreaterThan(SIZE * SIZE / 10);
        }
    }
}
