package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.assertj.core.api.Assertions.within;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.Cylinder;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
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
import renderer.RayTracerBasic;
import renderer.RenderStats;
import renderer.Sampling;
import renderer.View;

/** Every element and attribute of the scene format, read into the library's objects. */
class XmlSceneReaderTest {
    @TempDir
    Path dir;

    private LoadedScene read(String xml) throws IOException, SceneFormatException {
        Path file = dir.resolve("scene.xml");
        Files.writeString(file, xml);
        return XmlSceneReader.read(file);
    }

    private LoadedScene readScene(String body) throws IOException, SceneFormatException {
        return read("<scene>\n" + body + "\n</scene>\n");
    }

    /** The single geometry of a {@code <geometries>} holding {@code element}. */
    private <T> T geometry(String element, Class<T> type) throws Exception {
        List<Intersectable> items = readScene("<geometries>" + element + "</geometries>").scene().geometries.getItems();
        assertThat(items).hasSize(1);
        assertThat(items.get(0)).isExactlyInstanceOf(type);
        return type.cast(items.get(0));
    }

    private LightSource light(String element) throws Exception {
        List<LightSource> lights = readScene("<lights>" + element + "</lights>").scene().lights;
        assertThat(lights).hasSize(1);
        return lights.get(0);
    }

    private static void assertColor(Color actual, double r, double g, double b) {
        assertThat(new double[] { actual.getR(), actual.getG(), actual.getB() })
                .containsExactly(new double[] { r, g, b }, within(1e-9));
    }

    private static void assertPoint(Point actual, double x, double y, double z) {
        assertThat(new double[] { actual.getX(), actual.getY(), actual.getZ() })
                .containsExactly(new double[] { x, y, z }, within(1e-12));
    }

    /** The camera of a view builder, completed with a 2×2 image and a tracer of the loaded scene. */
    private static Camera withSmallImage(Camera.Builder view, LoadedScene loaded) {
        return view.setImageWriter(new ImageWriter("small", 2, 2)).setRayTracer(new RayTracerBasic(loaded.scene()))
                .build();
    }

    private static boolean hits(Intersectable geometry, Point from, Vector direction) {
        return geometry.findIntersections(new Ray(from, direction)) != null;
    }

    @Nested
    @DisplayName("<scene>")
    class SceneElement {
        @Test
        @DisplayName("the course's scene file reads unchanged")
        void courseFile() throws Exception {
            LoadedScene loaded = read(CourseXml.TWO_COLORS);
            assertColor(loaded.scene().background, 75, 127, 90);
            // The course's Java scene: new AmbientLight(new Color(255, 191, 191), Double3.ONE).
            assertColor(loaded.scene().ambientLight.getIntensity(), 255, 191, 191);
            List<Intersectable> items = loaded.scene().geometries.getItems();
            assertThat(items).hasSize(5);
            assertThat(items.get(0)).isInstanceOf(Sphere.class);
            assertThat(items.subList(1, 5)).allMatch(g -> g instanceof Triangle);
            assertThat(loaded.camera()).isEmpty();
        }

        @Test
        @DisplayName("name defaults to the file name; background to black; no lights, no ambient light")
        void defaults() throws Exception {
            LoadedScene loaded = read("<scene/>");
            assertThat(loaded.scene().name).isEqualTo("scene");
            assertColor(loaded.scene().background, 0, 0, 0);
            assertColor(loaded.scene().ambientLight.getIntensity(), 0, 0, 0);
            assertThat(loaded.scene().lights).isEmpty();
            assertThat(loaded.scene().geometries.isEmpty()).isTrue();
            assertThat(loaded.settings()).isEqualTo(RenderSettings.defaults("scene"));
        }

        @Test
        @DisplayName("name and the schema attributes an editor adds")
        void nameAndSchema() throws Exception {
            LoadedScene loaded = read("""
                    <scene name="my scene" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
                           xsi:noNamespaceSchemaLocation="../docs/scene.xsd"/>""");
            assertThat(loaded.scene().name).isEqualTo("my scene");
            assertThat(loaded.settings().imageName()).isEqualTo("my scene");
        }

