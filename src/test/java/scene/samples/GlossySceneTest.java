package scene.samples;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.BoundingBox;
import geometries.Intersectable;
import geometries.Intersectable.GeoPoint;
import geometries.LeanQueries;
import geometries.Polygon;
import geometries.Sphere;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Double3;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

@DisplayName("GlossyScene: the second report's benchmark scene")
class GlossySceneTest {
    private final Scene scene = GlossyScene.create();

    private List<Sphere> spheres() {
        return scene.geometries.getItems().stream().filter(Sphere.class::isInstance).map(Sphere.class::cast).toList();
    }

    private List<Polygon> wall() {
        return scene.geometries.getItems().stream().filter(Polygon.class::isInstance).map(Polygon.class::cast).toList();
    }

    @Nested
    @DisplayName("contents")
    class Contents {
        @Test
        @DisplayName("8 spheres and 64 wall polygons, nothing else")
        void countsByKind() {
            assertThat(spheres()).hasSize(8);
            assertThat(wall()).hasSize(64);
            assertThat(scene.geometries.getItems()).hasSize(72);
        }

        @ParameterizedTest(name = "sphere at ({0}, {1}, {2}) r {3}: kD {4} kS {5} kT {6} kR {7}")
        @DisplayName("the report's eight spheres with their materials")
        @CsvSource({
                "125, -36, 50, 20, 0.3, 0.2, 0, 0",
                "125, 100, 50, 20, 0.25, 0.3, 0.22, 0",
                "0, -130, -90, 25, 0.25, 0.3, 0, 0.3",
                "0, -130, 90, 25, 0.25, 0.3, 0, 0.3",
                "-63, 30, -200, 50, 0.2, 0.2, 0, 0",
                "48, 30, -200, 50, 0.3, 0.2, 0, 0.1",
                "-180, 90, -70, 20, 0.3, 0.2, 0, 0",
                "-180, -36, -70, 20, 0.3, 0.4, 0.22, 0" })
        void reportSpheres(double x, double y, double z, double r, double kd, double ks, double kt, double kr) {
            Sphere s = spheres().stream().filter(sp -> sp.getCenter().equals(new Point(x, y, z))).findFirst()
                    .orElseThrow(() -> new AssertionError("no sphere centred at (" + x + "," + y + "," + z + ")"));
            assertThat(s.getRadius()).isEqualTo(r);
            assertThat(s.getMaterial().kD).isEqualTo(new Double3(kd));
            assertThat(s.getMaterial().kS).isEqualTo(new Double3(ks));
            assertThat(s.getMaterial().kT).isEqualTo(new Double3(kt));
            assertThat(s.getMaterial().kR).isEqualTo(new Double3(kr));
            assertThat(s.getMaterial().nShininess).isEqualTo(5);
        }

        @Test
        @DisplayName("the wall tiles [-250, 250]² at z = -250 with 62.5-unit squares")
        void wallTiles() {
            double area = 0;
            BoundingBox all = null;
            for (Polygon p : wall()) {
                BoundingBox b = LeanQueries.boundingBox(p);
                assertThat(b.getMaxX() - b.getMinX()).isCloseTo(62.5, within(1e-9));
                assertThat(b.getMaxY() - b.getMinY()).isCloseTo(62.5, within(1e-9));
                assertThat(b.getMinZ()).isEqualTo(-250);
                assertThat(b.getMaxZ()).isEqualTo(-250);
                area += (b.getMaxX() - b.getMinX()) * (b.getMaxY() - b.getMinY());
                all = all == null ? b : all.union(b);
            }
            // 64 squares of 62.5² covering the 500×500 box exactly can only tile it without overlap.
            assertThat(area).isCloseTo(500.0 * 500.0, within(1e-6));
            assertThat(all.getMinX()).isEqualTo(-250);
            assertThat(all.getMaxX()).isEqualTo(250);
            assertThat(all.getMinY()).isEqualTo(-250);
            assertThat(all.getMaxY()).isEqualTo(250);
        }

        @Test
        @DisplayName("the wall is glossy with the default spread; the spheres are not")
        void wallMaterial() {
            for (Polygon p : wall()) {
                assertThat(p.getMaterial().reflectionSpread).isEqualTo(GlossyScene.DEFAULT_WALL_SPREAD);
                assertThat(p.getMaterial().kR).isEqualTo(new Double3(0.5));
                assertThat(p.getMaterial().kD).isEqualTo(new Double3(0.2));
                assertThat(p.getMaterial().kS).isEqualTo(new Double3(0.2));
                assertThat(p.getMaterial().nShininess).isEqualTo(5);
            }
            for (Sphere s : spheres()) assertThat(s.getMaterial().reflectionSpread).isZero();
        }

