package scene.samples;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.BoundingBox;
import geometries.Bvh;
import geometries.Hit;
import geometries.Intersectable;
import geometries.LeanQueries;
import geometries.Sphere;
import geometries.Triangle;
import lighting.DirectionalLight;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

@DisplayName("ScalingScene: n random spheres and n random triangles")
class ScalingSceneTest {

    private static List<Sphere> spheres(Scene s) {
        return s.geometries.getItems().stream().filter(Sphere.class::isInstance).map(Sphere.class::cast).toList();
    }

    private static List<Triangle> triangles(Scene s) {
        return s.geometries.getItems().stream().filter(Triangle.class::isInstance).map(Triangle.class::cast).toList();
    }

    @Nested
    @DisplayName("contents")
    class Contents {
        @ParameterizedTest(name = "n = {0}")
        @ValueSource(ints = { 1, 2, 10, 1000 })
        @DisplayName("2n geometries: n spheres and n triangles")
        void twoNGeometries(int n) {
            Scene s = ScalingScene.create(n);
            assertThat(s.geometries.getItems()).hasSize(2 * n);
            assertThat(spheres(s)).hasSize(n);
            assertThat(triangles(s)).hasSize(n);
        }

        @ParameterizedTest(name = "n = {0}")
        @ValueSource(ints = { 8, 1000 })
        @DisplayName("sphere centres lie in the cube and radii are 0.15–0.4 of a cell")
        void spheresInTheCube(int n) {
            double half = ScalingScene.SIDE / 2, cell = ScalingScene.SIDE / Math.cbrt(n);
            assertThat(spheres(ScalingScene.create(n))).allSatisfy(sp -> {
                Point c = sp.getCenter();
                assertThat(List.of(c.getX(), c.getY(), c.getZ())).allSatisfy(v -> assertThat(v).isBetween(-half, half));
                assertThat(sp.getRadius()).isBetween(0.15 * cell, 0.4 * cell);
            });
        }

        @ParameterizedTest(name = "n = {0}")
        @ValueSource(ints = { 8, 1000 })
        @DisplayName("triangles stay within a cell's reach of the cube")
        void trianglesNearTheCube(int n) {
            double reach = ScalingScene.SIDE / 2 + 0.4 * ScalingScene.SIDE / Math.cbrt(n);
            assertThat(triangles(ScalingScene.create(n))).allSatisfy(t -> {
                BoundingBox b = LeanQueries.boundingBox(t);
                assertThat(List.of(b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ()))
                        .allSatisfy(v -> assertThat(v).isBetween(-reach, reach));
            });
        }

        @Test
        @DisplayName("one directional light")
        void oneLight() {
            assertThat(ScalingScene.create(10).lights).singleElement().isInstanceOf(DirectionalLight.class);
        }

        @ParameterizedTest(name = "n = {0}")
        @ValueSource(ints = { 0, -1, ScalingScene.MAX_N + 1 })
        @DisplayName("n outside 1..MAX_N is rejected, naming it")
        void badN(int n) {
            assertThatThrownBy(() -> ScalingScene.create(n)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining(Integer.toString(n));
        }
    }

    @Nested
    @DisplayName("determinism")
    class Determinism {
        @Test
        @DisplayName("the same n and seed give identical spheres and triangles")
        void sameSeedSameScene() {
            Scene a = ScalingScene.create(500), b = ScalingScene.create(500);
            List<Sphere> sa = spheres(a), sb = spheres(b);
            for (int i = 0; i < sa.size(); ++i) {
                Point ca = sa.get(i).getCenter(), cb = sb.get(i).getCenter();
                assertThat(new double[] { ca.getX(), ca.getY(), ca.getZ(), sa.get(i).getRadius() })
                        .containsExactly(cb.getX(), cb.getY(), cb.getZ(), sb.get(i).getRadius());
            }
            List<Triangle> ta = triangles(a), tb = triangles(b);
            for (int i = 0; i < ta.size(); ++i) {
                BoundingBox ba = LeanQueries.boundingBox(ta.get(i)), bb = LeanQueries.boundingBox(tb.get(i));
                assertThat(new double[] { ba.getMinX(), ba.getMinY(), ba.getMinZ(), ba.getMaxX(), ba.getMaxY(), ba.getMaxZ() })
                        .containsExactly(bb.getMinX(), bb.getMinY(), bb.getMinZ(), bb.getMaxX(), bb.getMaxY(), bb.getMaxZ());
            }
        }

        @Test
        @DisplayName("another seed gives other sphere centres")
        void otherSeedOtherScene() {
            List<Sphere> a = spheres(ScalingScene.create(50, 1)), b = spheres(ScalingScene.create(50, 2));
            long same = 0;
            for (int i = 0; i < a.size(); ++i) if (a.get(i).getCenter().equals(b.get(i).getCenter())) ++same;
            assertThat(same).isZero();
        }
    }

    @Nested
    @DisplayName("camera()")
    class CameraView {
        private Camera camera(Scene s, int n) {
            return ScalingScene.camera().setImageWriter(new ImageWriter("scaling-test", n, n))
                    .setRayTracer(new RayTracerBasic(s)).build();
        }

        @Test
        @DisplayName("the view plane is the cube's front face")
        void framing() {
            // 2×2 pixels: pixel (0, 0)'s centre is at (-50, 50) on the view plane, which lies at z = 100.
            Ray r = camera(ScalingScene.create(1), 2).constructRay(2, 2, 0, 0);
            assertThat(r.getHead()).isEqualTo(new Point(0, 0, 450));
            assertThat(r.getDirection()).isEqualTo(new Vector(-50, 50, -350).normalize());
        }

        @Test
        @DisplayName("from n = 10³ on, most camera rays hit something")
        void pictureIsFilled() {
            for (int n : new int[] { 1000, 20000 }) {
                Scene s = ScalingScene.create(n);
                Intersectable world = Bvh.build(s.geometries);
                Camera c = camera(s, 20);
                Hit hit = new Hit();
                int hits = 0;
                for (int i = 0; i < 20; ++i)
                    for (int j = 0; j < 20; ++j)
                        if (LeanQueries.closestHit(world, c.constructRay(20, 20, j, i), hit.reset(Double.POSITIVE_INFINITY))) ++hits;
                assertThat(hits).as("camera rays hitting the scene of n = %d, out of 400", n).isGreaterThan(200);
            }
        }
    }

    @Test
    @DisplayName("primitives share a small palette of materials")
    void sharedMaterials() {
        Scene s = ScalingScene.create(2000);
        long materials = s.geometries.getItems().stream().map(g -> ((geometries.Geometry) g).getMaterial())
                .distinct().count();
        assertThat(materials).isLessThanOrEqualTo(8);
    }
}