        @Test
        @DisplayName("a UTF-8 byte-order mark and an XML declaration are accepted")
        void bomAndDeclaration() throws Exception {
            LoadedScene loaded = read("\uFEFF<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene name=\"é\"/>");
            assertThat(loaded.scene().name).isEqualTo("é");
        }

        @Test
        @DisplayName("<ambient-light ka> as a number and as a triple")
        void ambientLight() throws Exception {
            assertColor(readScene("<ambient-light color=\"100 200 50\" ka=\"0.5\"/>").scene().ambientLight.getIntensity(),
                    50, 100, 25);
            assertColor(readScene("<ambient-light color=\"100 200 50\" ka=\"1 0.5 0\"/>").scene().ambientLight.getIntensity(),
                    100, 100, 0);
        }
    }

    @Nested
    @DisplayName("geometries")
    class Geometries {
        @Test
        void sphere() throws Exception {
            Sphere s = geometry("<sphere center=\"1 2 -3.5\" radius=\"2.25\"/>", Sphere.class);
            assertPoint(s.getCenter(), 1, 2, -3.5);
            assertThat(s.getRadius()).isEqualTo(2.25);
        }

        @Test
        @DisplayName("plane through three points")
        void planeThreePoints() throws Exception {
            Plane p = geometry("<plane p0=\"0 0 5\" p1=\"1 0 5\" p2=\"0 1 5\"/>", Plane.class);
            assertPoint(p.getQ(), 0, 0, 5);
            assertPoint(p.getNormal(), 0, 0, 1);
        }

        @Test
        @DisplayName("plane by a point and a normal (normalized)")
        void planePointNormal() throws Exception {
            Plane p = geometry("<plane point=\"0 -2 0\" normal=\"0 3 0\"/>", Plane.class);
            assertPoint(p.getQ(), 0, -2, 0);
            assertPoint(p.getNormal(), 0, 1, 0);
        }

        @Test
        @DisplayName("triangle: rays through its inside hit, rays beside it miss")
        void triangle() throws Exception {
            Triangle t = geometry("<triangle p0=\"0 0 -10\" p1=\"4 0 -10\" p2=\"0 4 -10\"/>", Triangle.class);
            Vector down = new Vector(0, 0, -1);
            assertThat(hits(t, new Point(1, 1, 0), down)).isTrue();
            assertThat(hits(t, new Point(3, 3, 0), down)).isFalse();
            assertThat(t.findIntersections(new Ray(new Point(1, 1, 0), down))).containsExactly(new Point(1, 1, -10));
        }

        @Test
        @DisplayName("polygon with any number of vertices p0, p1, …")
        void polygon() throws Exception {
            Polygon p = geometry("<polygon p0=\"0 0 -10\" p1=\"4 0 -10\" p2=\"5 3 -10\" p3=\"2 5 -10\" p4=\"-1 3 -10\"/>",
                    Polygon.class);
            Vector down = new Vector(0, 0, -1);
            assertThat(hits(p, new Point(2, 4, 0), down)).as("inside, near the fifth edges").isTrue();
            assertThat(hits(p, new Point(-0.5, 0.5, 0), down)).as("outside the edge p4-p0").isFalse();
            assertThat(hits(p, new Point(4.9, 0.5, 0), down)).as("outside the edge p1-p2").isFalse();
        }

        @Test
        void tube() throws Exception {
            Tube t = geometry("<tube radius=\"1.5\" origin=\"1 2 3\" axis=\"0 0 2\"/>", Tube.class);
            assertThat(t.getRadius()).isEqualTo(1.5);
            assertPoint(t.getAxis().getHead(), 1, 2, 3);
            assertPoint(t.getAxis().getDirection(), 0, 0, 1);
        }

        @Test
        void cylinder() throws Exception {
            Cylinder c = geometry("<cylinder radius=\"2\" origin=\"0 0 0\" axis=\"0 1 0\" height=\"7\"/>", Cylinder.class);
            assertThat(c.getRadius()).isEqualTo(2);
            assertThat(c.getHeight()).isEqualTo(7);
            assertPoint(c.getAxis().getHead(), 0, 0, 0);
            assertPoint(c.getAxis().getDirection(), 0, 1, 0);
        }

