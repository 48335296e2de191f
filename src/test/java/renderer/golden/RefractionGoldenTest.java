package renderer.golden;

import static java.awt.Color.WHITE;
import static org.assertj.core.api.Assertions.assertThat;
import static renderer.golden.Golden.blue;
import static renderer.golden.Golden.green;
import static renderer.golden.Golden.red;
import static renderer.golden.Golden.rgb;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * Golden renders of refraction with an index ({@code Material.setIor}): a glass ball in front of
 * a checkerboard (index 1, the course's straight transmission, and 1.5), and the surface of a
 * glass slab seen from inside at grazing angles (total internal reflection).
 */
@DisplayName("Golden renders: refraction with an index")
class RefractionGoldenTest {
    private static final int SIZE = 150;

    @Nested
    @DisplayName("a glass ball (radius 30) in front of a checkerboard, red on the left, blue on the right")
    class GlassBall {
        private static final Golden.View VIEW = new Golden.View(new Point(0, 0, 300), Point.ZERO, 100, 300);
        /** A point of the ball's disc left of its centre, where index 1 shows the left of the board. */
        private static final Point LEFT_OF_CENTRE = new Point(-18, 0, 0);

        @Test
        @DisplayName("index 1 (before): the ball shows the board straight through, red behind its left half")
        void indexOne() {
            ImageWriter image = render("refraction-off", 1);
            int left = image.getRgb(VIEW.pixelOf(LEFT_OF_CENTRE, SIZE)[0], VIEW.pixelOf(LEFT_OF_CENTRE, SIZE)[1]);
            assertThat(red(left)).as("left of the ball's centre, " + rgb(left)).isGreaterThan(blue(left) + 40);
        }

        @Test
        @DisplayName("index 1.5 (after): the ball is a lens beyond whose focus the board is inverted, blue on the left")
        void indexOneAndAHalf() {
            // A ray 18 units left of the axis leaves the ball bent by about 27° toward the axis,
            // crosses it about 40 units behind the centre and meets the board (60 behind) about
            // 10 units right of the axis: the blue half.
            ImageWriter image = render("refraction-sphere", 1.5);
            int left = image.getRgb(VIEW.pixelOf(LEFT_OF_CENTRE, SIZE)[0], VIEW.pixelOf(LEFT_OF_CENTRE, SIZE)[1]);
            assertThat(blue(left)).as("left of the ball's centre, " + rgb(left)).isGreaterThan(red(left) + 40);
            // Outside the ball nothing bends: the board's left half stays red.
            int beside = image.getRgb(VIEW.pixelOf(new Point(-45, 0, 0), SIZE)[0], VIEW.pixelOf(new Point(-45, 0, 0), SIZE)[1]);
            assertThat(red(beside)).as("left of the ball, " + rgb(beside)).isGreaterThan(blue(beside) + 40);
        }

        private ImageWriter render(String what, double ior) {
            Scene scene = new Scene("glass ball, ior " + ior).setAmbientLight(new AmbientLight(new Color(WHITE), 0.05));
            // The board 60 units behind the ball: 10-unit squares, red shades left of x = 0, blue right.
            for (int x = -80; x < 80; x += 10)
                for (int y = -80; y < 80; y += 10) {
                    boolean dark = ((x + y) / 10 & 1) != 0;
                    Color c = x < 0 ? (dark ? new Color(90, 20, 20) : new Color(220, 60, 50))
                            : (dark ? new Color(20, 30, 90) : new Color(50, 90, 220));
                    scene.geometries.add(new Polygon(new Point(x, y, -60), new Point(x + 10, y, -60),
                            new Point(x + 10, y + 10, -60), new Point(x, y + 10, -60)).setEmission(c));
                }
            // Behind the board, a dark plane fills the hairline seams between its squares (a ray
            // exactly on a shared polygon edge hits neither polygon, as the course specifies).
            scene.geometries.add(new Plane(new Point(0, 0, -61), Vector.AXIS_Z).setEmission(new Color(45, 25, 50)));
            scene.geometries.add(new Sphere(Point.ZERO, 30).setEmission(new Color(2, 4, 6))
                    .setMaterial(new Material().setKd(0.02).setKs(0.6).setShininess(300).setKt(0.9).setKr(0.1).setIor(ior)));
            scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(-100, 120, 200)).setKl(0.001));
            ImageWriter image = Golden.image(what, SIZE, SIZE);
            VIEW.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene)).build().renderImage().writeToImage();
            return image;
        }
    }

    @Nested
    @DisplayName("inside a glass slab, looking up at its surface from 15° to 75° above the horizon")
    class SlabFromInside {
        /** The camera, 20 units below the surface y = 0, looks up 45° toward −z. */
        private static final Point EYE = new Point(0, -20, 0);
        private static final Golden.View VIEW = new Golden.View(EYE, new Point(0, 80, -100), 115, 100);
        private static final Color SKY = new Color(110, 160, 240);

        @Test
        @DisplayName("index 1 (before): the surface lets the sky through at every angle")
        void indexOne() {
            ImageWriter image = render("refraction-tir-off", 1);
            assertSky(image, seenAtElevation(30), "30° above the horizon");
            assertSky(image, seenAtElevation(60), "60° above the horizon");
        }

        @Test
        @DisplayName("index 1.5 (after): the sky within 41.8° of the normal, the floor mirrored beyond it")
        void totalInternalReflection() {
            ImageWriter image = render("refraction-tir", 1.5);
            // The critical angle asin(1/1.5) = 41.8° from the normal is 48.2° above the horizon.
            assertSky(image, seenAtElevation(52), "52° above the horizon (within Snell's window)");
            for (double elevation : new double[] { 44, 35, 20 }) {
                int[] at = seenAtElevation(elevation);
                int rgb = image.getRgb(at[0], at[1]);
                assertThat(blue(rgb)).as("%s° above the horizon: the floor's orange mirrored, not the sky: %s",
                        elevation, rgb(rgb)).isLessThan(red(rgb));
            }
        }

        private static void assertSky(ImageWriter image, int[] at, String where) {
            int rgb = image.getRgb(at[0], at[1]);
            assertThat(blue(rgb)).as(where + ": the sky, " + rgb(rgb)).isGreaterThan(red(rgb) + 60)
                    .isGreaterThan(green(rgb));
        }

        /** The pixel whose ray from the eye rises {@code degrees} above the horizon (toward −z). */
        private static int[] seenAtElevation(double degrees) {
            double e = Math.toRadians(degrees);
            return VIEW.pixelOf(EYE.add(new Vector(0, Math.sin(e), -Math.cos(e)).scale(10)), SIZE);
        }

        private ImageWriter render(String what, double ior) {
            Scene scene = new Scene("glass slab, ior " + ior).setBackground(SKY)
                    .setAmbientLight(new AmbientLight(new Color(WHITE), 0.02));
            // The slab's top surface, its normal up (out of the glass): the camera is inside.
            scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Y)
                    .setMaterial(new Material().setKt(0.95).setIor(ior)));
            // The floor of the slab, inside the glass: orange and brown 20-unit squares.
            for (int x = -200; x < 200; x += 20)
                for (int z = -400; z < 40; z += 20) {
                    boolean dark = ((x + z) / 20 & 1) != 0;
                    scene.geometries.add(new Polygon(new Point(x, -40, z), new Point(x, -40, z + 20),
                            new Point(x + 20, -40, z + 20), new Point(x + 20, -40, z))
                            .setEmission(dark ? new Color(120, 50, 10) : new Color(240, 150, 40)));
                }
            ImageWriter image = Golden.image(what, SIZE, SIZE);
            VIEW.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene)).build().renderImage().writeToImage();
            return image;
        }
    }
}
