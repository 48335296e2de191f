package scene.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import app.Project;
import geometries.Geometry;
import geometries.Intersectable;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import lighting.PointLight;
import primitives.Material;
import lighting.AmbientLight;
import primitives.Color;
import primitives.Double3;
import primitives.Point;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;
import scene.samples.Showcase;

/**
 * The scene files in scenes/ describe the scenes they claim to: each renders to exactly the
 * pixels of the same scene built in Java through the public API, at a small resolution.
 */
class SceneFilesTest {
    private static final Path SCENES = Project.file("scenes");

    @TempDir
    Path dir;

    /** Renders {@code camera} into a new nX × nY image and returns it. */
    private static ImageWriter render(Camera.Builder camera, String name, int nX, int nY) {
        ImageWriter image = new ImageWriter(name, nX, nY);
        camera.setImageWriter(image).setMultithreading(2).setSummary(false).build().renderImage();
        return image;
    }

    private static int[] pixels(ImageWriter image) {
        int[] p = new int[image.getNx() * image.getNy()];
        for (int y = 0; y < image.getNy(); ++y)
            for (int x = 0; x < image.getNx(); ++x) p[y * image.getNx() + x] = image.getRgb(x, y);
        return p;
    }

    private static Set<Integer> distinct(int[] pixels) {
        Set<Integer> set = new HashSet<>();
        for (int p : pixels) set.add(p);
        return set;
    }

    /** The course's basicRenderTwoColorTest scene, as the course builds it in Java. */
    private static Scene courseTwoColorScene() {
        Scene scene = new Scene("Test scene")
                .setAmbientLight(new AmbientLight(new Color(255, 191, 191), Double3.ONE))
                .setBackground(new Color(75, 127, 90));
        scene.geometries.add(new Sphere(new Point(0, 0, -100), 50d),
                new Triangle(new Point(-100, 0, -100), new Point(0, 100, -100), new Point(-100, 100, -100)), // up left
                new Triangle(new Point(100, 0, -100), new Point(0, 100, -100), new Point(100, 100, -100)), // up right
                new Triangle(new Point(-100, 0, -100), new Point(0, -100, -100), new Point(-100, -100, -100)), // down left
                new Triangle(new Point(100, 0, -100), new Point(0, -100, -100), new Point(100, -100, -100))); // down right
        return scene;
    }