        @Test
        @DisplayName("mesh from an OBJ file, found relative to the scene file, with emission and material")
        void mesh() throws Exception {
            Files.createDirectories(dir.resolve("models"));
            Files.writeString(dir.resolve("models/quad.obj"), "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nf 1 2 3 4\n");
            TriangleMesh mesh = geometry("""
                    <mesh file="models/quad.obj" emission="1 2 3"><material kd="0.25"/></mesh>""", TriangleMesh.class);
            assertThat(mesh.triangleCount()).isEqualTo(2);
            assertPoint(mesh.getVertex(2), 2, 2, 0);
            assertColor(mesh.getEmission(), 1, 2, 3);
            assertThat(mesh.getMaterial().kD).isEqualTo(new Double3(0.25));
            assertThat(hits(mesh, new Point(1.5, 0.5, 5), new Vector(0, 0, -1))).isTrue();
            assertThat(hits(mesh, new Point(2.5, 0.5, 5), new Vector(0, 0, -1))).isFalse();
        }

        @Test
        @DisplayName("emission on any geometry; black and the default material when absent")
        void emission() throws Exception {
            Geometry g = geometry("<sphere center=\"0 0 0\" radius=\"1\" emission=\"10 20.5 30\"/>", Sphere.class);
            assertColor(g.getEmission(), 10, 20.5, 30);
            Geometry plain = geometry("<sphere center=\"0 0 0\" radius=\"1\"/>", Sphere.class);
            assertColor(plain.getEmission(), 0, 0, 0);
            assertThat(plain.getMaterial().kD).isEqualTo(Double3.ZERO);
            assertThat(plain.getMaterial().nShininess).isZero();
        }

        @Test
        @DisplayName("geometries keep the file's order")
        void order() throws Exception {
            List<Intersectable> items = readScene("""
                    <geometries>
                        <triangle p0="0 0 0" p1="1 0 0" p2="0 1 0"/>
                        <sphere center="0 0 0" radius="1"/>
                        <plane point="0 0 0" normal="0 0 1"/>
                    </geometries>""").scene().geometries.getItems();
            assertThat(items).extracting(Object::getClass).containsExactly(Triangle.class, Sphere.class, Plane.class);
        }
    }

    @Nested
    @DisplayName("<material>")
    class Materials {
        private Material material(String attributes) throws Exception {
            return geometry("<sphere center=\"0 0 0\" radius=\"1\"><material " + attributes + "/></sphere>", Sphere.class)
                    .getMaterial();
        }

        @Test
        @DisplayName("every coefficient as one number")
        void numbers() throws Exception {
            Material m = material("kd=\"0.5\" ks=\"0.25\" kt=\"0.75\" kr=\"0.125\" shininess=\"60\"");
            assertThat(m.kD).isEqualTo(new Double3(0.5));
            assertThat(m.kS).isEqualTo(new Double3(0.25));
            assertThat(m.kT).isEqualTo(new Double3(0.75));
            assertThat(m.kR).isEqualTo(new Double3(0.125));
            assertThat(m.nShininess).isEqualTo(60);
        }

        @Test
        @DisplayName("every coefficient as a triple")
        void triples() throws Exception {
            Material m = material("kd=\"0.1 0.2 0.3\" ks=\"0.4 0.5 0.6\" kt=\"0.5 0.7 0.6\" kr=\"0 0.5 1\"");
            assertThat(m.kD).isEqualTo(new Double3(0.1, 0.2, 0.3));
            assertThat(m.kS).isEqualTo(new Double3(0.4, 0.5, 0.6));
            assertThat(m.kT).isEqualTo(new Double3(0.5, 0.7, 0.6));
            assertThat(m.kR).isEqualTo(new Double3(0, 0.5, 1));
        }

