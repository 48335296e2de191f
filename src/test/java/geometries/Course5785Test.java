package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.assertThatIllegalStateException;
import static org.assertj.core.api.Assertions.assertThatNullPointerException;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import geometries.Intersectable.Intersection;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.CameraValues;
import renderer.ImageWriter;
import renderer.RayTracerType;
import renderer.Sampling;
import renderer.SimpleRayTracer;
import renderer.View;
import scene.Scene;

/**
 * The 2024–25 (5785) course API, written the way that year's tests are written: its names only
 * ({@code calculateIntersections}, {@code Intersection}, {@code setResolution},
 * {@code setRayTracer(scene, RayTracerType)}, {@code writeToImage(name)}, {@code setKA},
 * {@code AmbientLight(Color)}, {@code d1()}), one nested class per class under test. In package
 * {@code geometries} because the course's tests call the protected hook there.
 */
class Course5785Test {
    private static final Vector Y = new Vector(0, 1, 0);

    private static void assertVector(Vector actual, double x, double y, double z) {
        assertThat(new double[] { actual.getX(), actual.getY(), actual.getZ() })
                .containsExactly(new double[] { x, y, z }, within(1e-12));
    }

    @Nested
    @DisplayName("Camera (5785: testBuilder, constructRay, integration)")
    class CameraTest {
        /** Built as the 5785 integration tests build: no image writer, tracer or resolution. */
        private final Camera.Builder cameraBuilder = Camera.getBuilder().setLocation(Point.ZERO)
                .setDirection(new Vector(0, 0, -1), new Vector(0, -1, 0)).setVpSize(3, 3).setVpDistance(1);

        @Test
        @DisplayName("BV01: a target straight along the +y up hint is an IllegalArgumentException")
        void targetAlongUpHint() {
            assertThatIllegalArgumentException().isThrownBy(
                    () -> Camera.getBuilder().setLocation(Point.ZERO).setVpSize(1, 1).setVpDistance(1)
                            .setDirection(new Point(0, 10, 0)).build());
        }

        @Test
        @DisplayName("setDirection(target): right = to x +y, up = right x to")
        void targetWithUpHint() {
            Camera camera = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(10, -10, 0))
                    .setVpSize(2, 2).setVpDistance(1).build();
            double h = Math.sqrt(0.5);
            assertVector(camera.getVRight(), 0, 0, 1);
            assertVector(camera.getVUp(), h, h, 0);
            assertVector(camera.getVTo(), h, -h, 0);
            // Pixel (0,0) of 2x2 lies at centre + up*rY/2 - right*rX/2 (rX = rY = 1).
            Point centre = new Point(h, -h, 0);
            Point pixel = centre.add(camera.getVUp().scale(0.5)).add(camera.getVRight().scale(-0.5));
            assertThat(camera.constructRay(2, 2, 0, 0)).isEqualTo(new Ray(Point.ZERO, pixel.subtract(Point.ZERO)));
        }