        @Test
        @DisplayName("a ray between the spheres reaches the wall at z = -250")
        void wallIsSeen() {
            // Toward (200, -200, -250): left of every sphere's silhouette, inside a tile (not on an edge).
            Point head = GlossyScene.CAMERA_LOCATION;
            Ray ray = new Ray(head, new Point(200, -200, -250).subtract(head));
            List<GeoPoint> hits = scene.geometries.findGeoIntersections(ray);
            assertThat(hits).hasSize(1);
            assertThat(hits.get(0).geometry).isInstanceOf(Polygon.class);
            assertThat(hits.get(0).point.getZ()).isCloseTo(-250, within(1e-9));
        }

        @Test
        @DisplayName("lights: one directional, two point and one spot light")
        void lights() {
            List<LightSource> lights = scene.lights;
            assertThat(lights).hasSize(4);
            assertThat(lights).filteredOn(l -> l instanceof DirectionalLight).hasSize(1);
            assertThat(lights).filteredOn(l -> l instanceof SpotLight).hasSize(1);
            assertThat(lights).filteredOn(l -> l instanceof PointLight && !(l instanceof SpotLight)).hasSize(2)
                    .allSatisfy(l -> assertThat(((PointLight) l).getPosition().getZ()).isEqualTo(-60));
        }
    }

    @Nested
    @DisplayName("the wall spread parameter")
    class Spread {
        @ParameterizedTest(name = "spread {0}")
        @ValueSource(doubles = { 0, 0.01, 0.3 })
        void spreadGoesToEveryTile(double spread) {
            Scene s = GlossyScene.create(spread);
            assertThat(s.geometries.getItems()).filteredOn(Polygon.class::isInstance).hasSize(64)
                    .allSatisfy(g -> assertThat(((Polygon) g).getMaterial().reflectionSpread).isEqualTo(spread));
        }

        @ParameterizedTest(name = "spread {0}")
        @ValueSource(doubles = { -0.1, Double.NaN, Double.POSITIVE_INFINITY })
        void badSpreadIsRejected(double spread) {
            assertThatThrownBy(() -> GlossyScene.create(spread)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("spread");
        }

        @Test
        @DisplayName("two scenes do not share the wall material (changing one leaves the other)")
        void independentScenes() {
            Scene other = GlossyScene.create();
            ((Polygon) other.geometries.getItems().get(8)).getMaterial().setReflectionSpread(0.9);
            assertThat(wall()).allSatisfy(p -> assertThat(p.getMaterial().reflectionSpread)
                    .isEqualTo(GlossyScene.DEFAULT_WALL_SPREAD));
        }
    }

    @Nested
    @DisplayName("camera()")
    class CameraView {
        private Camera camera(int n) {
            return GlossyScene.camera().setImageWriter(new ImageWriter("glossy-test", n, n))
                    .setRayTracer(new RayTracerBasic(scene)).build();
        }

        @Test
        @DisplayName("stands at (0, 0, 1000) looking down -z with +y up")
        void view() {
            Camera c = camera(10);
            assertThat(c.getLocation()).isEqualTo(new Point(0, 0, 1000));
            assertThat(c.getVTo()).isEqualTo(new Vector(0, 0, -1));
            assertThat(c.getVUp()).isEqualTo(new Vector(0, 1, 0));
        }

        @Test
        @DisplayName("the 600×600 view plane at 1000 frames ±300 at z = 0")
        void framing() {
            // 2×2 pixels: pixel (0, 0)'s centre is at (-150, 150) on the view plane at z = 0.
            Ray corner = camera(2).constructRay(2, 2, 0, 0);
            assertThat(corner.getDirection()).isEqualTo(new Vector(-150, 150, -1000).normalize());
        }
    }

    @Test
    @DisplayName("each create() builds a new scene")
    void freshInstances() {
        Scene other = GlossyScene.create();
        assertThat(other).isNotSameAs(scene);
        assertThat(other.geometries.getItems()).doesNotContainAnyElementsOf(List.<Intersectable>copyOf(scene.geometries.getItems()));
    }
}