        @Test
        @DisplayName("reflection and transmission spreads, index of refraction")
        void spreads() throws Exception {
            Material m = material("reflection-spread=\"0.1\" transmission-spread=\"0.05\" ior=\"1.5\"");
            assertThat(m.reflectionSpread).isEqualTo(0.1);
            assertThat(m.transmissionSpread).isEqualTo(0.05);
            assertThat(m.ior).isEqualTo(1.5);
            assertThat(material("kd=\"0.5\"").ior).as("default").isEqualTo(1);
        }
    }

    @Nested
    @DisplayName("lights")
    class Lights {
        @Test
        @DisplayName("directional light: intensity everywhere, normalized direction")
        void directional() throws Exception {
            LightSource l = light("<directional-light color=\"90 85 80\" direction=\"0 -2 0\"/>");
            assertThat(l).isExactlyInstanceOf(DirectionalLight.class);
            assertColor(l.getIntensity(new Point(5, 5, 5)), 90, 85, 80);
            assertPoint(l.getL(new Point(5, 5, 5)), 0, -1, 0);
        }

        @Test
        @DisplayName("point light: attenuation 1 / (kc + kl·d + kq·d²) and radius")
        void point() throws Exception {
            LightSource l = light("<point-light color=\"400 200 100\" position=\"0 0 0\" kc=\"2\" kl=\"0.5\" kq=\"0.25\" radius=\"3\"/>");
            assertThat(l).isExactlyInstanceOf(PointLight.class);
            assertPoint(l.getPosition(), 0, 0, 0);
            assertThat(l.getRadius()).isEqualTo(3);
            // d = 2: 2 + 0.5·2 + 0.25·4 = 4
            assertColor(l.getIntensity(new Point(0, 2, 0)), 100, 50, 25);
        }

        @Test
        @DisplayName("point light defaults: kc 1, kl 0, kq 0, radius 0")
        void pointDefaults() throws Exception {
            LightSource l = light("<point-light color=\"400 200 100\" position=\"1 1 1\"/>");
            assertColor(l.getIntensity(new Point(100, 50, -20)), 400, 200, 100);
            assertThat(l.getRadius()).isZero();
        }

        @Test
        @DisplayName("spot light: cos^narrow-beam times the attenuation, and radius")
        void spot() throws Exception {
            LightSource l = light("""
                    <spot-light color="400 400 400" position="0 0 0" direction="0 0 -1"
                                kc="1" kl="0.5" kq="0" radius="2" narrow-beam="2"/>""");
            assertThat(l).isExactlyInstanceOf(SpotLight.class);
            assertThat(l.getRadius()).isEqualTo(2);
            // A point at 60° off the axis, at distance 2: cos = 0.5, squared 0.25; attenuation 1/(1 + 1).
            Point p = new Point(Math.sqrt(3), 0, -1);
            assertColor(l.getIntensity(p), 50, 50, 50);
            assertColor(l.getIntensity(new Point(0, 0, 2)), 0, 0, 0);
        }

        @Test
        @DisplayName("lights keep the file's order")
        void order() throws Exception {
            List<LightSource> lights = readScene("""
                    <lights>
                        <spot-light color="1 1 1" position="0 0 0" direction="0 0 -1"/>
                        <directional-light color="1 1 1" direction="0 0 -1"/>
                        <point-light color="1 1 1" position="0 0 0"/>
                    </lights>""").scene().lights;
            assertThat(lights).extracting(Object::getClass)
                    .containsExactly(SpotLight.class, DirectionalLight.class, PointLight.class);
        }
    }

    @Nested
    @DisplayName("<camera>")
    class CameraElement {
        private Camera camera(String attributes) throws Exception {
            return readScene("<camera " + attributes + "/>").requireCamera().build();
        }

        @Test
        @DisplayName("location, direction and up")
        void directionAndUp() throws Exception {
            Camera c = camera("location=\"1 2 3\" direction=\"0 0 -2\" up=\"0 3 0\" vp-size=\"200 100\" vp-distance=\"50\"");
            assertPoint(c.getLocation(), 1, 2, 3);
            assertPoint(c.getVTo(), 0, 0, -1);
            assertPoint(c.getVUp(), 0, 1, 0);
        }

