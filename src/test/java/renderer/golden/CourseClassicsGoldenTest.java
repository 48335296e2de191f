package renderer.golden;

import static java.awt.Color.BLUE;
import static java.awt.Color.GREEN;
import static java.awt.Color.RED;
import static java.awt.Color.WHITE;
import static java.awt.Color.YELLOW;
import static org.assertj.core.api.Assertions.assertThat;
import static renderer.golden.FloorScene.FLOOR_BASE;
import static renderer.golden.FloorScene.FLOOR_KD;
import static renderer.golden.FloorScene.floor;
import static renderer.golden.Golden.assertPixel;
import static renderer.golden.Golden.blue;
import static renderer.golden.Golden.lumaAt;
import static renderer.golden.Golden.red;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * The course's classic pictures, small: flat colours with a grid, emission with ambient light,
 * each kind of light, shadows, transparency and mirrors. Every expected colour asserted here is
 * worked out by hand from the scene's numbers (pixels are truncated to whole 0..255 steps).
 */
@DisplayName("Golden renders: the course classics")
class CourseClassicsGoldenTest {
    /** The course's first scene: a sphere and three triangles around the view's centre. */
    private static final Golden.View FRONT = new Golden.View(Point.ZERO, new Point(0, 0, -100), 500, 100);
    private static final int FRONT_SIZE = 200;

    private static Scene sphereAndTriangles(String name) {
        Scene scene = new Scene(name);
        scene.geometries.add(new Sphere(new Point(0, 0, -100), 50d),
                new Triangle(new Point(-100, 0, -100), new Point(0, 100, -100), new Point(-100, 100, -100)), // up left
                new Triangle(new Point(-100, 0, -100), new Point(0, -100, -100), new Point(-100, -100, -100)), // down left
                new Triangle(new Point(100, 0, -100), new Point(0, -100, -100), new Point(100, -100, -100))); // down right
        return scene;
    }