        @Test
        @DisplayName("setDirection(target, up) re-orthogonalizes a non-orthogonal up")
        void targetWithUp() {
            Camera camera = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(0, 5, 0), new Vector(0, 1, 1))
                    .setVpSize(2, 2).setVpDistance(1).build();
            assertVector(camera.getVRight(), 1, 0, 0);
            assertVector(camera.getVUp(), 0, 0, 1);
        }

        private int hits(Intersectable geometry, Camera camera) {
            int count = 0;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    List<Intersection> found = geometry.calculateIntersections(camera.constructRay(3, 3, j, i));
                    if (found != null) count += found.size();
                }
            return count;
        }

        @Test
        @DisplayName("integration: a camera built without writer, tracer or resolution casts 3x3 rays at spheres")
        void integrationWithSpheres() {
            assertThat(hits(new Sphere(1, new Point(0, 0, -3)), cameraBuilder.build())).isEqualTo(2);
            Camera shifted = cameraBuilder.setLocation(new Point(0, 0, 0.5)).build();
            assertThat(hits(new Sphere(2.5, new Point(0, 0, -2.5)), shifted)).isEqualTo(18);
            assertThat(hits(new Sphere(2, new Point(0, 0, -2)), shifted)).isEqualTo(10);
            assertThat(hits(new Sphere(0.5, new Point(0, 0, 1)), shifted)).isZero();
        }

        @Test
        @DisplayName("setResolution + setRayTracer(scene, SIMPLE): render and writeToImage(name)")
        void renderAndWrite() throws Exception {
            Scene scene = new Scene("5785").setBackground(new Color(0, 255, 0));
            Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Y).setVpSize(5, 4)
                    .setVpDistance(1).setResolution(5, 4).setRayTracer(scene, RayTracerType.SIMPLE).setSummary(false)
                    .build().renderImage().printGrid(2, new Color(255, 0, 0)).writeToImage("course-years/5785");
            BufferedImage image = ImageIO.read(Path.of("images/course-years/5785.png").toFile());
            assertThat(image.getWidth()).isEqualTo(5);
            assertThat(image.getHeight()).isEqualTo(4);
            assertThat(image.getRGB(1, 1) & 0xFFFFFF).isEqualTo(0x00FF00);
            assertThat(image.getRGB(4, 1) & 0xFFFFFF).isEqualTo(0xFF0000);
        }

        @Test
        @DisplayName("setMultithreading(-1) (the course's parallel streams) renders the same image as the calling thread")
        void parallelStreams() throws Exception {
            Scene scene = new Scene("5785 threads").setAmbientLight(new AmbientLight(new Color(40, 40, 40)));
            scene.geometries.add(new Sphere(20, new Point(0, 0, -100)).setEmission(new Color(90, 30, 10))
                    .setMaterial(new Material().setKD(0.5).setKS(0.5).setShininess(20)));
            scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(50, 50, 0)).setKl(0.001));
            int[][] images = new int[2][];
            int k = 0;
            for (int threads : new int[] { 0, -1 }) {
                String name = "course-years/5785-threads" + threads;
                Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Y).setVpSize(50, 50)
                        .setVpDistance(100).setResolution(40, 40).setRayTracer(scene, RayTracerType.SIMPLE)
                        .setMultithreading(threads).setSummary(false).build().renderImage().writeToImage(name);
                BufferedImage image = ImageIO.read(Path.of("images/" + name + ".png").toFile());
                images[k++] = image.getRGB(0, 0, 40, 40, null, 0, 40);
            }
            assertThat(images[1]).isEqualTo(images[0]);
            assertThat(images[0][20 * 40 + 20] & 0xFFFFFF).as("the sphere in the middle").isNotZero();
        }

        @Test
        @DisplayName("new Camera.Builder() is getBuilder()")
        void publicBuilderConstructor() {
            Camera camera = new Camera.Builder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Y)
                    .setVpSize(3, 3).setVpDistance(1).build();
            assertThat(camera.constructRay(3, 3, 0, 0)).isEqualTo(new Ray(Point.ZERO, new Vector(-1, 1, -1)));
            assertThat(camera.constructRay(3, 3, 0, 0)).isEqualTo(cameraBuilder.setDirection(new Vector(0, 0, -1), Y).build()
                    .constructRay(3, 3, 0, 0));
        }

        @Test
        @DisplayName("getBuilder(camera) starts from the camera's settings; its own writer per copy; the original unchanged")
        void builderFromACamera() throws Exception {
            Scene scene = new Scene("copy").setBackground(new Color(0, 0, 255));
            Camera first = Camera.getBuilder().setLocation(new Point(1, 2, 3)).setDirection(new Point(1, 2, -7), Y)
                    .setVpSize(4, 3).setVpDistance(10).setResolution(4, 3).setRayTracer(scene, RayTracerType.SIMPLE)
                    .setAntiAliasing(AntiAliasing.RANDOM, 2, 3).setDepthOfField(12, 0.5).setSeed(7).setSummary(false).build();
            Camera same = Camera.getBuilder(first).build();
            assertThat(same.getLocation()).isEqualTo(new Point(1, 2, 3));
            assertVector(same.getVTo(), 0, 0, -1);
            assertVector(same.getVUp(), 0, 1, 0);
            assertThat(CameraValues.of(same)).isEqualTo(CameraValues.of(first)).isEqualTo(new CameraValues(Sampling.DEFAULT
                    .withAntiAliasing(AntiAliasing.RANDOM).withGrid(2, 3).withSeed(7), View.Lens.thin(12, 0.5),
                    CameraValues.Tracer.DEFAULT));
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 4; ++j) assertThat(same.constructRay(j, i)).isEqualTo(first.constructRay(j, i));

            Camera moved = new Camera.Builder(first).setLocation(new Point(1, 2, 13)).build();
            assertThat(moved.constructRay(0, 0)).isEqualTo(new Ray(new Point(1, 2, 13), new Vector(-1.5, 1, -10)));
            assertThat(first.getLocation()).as("the original").isEqualTo(new Point(1, 2, 3));
            moved.renderImage().writeToImage("course-years/5785-copy");
            first.writeToImage("course-years/5785-original");
            assertThat(ImageIO.read(Path.of("images/course-years/5785-copy.png").toFile()).getRGB(0, 0) & 0xFFFFFF)
                    .isEqualTo(0x0000FF);
            assertThat(ImageIO.read(Path.of("images/course-years/5785-original.png").toFile()).getRGB(0, 0) & 0xFFFFFF)
                    .as("the original's image was not rendered into").isZero();
            assertThatNullPointerException().isThrownBy(() -> Camera.getBuilder(null)).withMessageContaining("camera");
            assertThatNullPointerException().isThrownBy(() -> new Camera.Builder(null)).withMessageContaining("camera");
        }

        @ParameterizedTest(name = "{0}")
        @EnumSource(RayTracerType.class)
        @DisplayName("both tracer types trace like SimpleRayTracer (GRID: the BVH-accelerated tracer)")
        void tracerTypes(RayTracerType type) throws Exception {
            Scene scene = new Scene("types").setAmbientLight(new AmbientLight(new Color(10, 20, 30)));
            scene.geometries.add(new Sphere(5, new Point(0, 0, -50)).setEmission(new Color(100, 0, 0)));
            // No resolution: the default 1x1 image, whose one ray hits the sphere's centre.
            Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Y).setVpSize(1, 1)
                    .setVpDistance(1).setRayTracer(scene, type).setSummary(false).build().renderImage()
                    .writeToImage("course-years/5785-" + type);
            BufferedImage image = ImageIO.read(Path.of("images/course-years/5785-" + type + ".png").toFile());
            assertThat(image.getRGB(0, 0) & 0xFFFFFF).as("emission (100,0,0) + ambient (10,20,30)").isEqualTo(0x6E141E);
            assertThatNullPointerException().isThrownBy(() -> Camera.getBuilder().setRayTracer(scene, null))
                    .withMessageContaining("type");
        }
    }

    @Nested
    @DisplayName("ImageWriter (5785)")
    class ImageWriterTest {
        @Test
        @DisplayName("ImageWriter(nX, nY) with nX()/nY(), named when written")
        void unnamed() throws Exception {
            ImageWriter writer = new ImageWriter(3, 2);
            assertThat(writer.nX()).isEqualTo(3);
            assertThat(writer.nY()).isEqualTo(2);
            writer.writePixel(2, 1, new Color(255, 255, 0));
            writer.writeToImage("course-years/5785-writer");
            BufferedImage image = ImageIO.read(Path.of("images/course-years/5785-writer.png").toFile());
            assertThat(image.getRGB(2, 1) & 0xFFFFFF).isEqualTo(0xFFFF00);
            assertThatIllegalStateException().isThrownBy(writer::writeToImage).withMessageContaining("no name");
        }

        @Test
        @DisplayName("bad sizes and names are rejected, naming them")
        void badInput() {
            assertThatIllegalArgumentException().isThrownBy(() -> new ImageWriter(0, 2)).withMessageContaining("0x2");
            assertThatIllegalArgumentException().isThrownBy(() -> new ImageWriter(2, -1)).withMessageContaining("2x-1");
            assertThatIllegalArgumentException().isThrownBy(() -> new ImageWriter(1, 1).writeToImage(" "))
                    .withMessageContaining("blank");
        }
    }

    @Nested
    @DisplayName("Material and AmbientLight (5785: kA moved to the material)")
    class MaterialTest {
        @Test
        @DisplayName("setKA/KD/KS/KT/KR set the fields; kA defaults to ONE")
        void setters() {
            Material m = new Material().setKA(new Double3(0.1, 0.2, 0.3)).setKD(0.4).setKS(new Double3(0.5)).setKT(0.6)
                    .setKR(new Double3(0.7, 0.8, 0.9)).setShininess(12);
            assertThat(m.kA).isEqualTo(new Double3(0.1, 0.2, 0.3));
            assertThat(m.kD).isEqualTo(new Double3(0.4));
            assertThat(m.kS).isEqualTo(new Double3(0.5));
            assertThat(m.kT).isEqualTo(new Double3(0.6));
            assertThat(m.kR).isEqualTo(new Double3(0.7, 0.8, 0.9));
            assertThat(new Material().kA).isEqualTo(Double3.ONE);
            assertThat(m.kA.d1()).isEqualTo(0.1);
            assertThat(m.kA.d3()).isEqualTo(0.3);
        }

        @Test
        @DisplayName("bad coefficients are rejected, naming them")
        void badCoefficients() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setKA(-1)).withMessageContaining("kA")
                    .withMessageContaining("-1");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setKT(1.5)).withMessageContaining("kT")
                    .withMessageContaining("1.5");
        }

        @Test
        @DisplayName("the ambient term is I_A scaled by the hit material's kA")
        void ambientScaledByKA() {
            Scene scene = new Scene("kA").setAmbientLight(new AmbientLight(new Color(200, 100, 50)));
            scene.geometries.add(new Sphere(10, new Point(0, 0, -50)).setMaterial(new Material().setKA(new Double3(0.5, 0.2, 0))));
            Color c = new SimpleRayTracer(scene).traceRay(new Ray(Point.ZERO, new Vector(0, 0, -1)));
            assertThat(new double[] { c.getR(), c.getG(), c.getB() }).containsExactly(new double[] { 100, 20, 0 }, within(1e-12));
            assertThat(new AmbientLight(new Color(200, 100, 50)).getIntensity().distance(new Color(200, 100, 50))).isZero();
            assertThatNullPointerException().isThrownBy(() -> new AmbientLight(null)).withMessageContaining("ambient intensity");
        }

        @Test
        @DisplayName("the ambient render test as several cohorts write it, with setKa (double and Double3)")
        void ambientWithSetKa() {
            Scene scene = new Scene("kA").setAmbientLight(new AmbientLight(new Color(200, 100, 50)));
            scene.geometries.add(new Sphere(10, new Point(0, 0, -50)).setMaterial(new Material().setKa(new Double3(0.5, 0.2, 0))),
                    new Sphere(10, new Point(0, 0, 50)).setMaterial(new Material().setKa(0.25)));
            SimpleRayTracer tracer = new SimpleRayTracer(scene);
            Color c = tracer.traceRay(new Ray(Point.ZERO, new Vector(0, 0, -1)));
            assertThat(new double[] { c.getR(), c.getG(), c.getB() }).containsExactly(new double[] { 100, 20, 0 }, within(1e-12));
            c = tracer.traceRay(new Ray(Point.ZERO, new Vector(0, 0, 1)));
            assertThat(new double[] { c.getR(), c.getG(), c.getB() }).containsExactly(new double[] { 50, 25, 12.5 }, within(1e-12));
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setKa(-0.1)).withMessageContaining("kA")
                    .withMessageContaining("-0.1");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setKa(new Double3(0, Double.POSITIVE_INFINITY, 0)))
                    .withMessageContaining("kA").withMessageContaining("Infinity");
        }
    }

    @Nested
    @DisplayName("Intersectable (5785: Intersection, calculateIntersections)")
    class IntersectableTest {
        private final Sphere sphere = new Sphere(1, new Point(1, 0, 0));
        private final Ray chord = new Ray(new Point(-1, 0.6, 0), new Vector(1, 0, 0));

        @Test
        @DisplayName("the protected helper and the public query find the two points of a chord")
        void sphereChord() {
            List<Intersection> expected = List.of(new Intersection(sphere, new Point(0.2, 0.6, 0)),
                    new Intersection(sphere, new Point(1.8, 0.6, 0)));
            assertThat(sphere.calculateIntersectionsHelper(chord, Double.POSITIVE_INFINITY)).containsExactlyInAnyOrderElementsOf(expected);
            assertThat(sphere.calculateIntersections(chord)).containsExactlyInAnyOrderElementsOf(expected);
            assertThat(chord.findClosestIntersection(sphere.calculateIntersections(chord))).isEqualTo(expected.get(0));
            assertThat(chord.findClosestIntersection(List.of())).isNull();
        }

        @Test
        @DisplayName("maxDistance: a hit exactly at it counts (the library keeps one inclusive rule for every year)")
        void maxDistanceInclusive() {
            assertThat(sphere.calculateIntersections(chord, 1.2)).containsExactly(new Intersection(sphere, new Point(0.2, 0.6, 0)));
            assertThat(sphere.calculateIntersections(chord, 1.1)).isNull();
        }

        @Test
        @DisplayName("no hit gives null: a shape, a Geometries, an empty Geometries")
        void noHitIsNull() {
            Ray away = new Ray(new Point(-1, 0, 0), new Vector(-1, 0, 0));
            assertThat(sphere.calculateIntersections(away)).isNull();
            assertThat(new Geometries(sphere, new Plane(new Point(5, 0, 0), new Vector(1, 0, 0))).calculateIntersections(away)).isNull();
            assertThat(new Geometries().calculateIntersections(away)).isNull();
        }

        @Test
        @DisplayName("Intersection: the geometry's material; equal for the same geometry instance and equal points")
        void intersectionRecord() {
            Material material = new Material().setKD(0.3);
            sphere.setMaterial(material);
            Intersection i = new Intersection(sphere, new Point(0.2, 0.6, 0));
            assertThat(i.material).isSameAs(material);
            assertThat(i).isEqualTo(new Intersection(sphere, new Point(0.2, 0.6, 0)));
            assertThat(i).isNotEqualTo(new Intersection(new Sphere(1, new Point(1, 0, 0)), new Point(0.2, 0.6, 0)));
            assertThat(i).isNotEqualTo(new Intersection(sphere, new Point(1.8, 0.6, 0)));
            i.normal = new Vector(-1, 0, 0);
            i.vNormal = -0.5;
            assertThat(i).as("the mutable shading fields take no part").isEqualTo(new Intersection(sphere, new Point(0.2, 0.6, 0)));
            assertThatNullPointerException().isThrownBy(() -> new Intersection(null, Point.ZERO)).withMessageContaining("geometry");
        }
    }

    @Nested
    @DisplayName("Tube and Cylinder with the axis first (several cohorts' order)")
    class AxisFirstTest {
        private final Ray axis = new Ray(Point.ZERO, new Vector(0, 0, 1));
        private final Ray across = new Ray(new Point(-3, 0, 1), new Vector(1, 0, 0));

        @Test
        @DisplayName("Tube(axis, radius) and Cylinder(axis, radius, height) are the course's shapes")
        void axisFirst() {
            Tube tube = new Tube(axis, 2);
            assertThat(tube.getRadius()).isEqualTo(2);
            assertThat(tube.getAxis()).isSameAs(axis);
            assertThat(tube.calculateIntersections(across)).containsExactly(new Intersection(tube, new Point(-2, 0, 1)),
                    new Intersection(tube, new Point(2, 0, 1)));
            Cylinder cylinder = new Cylinder(axis, 2, 0.5);
            assertThat(cylinder.getRadius()).isEqualTo(2);
            assertThat(cylinder.getHeight()).isEqualTo(0.5);
            assertThat(cylinder.calculateIntersections(across)).as("above the top cap").isNull();
            assertThat(cylinder.calculateIntersections(new Ray(new Point(-3, 0, 0.25), new Vector(1, 0, 0))))
                    .containsExactly(new Intersection(cylinder, new Point(-2, 0, 0.25)), new Intersection(cylinder, new Point(2, 0, 0.25)));
        }

        @Test
        @DisplayName("bad values are rejected like the course order's, naming them")
        void badValues() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Tube(axis, -2)).withMessageContaining("radius")
                    .withMessageContaining("-2.0");
            assertThatNullPointerException().isThrownBy(() -> new Tube(null, 2)).withMessageContaining("axis");
            assertThatIllegalArgumentException().isThrownBy(() -> new Cylinder(axis, 1, Double.NaN))
                    .withMessageContaining("height").withMessageContaining("NaN");
        }

        @Test
        @DisplayName("calculateIntersectionsHelper returns null, not an empty list, when nothing is in range")
        void helperNull() {
            Tube tube = new Tube(axis, 2);
            assertThat(tube.calculateIntersectionsHelper(across, 0.5)).isNull();
            assertThat(tube.calculateIntersectionsHelper(new Ray(new Point(-3, 0, 1), new Vector(0, 1, 0)), 100)).isNull();
            assertThat(new Cylinder(axis, 2, 0.5).calculateIntersectionsHelper(across, 100)).isNull();
            assertThat(tube.calculateIntersectionsHelper(across, 1)).containsExactly(new Intersection(tube, new Point(-2, 0, 1)));
        }

        @Test
        @DisplayName("getNormal of a point on the axis: an IllegalArgumentException naming the point")
        void normalOnTheAxis() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Tube(axis, 2).getNormal(new Point(0, 0, 7)))
                    .withMessageContaining("(0.0,0.0,7.0)").withMessageContaining("axis");
            assertThatIllegalArgumentException().isThrownBy(() -> new Cylinder(axis, 2, 10).getNormal(new Point(0, 0, 5)))
                    .withMessageContaining("(0.0,0.0,5.0)").withMessageContaining("axis");
            assertVector(new Tube(axis, 2).getNormal(new Point(0, 2, 7)), 0, 1, 0);
        }
    }

    /** A shape as a 5785 student writes it: only the 5785 hook, no bounding box. */
    static final class Ball extends Geometry {
        private final Sphere surface = new Sphere(UserGeometryScenes.RADIUS, UserGeometryScenes.CENTER);

        @Override
        public Vector getNormal(Point point) {
            return surface.getNormal(point);
        }

        @Override
        protected List<Intersection> calculateIntersectionsHelper(Ray ray, double maxDistance) {
            List<Intersection> found = surface.calculateIntersections(ray, maxDistance);
            if (found == null) return null;
            List<Intersection> mine = new ArrayList<>();
            for (Intersection i : found) mine.add(new Intersection(this, i.point));
            return mine;
        }
    }

    @Nested
    @DisplayName("a user's own geometry (5785 hook)")
    class UserGeometryTest implements UserShapeContract {
        @Override
        public Geometry newShape() {
            return new Ball();
        }

        @Test
        @DisplayName("a shape overriding no hook fails at construction with a clear message, not a stack overflow")
        void noHook() {
            class Nothing extends Geometry {
                @Override
                public Vector getNormal(Point point) {
                    return Y;
                }
            }
            assertThatIllegalStateException().isThrownBy(Nothing::new).withMessageContaining("Nothing")
                    .withMessageContaining("calculateIntersectionsHelper");
            assertThatCode(Ball::new).doesNotThrowAnyException();
        }
    }
}