        @Test
        @DisplayName("target without up: +y is up")
        void target() throws Exception {
            Camera c = camera("location=\"0 0 10\" target=\"0 0 0\" vp-size=\"1\" vp-distance=\"1\"");
            assertPoint(c.getVTo(), 0, 0, -1);
            assertPoint(c.getVUp(), 0, 1, 0);
        }

        @Test
        @DisplayName("target with an up that is not orthogonal to the view")
        void targetAndUp() throws Exception {
            Camera c = camera("location=\"0 0 0\" target=\"10 0 0\" up=\"1 0 1\" vp-size=\"1\" vp-distance=\"1\"");
            assertPoint(c.getVTo(), 1, 0, 0);
            assertPoint(c.getVUp(), 0, 0, 1);
        }

        @Test
        @DisplayName("view-plane size (width height) and distance: the corner pixel's ray")
        void viewPlane() throws Exception {
            Camera c = camera("location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"200 100\" vp-distance=\"50\"");
            // Pixel (0, 0) of 2×2: centre at (-w/4, +h/4) on the plane at distance 50.
            Vector d = c.constructRay(2, 2, 0, 0).getDirection();
            Vector expected = new Vector(-50, 25, -50).normalize();
            assertPoint(d, expected.getX(), expected.getY(), expected.getZ());
        }

        @Test
        @DisplayName("requireView: the view alone, without image or tracer")
        void viewOnly() throws Exception {
            LoadedScene loaded = readScene(
                    "<camera location=\"1 2 3\" target=\"1 2 0\" vp-size=\"4 2\" vp-distance=\"5\"/>");
            Camera.Builder view = loaded.requireView();
            assertThat(view.build().constructRay(0, 0).getDirection()).as("a 1x1 image by default").isEqualTo(new Vector(0, 0, -1));
            Camera camera = withSmallImage(view, loaded);
            assertPoint(camera.getLocation(), 1, 2, 3);
            assertPoint(camera.getVTo(), 0, 0, -1);
        }

        @Test
        @DisplayName("each requireCamera and requireView is a new builder: changing one leaves the next alone")
        void newBuilders() throws Exception {
            LoadedScene loaded = readScene(
                    "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"1\" vp-distance=\"1\"/>");
            Camera.Builder first = loaded.requireCamera();
            assertThat(loaded.requireCamera()).isNotSameAs(first);
            first.setLocation(new Point(9, 9, 9));
            assertPoint(loaded.requireCamera().build().getLocation(), 0, 0, 0);
            assertPoint(withSmallImage(loaded.requireView(), loaded).getLocation(), 0, 0, 0);
        }

        @Test
        @DisplayName("one vp-size number makes a square view plane")
        void squareViewPlane() throws Exception {
            Camera c = camera("location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"100\" vp-distance=\"50\"");
            Vector expected = new Vector(-25, 25, -50).normalize();
            Vector d = c.constructRay(2, 2, 0, 0).getDirection();
            assertPoint(d, expected.getX(), expected.getY(), expected.getZ());
        }
    }

    @Nested
    @DisplayName("<image> and <render>")
    class Settings {
        @Test
        @DisplayName("every setting is read, stated as the file states it")
        void everything() throws Exception {
            RenderSettings s = readScene("""
                    <image name="picture" width="64" height="32" grid-interval="8" grid-color="0 255 0"/>
                    <render threads="3" seed="-42" bvh="false" beam-size="7" shadow-samples="9">
                        <anti-aliasing mode="random" grid="3 5" depth="4" threshold="2.5"/>
                        <depth-of-field focal-distance="900" aperture="5" samples="12"/>
                    </render>""").settings();
            assertThat(s).isEqualTo(RenderSettings.defaults("picture").withImage("picture", 64, 32)
                    .withGrid(8, new Color(0, 255, 0)).withThreads(3).withSeed(-42).withBvh(false).withBeamSize(7)
                    .withShadowSamples(9).withAntiAliasing(AntiAliasing.RANDOM).withAntiAliasingGrid(3, 5)
                    .withAdaptiveDepth(4).withAdaptiveThreshold(2.5).withDepthOfField(900, 5).withDepthOfFieldSamples(12));
            assertThat(new int[] { s.width(), s.height(), s.gridInterval() }).containsExactly(64, 32, 8);
            assertColor(s.gridColor(), 0, 255, 0);
        }