    @Test
    @DisplayName("two colours: ambient-lit shapes on a background, yellow grid every 20 pixels")
    void twoColours() {
        Scene scene = sphereAndTriangles("two colours")
                .setAmbientLight(new AmbientLight(new Color(255, 191, 191), Double3.ONE))
                .setBackground(new Color(75, 127, 90));
        ImageWriter image = Golden.image("two-colors", FRONT_SIZE, FRONT_SIZE);
        FRONT.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene)).build()
                .renderImage().printGrid(20, new Color(YELLOW)).writeToImage();

        // Shapes without lights or emission show the ambient colour exactly; misses show the background.
        assertPixel(image, FRONT.pixelOf(new Point(5, 5, -100), FRONT_SIZE), 255, 191, 191, 0, "sphere");
        assertPixel(image, FRONT.pixelOf(new Point(-80, 85, -100), FRONT_SIZE), 255, 191, 191, 0, "up-left triangle");
        assertPixel(image, FRONT.pixelOf(new Point(70, 70, -100), FRONT_SIZE), 75, 127, 90, 0, "empty up-right quarter");
        assertPixel(image, new int[] { 0, 57 }, 255, 255, 0, 0, "grid column 0");
        assertPixel(image, new int[] { 57, 180 }, 255, 255, 0, 0, "grid row 180");
    }

    @Test
    @DisplayName("multi-colour: emission plus a 20 % white ambient light, white grid")
    void multiColour() {
        Scene scene = new Scene("multi colour").setAmbientLight(new AmbientLight(new Color(WHITE), new Double3(0.2)));
        scene.geometries.add(new Sphere(new Point(0, 0, -100), 50),
                new Triangle(new Point(-100, 0, -100), new Point(0, 100, -100), new Point(-100, 100, -100))
                        .setEmission(new Color(GREEN)),
                new Triangle(new Point(-100, 0, -100), new Point(0, -100, -100), new Point(-100, -100, -100))
                        .setEmission(new Color(RED)),
                new Triangle(new Point(100, 0, -100), new Point(0, -100, -100), new Point(100, -100, -100))
                        .setEmission(new Color(BLUE)));
        ImageWriter image = Golden.image("multi-color", FRONT_SIZE, FRONT_SIZE);
        FRONT.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene)).build()
                .renderImage().printGrid(20, new Color(WHITE)).writeToImage();

        // Emission + 0.2 × 255 = 51 per channel, clamped at 255.
        assertPixel(image, FRONT.pixelOf(new Point(5, 5, -100), FRONT_SIZE), 51, 51, 51, 0, "sphere: ambient only");
        assertPixel(image, FRONT.pixelOf(new Point(-80, 85, -100), FRONT_SIZE), 51, 255, 51, 0, "green triangle");
        assertPixel(image, FRONT.pixelOf(new Point(-80, -85, -100), FRONT_SIZE), 255, 51, 51, 0, "red triangle");
        assertPixel(image, FRONT.pixelOf(new Point(80, -85, -100), FRONT_SIZE), 51, 51, 255, 0, "blue triangle");
        assertPixel(image, FRONT.pixelOf(new Point(70, 70, -100), FRONT_SIZE), 0, 0, 0, 0, "black background");
    }

    /** Each kind of light on the floor-and-sphere stage. */
    @Nested
    @DisplayName("lights on a floor with a sphere")
    class Lights {
        @Test
        @DisplayName("directional: the whole lit floor has one colour, the shadow only emission + ambient")
        void directional() {
            ImageWriter image = FloorScene.render("light-directional",
                    FloorScene.create("directional", new DirectionalLight(new Color(200, 200, 200), new Vector(1, -1, -1))));
            int lit = (int) (FLOOR_BASE + FLOOR_KD * 200 / Math.sqrt(3)); // |n·l| = 1/√3
            assertPixel(image, floor(-50, 60), lit, lit, lit, 0, "lit floor, front left");
            assertPixel(image, floor(45, 90), lit, lit, lit, 0, "lit floor, front right");
            // The sphere's shadow falls along (1, 0, −1) from below its centre; (45, 0, −15) is inside it.
            int dark = (int) FLOOR_BASE;
            assertPixel(image, floor(45, -15), dark, dark, dark, 0, "floor in the sphere's shadow");
        }

        @Test
        @DisplayName("point: the floor is brightest below the light and dims with distance")
        void point() {
            Point position = new Point(-40, 80, 60);
            ImageWriter image = FloorScene.render("light-point", FloorScene.create("point",
                    new PointLight(new Color(300, 300, 300), position).setKl(0.005).setKq(0.0001)));
            // Below the light: d = 80, n·l = 1, attenuation 1 / (1 + 0.4 + 0.64).
            double below = FLOOR_BASE + FLOOR_KD * 300 / (1 + 0.005 * 80 + 0.0001 * 80 * 80);
            int expected = (int) below;
            assertPixel(image, floor(-40, 60), expected, expected, expected, 1, "floor below the light");
            assertThat(lumaAt(image, floor(-40, 60)))
                    .as("floor below the light vs 100 units aside")
                    .isGreaterThan(lumaAt(image, floor(50, 40)) + 30);
        }

        @Test
        @DisplayName("spot: a bright disc on its axis, falling off sharply with narrow beam 12")
        void spot() {
            ImageWriter image = FloorScene.render("light-spot", FloorScene.create("spot",
                    new SpotLight(new Color(400, 400, 400), new Point(40, 100, 60), new Vector(0, -1, 0))
                            .setKl(0.001).setNarrowBeam(12)));
            // On the axis: cos = 1, d = 100, attenuation 1 / 1.1, n·l = 1.
            int onAxis = (int) (FLOOR_BASE + FLOOR_KD * 400 / 1.1);
            assertPixel(image, floor(40, 60), onAxis, onAxis, onAxis, 1, "floor on the spot's axis");
            // 80 units aside: cos = 100/128 → cos^12 ≈ 0.05, so the floor keeps under a tenth of the light.
            assertThat(lumaAt(image, floor(-40, 60)))
                    .as("floor 80 units off the spot's axis").isLessThan(FLOOR_BASE + 0.1 * FLOOR_KD * 400);
        }
    }

    @Test
    @DisplayName("shadows: a sphere and a floating triangle shade the floor from a point light")
    void shadows() {
        Point light = new Point(-100, 100, -40);
        Scene scene = FloorScene.create("shadows", new PointLight(new Color(350, 330, 300), light).setKl(0.001));
        Point a = new Point(-65, 42, 0), b = new Point(-40, 42, 5), c = new Point(-52, 60, 25);
        scene.geometries.add(new Triangle(a, b, c).setEmission(new Color(20, 60, 20)).setMaterial(new Material().setKd(0.5)));
        ImageWriter image = FloorScene.render("shadows", scene);

        // A shadow's inside: where the line from the light through an occluder's inner point
        // (the sphere's centre, the triangle's centroid) meets the floor.
        Point centroid = new Point((a.getX() + b.getX() + c.getX()) / 3, (a.getY() + b.getY() + c.getY()) / 3,
                (a.getZ() + b.getZ() + c.getZ()) / 3);
        int dark = (int) FLOOR_BASE;
        int[] sphereShadow = FloorScene.VIEW.pixelOf(Golden.onFloor(light, FloorScene.SPHERE_CENTRE), FloorScene.SIZE);
        int[] triangleShadow = FloorScene.VIEW.pixelOf(Golden.onFloor(light, centroid), FloorScene.SIZE);
        int[] lit = FloorScene.VIEW.pixelOf(new Point(20, 0, 90), FloorScene.SIZE);
        assertPixel(image, sphereShadow, dark, dark, dark, 0, "sphere's shadow");
        assertPixel(image, triangleShadow, dark, dark, dark, 0, "triangle's shadow");
        assertThat(lumaAt(image, lit)).as("floor lit by the light").isGreaterThan(dark + 40);
    }

    @Test
    @DisplayName("transparency: a red sphere seen through a blue glass sphere with kT 0.3")
    void transparency() {
        // No ambient light and a light without red: red reaches the image only from the inner
        // sphere's emission (255) through the glass, 0.3 × 255 = 76.5.
        Scene scene = new Scene("transparency");
        scene.geometries.add(
                new Sphere(new Point(0, 0, -50), 50d).setEmission(new Color(BLUE))
                        .setMaterial(new Material().setKd(0.4).setKs(0.3).setShininess(100).setKt(0.3)),
                new Sphere(new Point(0, 0, -50), 25d).setEmission(new Color(RED))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(100)));
        scene.lights.add(new SpotLight(new Color(0, 600, 1000), new Point(-100, -100, 500), new Vector(-1, -1, -2))
                .setKl(0.0004).setKq(0.0000006));
        Golden.View view = new Golden.View(new Point(0, 0, 1000), Point.ZERO, 150, 1000);
        ImageWriter image = Golden.image("transparency", 150, 150);
        view.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene)).build()
                .renderImage().writeToImage();

        int[] centre = view.pixelOf(new Point(0, 0, -50), 150);
        int[] glassOnly = view.pixelOf(new Point(0, 37, 0), 150);
        assertThat(red(image.getRgb(centre[0], centre[1]))).as("red through the glass at the centre").isEqualTo(76);
        assertThat(red(image.getRgb(glassOnly[0], glassOnly[1]))).as("red where only glass is in the way").isZero();
        assertThat(blue(image.getRgb(glassOnly[0], glassOnly[1]))).as("the glass's own blue").isEqualTo(255);
    }

    @Test
    @DisplayName("mirrors: a floor mirror shows the red and the blue sphere upside down")
    void mirrors() {
        Scene scene = new Scene("mirrors").setBackground(new Color(20, 30, 60))
                .setAmbientLight(new AmbientLight(new Color(WHITE), 0.1));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(8, 8, 10))
                        .setMaterial(new Material().setKd(0.2).setKr(0.8)),
                new Sphere(new Point(0, 35, 0), 30).setEmission(new Color(150, 20, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60)),
                new Sphere(new Point(-55, 25, 60), 20).setEmission(new Color(20, 30, 150))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60)));
        scene.lights.add(new DirectionalLight(new Color(150, 150, 150), new Vector(-1, -2, -1)));
        ImageWriter image = FloorScene.render("mirrors", scene);

        // A plane mirror at y = 0 shows a point (x, y, z) where the point (x, −y, z) would be seen.
        int[] redImage = FloorScene.VIEW.pixelOf(new Point(0, -35, 0), FloorScene.SIZE);
        int[] blueImage = FloorScene.VIEW.pixelOf(new Point(-55, -25, 60), FloorScene.SIZE);
        int redSeen = image.getRgb(redImage[0], redImage[1]);
        int blueSeen = image.getRgb(blueImage[0], blueImage[1]);
        assertThat(red(redSeen)).as("red channel of the red sphere's reflection, " + Golden.rgb(redSeen))
                .isGreaterThanOrEqualTo((int) (0.8 * 150)).isGreaterThan(2 * blue(redSeen));
        assertThat(blue(blueSeen)).as("blue channel of the blue sphere's reflection, " + Golden.rgb(blueSeen))
                .isGreaterThanOrEqualTo((int) (0.8 * 150)).isGreaterThan(2 * red(blueSeen));
    }
}