    private static Camera.Builder courseCamera(Scene scene) {
        return Camera.getBuilder().setRayTracer(new RayTracerBasic(scene)).setLocation(Point.ZERO)
                .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0)).setVpDistance(100).setVpSize(500, 500);
    }

    @Test
    @DisplayName("two-colors.xml renders byte-identical to the course's Java scene, grid included")
    void twoColors() throws Exception {
        LoadedScene loaded = XmlSceneReader.read(SCENES.resolve("two-colors.xml"));
        RenderSettings settings = loaded.settings();
        assertThat(new int[] { settings.width(), settings.height(), settings.gridInterval() }).containsExactly(500, 500, 50);
        assertThat(settings.gridColor().toRgb()).isEqualTo(java.awt.Color.YELLOW.getRGB() & 0xFFFFFF);

        // 100×100 with a grid line every 10 pixels: the file's 10×10 cells at a fifth of the size.
        Camera.Builder fromFile = loaded.requireCamera();
        ImageWriter file = new ImageWriter("file", 100, 100);
        Camera fileCamera = fromFile.setImageWriter(file).setSummary(false).build();
        fileCamera.renderImage().printGrid(settings.gridInterval() / 5, settings.gridColor());

        ImageWriter javaImage = new ImageWriter("java", 100, 100);
        courseCamera(courseTwoColorScene()).setImageWriter(javaImage).setSummary(false).build().renderImage()
                .printGrid(10, new Color(java.awt.Color.YELLOW));

        int[] expected = pixels(javaImage);
        assertThat(distinct(expected)).as("background, ambient-lit shapes and the grid").hasSize(3);
        assertThat(pixels(file)).isEqualTo(expected);
    }

    @Test
    @DisplayName("the course's scene file as the course wrote it (no camera) renders like its Java scene")
    void courseSnippet() throws Exception {
        Path file = dir.resolve("basicRenderTestTwoColors.xml");
        Files.writeString(file, CourseXml.TWO_COLORS);
        LoadedScene loaded = XmlSceneReader.read(file);
        assertThat(loaded.camera()).isEmpty();
        int[] fromFile = pixels(render(courseCamera(loaded.scene()), "file", 60, 40));
        int[] fromJava = pixels(render(courseCamera(courseTwoColorScene()), "java", 60, 40));
        assertThat(fromFile).isEqualTo(fromJava);
    }

    @Test
    @DisplayName("showcase.xml is scene.samples.Showcase: same geometries, same pixels with its sampling")
    void showcase() throws Exception {
        LoadedScene loaded = XmlSceneReader.read(SCENES.resolve("showcase.xml"));
        assertThat(loaded.scene().geometries.getItems()).hasSize(Showcase.create().geometries.getItems().size()).hasSize(133);
        assertThat(loaded.scene().lights).hasSize(3);
        RenderSettings s = loaded.settings();
        assertThat(s).isEqualTo(RenderSettings.defaults("showcase").withImage("showcase", 600, 600)
                .withAntiAliasing(AntiAliasing.ADAPTIVE).withAdaptiveDepth(3).withAdaptiveThreshold(8));

        Scene javaScene = Showcase.create();
        Camera.Builder javaCamera = Camera.getBuilder().setLocation(Showcase.CAMERA_LOCATION)
                .setDirection(Showcase.CAMERA_TARGET, Vector.AXIS_Y).setVpSize(Showcase.VP_SIZE, Showcase.VP_SIZE)
                .setVpDistance(Showcase.VP_DISTANCE);
        s.applyTo(javaCamera, javaScene);
        int[] expected = pixels(render(javaCamera, "java", 32, 32));
        assertThat(distinct(expected).size()).as("a real picture").isGreaterThan(100);
        assertThat(pixels(render(loaded.requireCamera(), "file", 32, 32))).isEqualTo(expected);
    }

    @Test
    @DisplayName("teapot.xml: the course's teapot mesh, material, light and camera")
    void teapot() throws Exception {
        LoadedScene loaded = XmlSceneReader.read(SCENES.resolve("teapot.xml"));
        assertThat(loaded.scene().geometries.getItems()).hasSize(1);
        TriangleMesh fromFile = (TriangleMesh) loaded.scene().geometries.getItems().get(0);
        assertThat(fromFile.triangleCount()).isEqualTo(992);

        // The same scene in Java, from the OBJ file's header.
        Scene scene = new Scene("teapot");
        scene.geometries.add(ObjReader.read(SCENES.resolve("teapot.obj")).setEmission(new Color(200, 0, 0))
                .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60)));
        scene.lights.add(new PointLight(new Color(500, 500, 500), new Point(100, 0, -100)).setKq(1e-6));
        Camera.Builder camera = Camera.getBuilder().setLocation(new Point(0, 0, -1000)).setDirection(Point.ZERO, Vector.AXIS_Y)
                .setVpSize(200, 200).setVpDistance(1000).setRayTracer(new RayTracerBasic(scene));
        int[] expected = pixels(render(camera, "java", 24, 24));
        assertThat(distinct(expected).size()).as("a lit teapot").isGreaterThan(10);
        assertThat(pixels(render(loaded.requireCamera(), "file", 24, 24))).isEqualTo(expected);
    }

    @Test
    @DisplayName("glossy.xml: eight spheres and an 8×8 wall with blurred reflection, four lights, beams of 10")
    void glossy() throws Exception {
        LoadedScene loaded = XmlSceneReader.read(SCENES.resolve("glossy.xml"));
        List<Intersectable> items = loaded.scene().geometries.getItems();
        assertThat(items.stream().filter(g -> g instanceof Sphere).count()).isEqualTo(8);
        List<Intersectable> wall = items.stream().filter(g -> g instanceof Polygon).toList();
        assertThat(wall).hasSize(64);
        assertThat(wall).allSatisfy(g -> assertThat(((Geometry) g).getMaterial().reflectionSpread).isEqualTo(0.1));
        assertThat(loaded.scene().lights).hasSize(4);
        assertThat(loaded.settings()).isEqualTo(RenderSettings.defaults("glossy").withImage("glossy", 1000, 1000)
                .withBeamSize(10));
        // The wall spans ±250: a ray from the camera through (±240, ±240, -250) hits a tile.
        Camera camera = loaded.requireCamera().setSummary(false).build();
        assertThat(camera.getLocation()).isEqualTo(new Point(0, 0, 1000));
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2) {
                Vector toCorner = new Point(240 * sx, 240 * sy, -250).subtract(camera.getLocation());
                assertThat(wall.stream().anyMatch(g -> g.findIntersections(new primitives.Ray(camera.getLocation(), toCorner)) != null))
                        .isTrue();
            }
    }
}