        @Test
        @DisplayName("only what the file states: <render> with one attribute states that one")
        void onlyStated() throws Exception {
            assertThat(readScene("<render seed=\"5\"/>").settings()).isEqualTo(RenderSettings.defaults("scene").withSeed(5));
            assertThat(readScene("<render><anti-aliasing mode=\"adaptive\" depth=\"5\"/></render>").settings())
                    .isEqualTo(RenderSettings.defaults("scene").withAntiAliasing(AntiAliasing.ADAPTIVE).withAdaptiveDepth(5));
            assertThat(readScene("<image height=\"20\"/>").settings()).as("a size is stated whole")
                    .isEqualTo(RenderSettings.defaults("scene").withImageSize(RenderSettings.DEFAULT_SIZE, 20));
        }

        @ParameterizedTest(name = "mode=\"{0}\"")
        @CsvSource({ "none, NONE", "random, RANDOM", "CORNERS, CORNERS", "Adaptive, ADAPTIVE" })
        @DisplayName("anti-aliasing modes, case-insensitive")
        void modes(String mode, AntiAliasing expected) throws Exception {
            assertThat(readScene("<render><anti-aliasing mode=\"" + mode + "\"/></render>").settings())
                    .isEqualTo(RenderSettings.defaults("scene").withAntiAliasing(expected));
        }

        @Test
        @DisplayName("one grid number means a square grid")
        void squareGrid() throws Exception {
            RenderSettings s = readScene("<render><anti-aliasing mode=\"random\" grid=\"17\"/></render>").settings();
            assertThat(s).isEqualTo(RenderSettings.defaults("scene").withAntiAliasing(AntiAliasing.RANDOM)
                    .withAntiAliasingGrid(17, 17));
        }

        @Test
        @DisplayName("the camera builder carries the settings: sampling, tracer, seed and depth of field")
        void appliedToCamera() throws Exception {
            Camera.Builder builder = readScene("""
                    <camera location="0 0 0" direction="0 0 -1" up="0 1 0" vp-size="10" vp-distance="10"/>
                    <image width="4" height="3"/>
                    <render threads="2" seed="42" bvh="false" beam-size="7" shadow-samples="9">
                        <anti-aliasing mode="random" grid="3 5"/>
                        <depth-of-field focal-distance="900" aperture="5"/>
                    </render>""").requireCamera();
            Camera camera = builder.setSummary(false).build();
            assertThat(CameraValues.of(camera)).isEqualTo(new CameraValues(Sampling.DEFAULT.withAntiAliasing(AntiAliasing.RANDOM)
                    .withGrid(3, 5).withSeed(42), View.Lens.thin(900, 5), new CameraValues.Tracer(false, 7, 9)));
            RenderStats stats = camera.render();
            assertThat(stats.pixels()).isEqualTo(12);
            assertThat(stats.threads()).isEqualTo(2);
            assertThat(stats.samplesPerPixel()).isEqualTo(15);
        }

        @Test
        @DisplayName("adaptive parameters reach the camera")
        void adaptive() throws Exception {
            Camera camera = readScene("""
                    <camera location="0 0 0" direction="0 0 -1" up="0 1 0" vp-size="10" vp-distance="10"/>
                    <render><anti-aliasing mode="adaptive" depth="5" threshold="2.5"/></render>""")
                    .requireCamera().build();
            assertThat(CameraValues.of(camera)).isEqualTo(new CameraValues(Sampling.DEFAULT.withAntiAliasing(AntiAliasing.ADAPTIVE)
                    .withAdaptive(5, 2.5), View.Lens.PINHOLE, CameraValues.Tracer.DEFAULT));
        }

