package scene.samples;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import geometries.Sphere;
import geometries.TriangleMesh;
import lighting.PointLight;
import primitives.Double3;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

@DisplayName("TeapotScene: the course's teapot with 400 spheres of steam")
class TeapotSceneTest {
    private final Scene scene = TeapotScene.create();

    private static List<Sphere> spheres(Scene s) {
        return s.geometries.getItems().stream().filter(Sphere.class::isInstance).map(Sphere.class::cast).toList();
    }

    @Nested
    @DisplayName("contents")
    class Contents {
        @Test
        @DisplayName("one mesh of 992 triangles with the course's material, and 400 spheres")
        void counts() {
            List<TriangleMesh> meshes = scene.geometries.getItems().stream().filter(TriangleMesh.class::isInstance)
                    .map(TriangleMesh.class::cast).toList();
            assertThat(meshes).singleElement().satisfies(m -> {
                assertThat(m.triangleCount()).isEqualTo(992);
                assertThat(m.getMaterial().kD).isEqualTo(new Double3(0.5));
                assertThat(m.getMaterial().kS).isEqualTo(new Double3(0.5));
                assertThat(m.getMaterial().nShininess).isEqualTo(60);
                assertThat(m.getEmission().getR()).isEqualTo(200);
                assertThat(m.getEmission().getG()).isZero();
            });
            assertThat(spheres(scene)).hasSize(TeapotScene.SPHERES).hasSize(400);
            assertThat(scene.geometries.getItems()).hasSize(401);
        }

        @Test
        @DisplayName("every sphere lies in the cone above the spout: height 0–70, radius ≤ 0.3 per unit of height")
        void spheresInTheCone() {
            Point apex = TeapotScene.CONE_APEX;
            assertThat(spheres(scene)).allSatisfy(s -> {
                Point c = s.getCenter();
                double h = c.getY() - apex.getY();
                double dx = c.getX() - apex.getX(), dz = c.getZ() - apex.getZ();
                assertThat(h).isBetween(0.0, 70.0);
                assertThat(Math.sqrt(dx * dx + dz * dz)).isLessThanOrEqualTo(0.3 * h + 1e-9);
                assertThat(s.getRadius()).isBetween(0.1, 1.0);
            });
        }

        @Test
        @DisplayName("the spheres fill the cone: some near the apex, some near the top")
        void spheresSpreadOverTheHeight() {
            double apexY = TeapotScene.CONE_APEX.getY();
            assertThat(spheres(scene)).anySatisfy(s -> assertThat(s.getCenter().getY() - apexY).isLessThan(10))
                    .anySatisfy(s -> assertThat(s.getCenter().getY() - apexY).isGreaterThan(60));
        }

        @Test
        @DisplayName("sphere materials: kD in [0, 0.1) per channel, kS 0.2, kR 0.1, kT 0")
        void sphereMaterials() {
            assertThat(spheres(scene)).allSatisfy(s -> {
                Double3 kd = s.getMaterial().kD;
                assertThat(List.of(kd.getD1(), kd.getD2(), kd.getD3())).allSatisfy(v -> assertThat(v).isBetween(0.0, 0.1));
                assertThat(s.getMaterial().kS).isEqualTo(new Double3(0.2));
                assertThat(s.getMaterial().kR).isEqualTo(new Double3(0.1));
                assertThat(s.getMaterial().kT).isEqualTo(Double3.ZERO);
            });
        }

        @Test
        @DisplayName("the course's light: one point light at (100, 0, -100)")
        void light() {
            assertThat(scene.lights).singleElement().isInstanceOf(PointLight.class)
                    .satisfies(l -> assertThat(((PointLight) l).getPosition()).isEqualTo(new Point(100, 0, -100)));
        }
    }

    @Nested
    @DisplayName("determinism")
    class Determinism {
        @Test
        @DisplayName("built twice, the spheres have identical centres and radii")
        void sameScene() {
            List<Sphere> a = spheres(scene), b = spheres(TeapotScene.create());
            for (int i = 0; i < a.size(); ++i) {
                Point ca = a.get(i).getCenter(), cb = b.get(i).getCenter();
                assertThat(List.of(ca.getX(), ca.getY(), ca.getZ(), a.get(i).getRadius()))
                        .containsExactly(cb.getX(), cb.getY(), cb.getZ(), b.get(i).getRadius());
            }
        }

        @Test
        @DisplayName("another seed moves the spheres")
        void otherSeed() {
            List<Sphere> a = spheres(scene), b = spheres(TeapotScene.create(TeapotScene.DEFAULT_SEED + 1));
            long same = 0;
            for (int i = 0; i < a.size(); ++i) if (a.get(i).getCenter().equals(b.get(i).getCenter())) ++same;
            assertThat(same).isZero();
        }
    }

    @Nested
    @DisplayName("camera()")
    class CameraView {
        @Test
        @DisplayName("the course's view: from (0, 0, -1000) toward the origin, +y up, 200×200 at 1000")
        void view() {
            Camera c = TeapotScene.camera().setImageWriter(new ImageWriter("teapot-test", 2, 2))
                    .setRayTracer(new RayTracerBasic(scene)).build();
            assertThat(c.getLocation()).isEqualTo(new Point(0, 0, -1000));
            assertThat(c.getVTo()).isEqualTo(new Vector(0, 0, 1));
            assertThat(c.getVUp()).isEqualTo(new Vector(0, 1, 0));
            // Looking down +z with +y up, right is -x: pixel (0, 0) of 2×2 is at (50, 50) on the view plane.
            Ray r = c.constructRay(2, 2, 0, 0);
            assertThat(r.getDirection()).isEqualTo(new Vector(50, 50, 1000).normalize());
        }

        @Test
        @DisplayName("the central camera ray hits the teapot")
        void centreSeesTheTeapot() {
            Ray centre = new Ray(TeapotScene.CAMERA_LOCATION, new Vector(0, 0, 1));
            assertThat(scene.geometries.findGeoIntersections(centre)).isNotNull()
                    .allSatisfy(gp -> assertThat(gp.geometry).isInstanceOf(TriangleMesh.class));
        }
    }
}