        /**
         * 46340 × 46340 pixels is just below the limit of one int array, and 8.6 GB: more than the
         * test JVM may use (else the test is skipped), so reading fails with an
         * OutOfMemoryError if it allocates the image.
         */
        @Test
        @DisplayName("an image larger than the memory: reading the file allocates nothing of its size")
        void hugeImage() throws Exception {
            int side = 46340;
            assumeTrue((long) side * side * Integer.BYTES > Runtime.getRuntime().maxMemory(),
                    "the JVM could allocate the image");
            LoadedScene loaded = readScene("""
                    <camera location="0 0 0" direction="0 0 -1" up="0 1 0" vp-size="10" vp-distance="10"/>
                    <image width="46340" height="46340"/>""");
            assertThat(new int[] { loaded.settings().width(), loaded.settings().height() }).containsExactly(side, side);
            assertPoint(withSmallImage(loaded.requireView(), loaded).getVTo(), 0, 0, -1);
        }

        @Test
        @DisplayName("without <image>, the image is named after the scene, 500×500")
        void defaultImage() throws Exception {
            RenderSettings s = read("<scene name=\"x\"/>").settings();
            assertThat(s.imageName()).isEqualTo("x");
            assertThat(new int[] { s.width(), s.height(), s.gridInterval() }).containsExactly(500, 500, 0);
        }
    }

    /**
     * The ray budget is checked once, when {@code <render>} is read whole (or, without it, once
     * for the defaults over the lights); a budget over the limit is reported where reading the file
     * in order first exceeds it, with the library's figures for what the file stated up to there.
     */
    @Nested
    @DisplayName("the ray budget")
    class RayBudget {
        /** One light with a radius: each shaded point takes the shadow samples toward it. */
        private static final String SOFT_LIGHT = "<lights><point-light color=\"100 100 100\" position=\"0 5 0\" radius=\"1\"/></lights>";
        private static final String CAMERA = "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"10\""
                + " vp-distance=\"10\"/><image width=\"2\" height=\"2\"/>";

        /**
         * 31,776 soft lights: with the default 16 shadow samples and beams of 16 rays, 33 × (1 + 16
         * × 31,776) = 16,777,761 rays, just over the limit.
         */
        private static String softLights() {
            return "<lights>" + "<point-light color=\"1 1 1\" position=\"0 5 0\" radius=\"1\"/>".repeat(31_776) + "</lights>";
        }

        /** The library's words for a budget over the limit, as the reader reports them at {@code element}. */
        private static String overBudget(String element, String mode, int samples, int beam, int shadow, int soft, long rays) {
            return "invalid <" + element + ">: " + mode + " sampling with " + samples + " samples per pixel × (1 + 2 beams of "
                    + beam + " rays: reflection and transmission) × (1 + " + shadow + " shadow samples × " + soft + " soft "
                    + (soft == 1 ? "light" : "lights") + " + 0 other lights) is " + rays + " rays per pixel, more than the"
                    + " limit of 16777216 (expected samples per pixel × (1 + 2 × beam-size) × (1 + shadow-samples × lights"
                    + " with a radius + other lights) at most 16777216)";
        }

        static Stream<Arguments> overTheLimit() {
            return Stream.of(
                    // name, the file's line 2, the text the error points at, the reason
                    Arguments.of("the attributes alone: at beam-size",
                            "<render beam-size=\"2048\" shadow-samples=\"4096\"/>" + SOFT_LIGHT, "beam-size=",
                            overBudget("render", "NONE", 1, 2048, 4096, 1, 16_785_409L)),
                    Arguments.of("the attributes alone, a lens after them: at beam-size, with the figures before the lens",
                            "<render beam-size=\"2048\" shadow-samples=\"4096\"><depth-of-field focal-distance=\"10\""
                                    + " aperture=\"1\" samples=\"2\"/></render>" + SOFT_LIGHT, "beam-size=",
                            overBudget("render", "NONE", 1, 2048, 4096, 1, 16_785_409L)),
                    Arguments.of("the lights alone, no <render>: at <lights>", softLights(), "<lights>",
                            overBudget("lights", "NONE", 1, 16, 16, 31_776, 16_777_761L)),
                    Arguments.of("the lights under a <render> that states neither beams nor shadow samples: at <render>",
                            "<render threads=\"1\"/>" + softLights(), "<render",
                            overBudget("render", "NONE", 1, 16, 16, 31_776, 16_777_761L)),
                    // 5 × 200,001 × 17 = 17,000,085; the beams alone 3,400,017.
                    Arguments.of("CORNERS' 5 samples × the beams: at mode",
                            "<render beam-size=\"100000\"><anti-aliasing mode=\"corners\"/></render>" + SOFT_LIGHT, "mode=",
                            overBudget("anti-aliasing", "CORNERS", 5, 100_000, 16, 1, 17_000_085L)),
                    Arguments.of("ADAPTIVE's lattice of depth 6 × the beams: at depth",
                            "<render beam-size=\"256\"><anti-aliasing mode=\"adaptive\" depth=\"6\"/></render>" + SOFT_LIGHT,
                            "depth=", overBudget("anti-aliasing", "ADAPTIVE", 4225, 256, 16, 1, 36_846_225L)),
                    // 16 × 80,001 × 17 = 21,760,272; the beams alone 1,360,017.
                    Arguments.of("the default 16 lens samples × the beams: at <depth-of-field>, which does not state them",
                            "<render beam-size=\"40000\"><depth-of-field focal-distance=\"10\" aperture=\"1\"/></render>"
                                    + SOFT_LIGHT, "<depth-of-field",
                            overBudget("depth-of-field", "NONE", 16, 40_000, 16, 1, 21_760_272L)),
                    // Neither 60,000 lens samples (× 33 × 17) nor beams of 100 rays (× 17) alone are over.
                    Arguments.of("only the combination of lens samples and beams: at samples",
                            "<render beam-size=\"100\"><depth-of-field focal-distance=\"10\" aperture=\"1\" samples=\"60000\"/>"
                                    + "</render>" + SOFT_LIGHT, "samples=",
                            overBudget("depth-of-field", "NONE", 60_000, 100, 16, 1, 205_020_000L)));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("overTheLimit")
        @DisplayName("a budget over the limit is reported where the file first exceeds it, with the figures up to there")
        void reportedWhereFirstExceeded(String name, String line2, String at, String reason) throws IOException {
            SceneFormatException e = catchThrowableOfType(SceneFormatException.class, () -> readScene(line2));
            assertThat(e).as("reading must fail").isNotNull();
            assertThat(e.getReason()).isEqualTo(reason);
            assertThat(new int[] { e.getLine(), e.getColumn() }).as("line and column of " + at)
                    .containsExactly(2, line2.indexOf(at) + 1);
            assertThat(e.getCause()).isInstanceOf(IllegalArgumentException.class);
        }

        /**
         * With a lens, ADAPTIVE samples each pixel on its own, at most 4^6 = 4,096 samples at depth
         * 6, not its lattice's 65² = 4,225: 4,096 × 237 × 17 = 16,502,784 is within the budget,
         * 4,225 × 237 × 17 = 17,022,525 is not. The file is held to what its camera traces.
         */
        @Test
        @DisplayName("the settings as a whole: ADAPTIVE depth 6 over the budget without a lens, within it with one")
        void wholeSettings() throws Exception {
            String adaptive = "<render beam-size=\"118\"><anti-aliasing mode=\"adaptive\" depth=\"6\"/>";
            SceneFormatException e = catchThrowableOfType(SceneFormatException.class,
                    () -> readScene(adaptive + "</render>" + SOFT_LIGHT));
            assertThat(e).as("without a lens").isNotNull();
            assertThat(e.getReason()).isEqualTo(overBudget("anti-aliasing", "ADAPTIVE", 4225, 118, 16, 1, 17_022_525L));

            LoadedScene withLens = readScene(adaptive + "<depth-of-field focal-distance=\"10\" aperture=\"1\"/></render>"
                    + SOFT_LIGHT + CAMERA);
            assertThat(withLens.requireCamera().setSummary(false).build()).as("the camera agrees").isNotNull();
        }
    }
}
