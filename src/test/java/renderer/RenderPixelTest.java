package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static renderer.Pixels.assertPixel;

import java.util.Set;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * Small renders whose pixels are worked out by hand from the course's model:
 * colour = emission + ambient + Σ lights (kD·|n·l| + kS·max(0, −r·v)^shininess)·I_L·ktr, plus kR
 * times the reflected colour (the ambient is added once, to the camera ray's colour, and never to
 * the background).
 *
 * <p>Unless a test says otherwise the camera stands at (0,0,10) looking along −z with +y up (so
 * vRight = +x), the view plane is 10×10 at distance 10 and the image 5×5: the centre ray of pixel
 * (x, y) meets the plane z = 0 at ((x − 2)·2, (2 − y)·2, 0).
 */
class RenderPixelTest {
    private static final Point EYE = new Point(0, 0, 10);
    /** The floor of most tests: the plane z = 0, facing the camera. */
    private static final Vector UP_Z = new Vector(0, 0, 1);

    private static ImageWriter render(Scene scene, int nX, int nY, double vpWidth, double vpHeight) {
        ImageWriter image = new ImageWriter("pixel-test", nX, nY);
        Camera.getBuilder()
                .setLocation(EYE).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(vpWidth, vpHeight).setVpDistance(10)
                .setImageWriter(image).setRayTracer(new RayTracerBasic(scene))
                .setSummary(false)
                .build().renderImage();
        return image;
    }

    private static ImageWriter render(Scene scene) {
        return render(scene, 5, 5, 10, 10);
    }

    private static Plane floor(Material material) {
        return (Plane) new Plane(Point.ZERO, UP_Z).setMaterial(material);
    }

    @Test
    @DisplayName("a ray that misses shows the background; a hit shows emission + ambient")
    void backgroundAndAmbient() {
        Scene scene = new Scene("ambient").setBackground(new Color(10, 20, 30))
                .setAmbientLight(new AmbientLight(new Color(100, 100, 100), 0.2));
        scene.geometries.add(new Sphere(Point.ZERO, 1).setEmission(new Color(50, 0, 0)));
        ImageWriter image = render(scene);
        assertPixel(image, 2, 2, 50 + 20, 0 + 20, 0 + 20);
        // Pixel (0,0) looks toward (−4, 4, 0) and pixel (3,2) passes 20/√104 ≈ 1.96 from the centre.
        assertPixel(image, 0, 0, 10, 20, 30);
        assertPixel(image, 3, 2, 10, 20, 30);
    }

    @Nested
    @DisplayName("directional light")
    class Directional {
        // Light travelling along (1,0,−1)/√2 onto the plane z = 0 (n = ẑ): |n·l| = 1/√2 everywhere.
        private final Vector direction = new Vector(1, 0, -1);
        private final Color intensity = new Color(200, 100, 50);

        @Test
        @DisplayName("diffuse only: I·kD·|n·l| at every pixel")
        void diffuse() {
            Scene scene = new Scene("directional");
            scene.geometries.add(floor(new Material().setKd(0.5)));
            scene.lights.add(new DirectionalLight(intensity, direction));
            ImageWriter image = render(scene);
            double f = 0.5 / Math.sqrt(2);
            for (int[] p : new int[][] {{2, 2}, {0, 0}, {4, 1}})
                assertPixel(image, p[0], p[1], 200 * f, 100 * f, 50 * f);
        }

        @Test
        @DisplayName("diffuse + specular: the highlight depends on the viewing direction")
        void specular() {
            Scene scene = new Scene("phong");
            scene.geometries.add(floor(new Material().setKd(0.5).setKs(0.4).setShininess(2)));
            scene.lights.add(new DirectionalLight(intensity, direction));
            ImageWriter image = render(scene);
            // r = l − 2(l·n)n = (1, 0, 1)/√2.
            // Centre pixel: v = (0,0,−1), −r·v = 1/√2, squared 1/2.
            double centre = 0.5 / Math.sqrt(2) + 0.4 * 0.5;
            assertPixel(image, 2, 2, 200 * centre, 100 * centre, 50 * centre);
            // Pixel (3,2): v = (2,0,−10)/√104, −r·v = (10 − 2)/(√2·√104).
            double minusRV = 8 / (Math.sqrt(2) * Math.sqrt(104));
            double right = 0.5 / Math.sqrt(2) + 0.4 * minusRV * minusRV;
            assertPixel(image, 3, 2, 200 * right, 100 * right, 50 * right);
        }

        @Test
        @DisplayName("a light from below the plane does not light the face the camera sees")
        void lightFromTheOtherSide() {
            Scene scene = new Scene("underneath");
            scene.geometries.add(floor(new Material().setKd(0.5).setKs(0.5).setShininess(1)));
            scene.lights.add(new DirectionalLight(intensity, new Vector(1, 0, 1)));
            assertPixel(render(scene), 2, 2, 0, 0, 0);
        }
    }

    @Nested
    @DisplayName("point light with kC, kL, kQ")
    class PointLights {
        private Scene scene() {
            Scene scene = new Scene("point")
                    .setAmbientLight(new AmbientLight(new Color(0, 0, 20), 0.5));
            scene.geometries.add(floor(new Material().setKd(0.8)).setEmission(new Color(10, 0, 0)));
            scene.lights.add(new PointLight(new Color(350, 175, 70), new Point(2, 3, 4))
                    .setKc(1).setKl(0.1).setKq(0.01));
            return scene;
        }

        @Test
        @DisplayName("straight below-ish the light: d = 5, attenuation 1 + 0.5 + 0.25")
        void nearPoint() {
            // Pixel (3,2) sees (2,0,0): l = (0,−3,−4)/5, |n·l| = 0.8, d = 5.
            double f = 0.8 * 0.8 / (1 + 0.1 * 5 + 0.01 * 25);
            assertPixel(render(scene()), 3, 2, 10 + 350 * f, 175 * f, 10 + 70 * f);
        }

        @Test
        @DisplayName("farther away: d = √41")
        void fartherPoint() {
            // Pixel (1,2) sees (−2,0,0): to it from the light (−4,−3,−4), d² = 41, |n·l| = 4/√41.
            double d = Math.sqrt(41);
            double f = 0.8 * (4 / d) / (1 + 0.1 * d + 0.01 * 41);
            assertPixel(render(scene()), 1, 2, 10 + 350 * f, 175 * f, 10 + 70 * f);
        }
    }

    @Nested
    @DisplayName("spot light")
    class Spot {
        private ImageWriter render(Vector direction, double narrowBeam) {
            Scene scene = new Scene("spot");
            scene.geometries.add(floor(new Material().setKd(0.5)));
            scene.lights.add(new SpotLight(new Color(250, 250, 250), new Point(0, 0, 4), direction)
                    .setNarrowBeam(narrowBeam));
            return RenderPixelTest.render(scene);
        }

        @Test
        @DisplayName("on its axis: the full intensity")
        void onAxis() {
            assertPixel(render(new Vector(0, 0, -1), 4), 2, 2, 125, 125, 125);
        }

        @ParameterizedTest(name = "pixel ({0},2), narrow beam {1}: cos = {2}/√{3}")
        @CsvSource({"3, 4, 4, 20", "4, 4, 4, 32", "3, 1, 4, 20", "4, 1, 4, 32"})
        @DisplayName("off its axis: the intensity times cos^narrowBeam, times |n·l|")
        void offAxis(int x, double narrowBeam, double cosNumerator, double distanceSquared) {
            // Pixel (x,2) sees (2(x−2),0,0); from the light at (0,0,4) l = (2(x−2),0,−4)/d, and both
            // the spot's cosine and |n·l| are 4/d.
            double cos = cosNumerator / Math.sqrt(distanceSquared);
            double value = 250 * Math.pow(cos, narrowBeam) * 0.5 * cos;
            assertPixel(render(new Vector(0, 0, -1), narrowBeam), x, 2, value, value, value);
        }

        @Test
        @DisplayName("pointing away from the plane: black")
        void pointingAway() {
            ImageWriter image = render(new Vector(0, 0, 1), 1);
            assertPixel(image, 2, 2, 0, 0, 0);
            assertPixel(image, 4, 2, 0, 0, 0);
        }
    }

    @Nested
    @DisplayName("shadows")
    class Shadows {
        /**
         * The floor lit by a directional light along (1,0,−1) with I = 200, kD = 0.5: unshadowed
         * 200·0.5/√2. The occluder at (−2,0,2), radius 0.5, sits on the shadow ray from the
         * centre point (the ray leaves (0,0,0.1) toward (−1,0,1) and passes 0.1/√2 from its
         * centre), crossing it twice; it is out of the way of the centre pixel's camera ray and of
         * the shadow ray of pixel (3,2).
         */
        @ParameterizedTest(name = "occluder kT {0}: light term x {1}")
        @CsvSource({"0, 0", "0.5, 0.25", "1, 1"})
        void transparentOccluder(double kT, double expectedFactor) {
            Scene scene = new Scene("shadow");
            scene.geometries.add(floor(new Material().setKd(0.5)),
                    new Sphere(new Point(-2, 0, 2), 0.5).setMaterial(new Material().setKt(kT)));
            scene.lights.add(new DirectionalLight(new Color(200, 200, 200), new Vector(1, 0, -1)));
            ImageWriter image = render(scene);
            double lit = 200 * 0.5 / Math.sqrt(2);
            assertPixel(image, 3, 2, lit, lit, lit);
            double shadowed = lit * expectedFactor;
            assertPixel(image, 2, 2, shadowed, shadowed, shadowed);
        }
    }

    @Nested
    @DisplayName("mirror")
    class Mirror {
        /**
         * The floor is a mirror; the camera's centre ray is reflected straight back up to the
         * bottom of a sphere (centre (0,0,20), radius 1) behind the camera. There, a point light at
         * (0,0,15) shines straight up onto it: the sphere's colour at (0,0,19) is its emission
         * (20,40,60) plus 100·kD·|n·l| = 50. The mirror pixel is kR times that.
         */
        @ParameterizedTest(name = "kR = ({0}, {1}, {2})")
        @CsvSource({"1, 1, 1", "0.5, 0.5, 0.5", "1, 0.5, 0.25"})
        void reflectsTheSphere(double r, double g, double b) {
            Scene scene = new Scene("mirror");
            scene.geometries.add(floor(new Material().setKr(new Double3(r, g, b))),
                    new Sphere(new Point(0, 0, 20), 1).setEmission(new Color(20, 40, 60))
                            .setMaterial(new Material().setKd(0.5)));
            scene.lights.add(new PointLight(new Color(100, 100, 100), new Point(0, 0, 15)));
            assertPixel(render(scene), 2, 2, r * 70, g * 90, b * 110);
        }
    }

    @Nested
    @DisplayName("a non-square image (80x40) keeps columns and rows apart")
    class NonSquare {
        private final Color paint = new Color(200, 100, 0);
        private final Color background = new Color(0, 0, 50);

        /**
         * An 8x4 view plane at distance 10 over 80x40 pixels: pixel (x, y) sees
         * ((x + 0.5 − 40)/10, (20 − y − 0.5)/10) on the plane z = 0.
         */
        private ImageWriter renderQuad(double x0, double x1, double y0, double y1) {
            Scene scene = new Scene("half").setBackground(background);
            scene.geometries.add(new Polygon(new Point(x0, y0, 0), new Point(x1, y0, 0), new Point(x1, y1, 0),
                    new Point(x0, y1, 0)).setEmission(paint));
            return render(scene, 80, 40, 8, 4);
        }

        private void assertHalves(ImageWriter image, boolean leftHalf) {
            assertThat(image.getNx()).isEqualTo(80);
            assertThat(image.getNy()).isEqualTo(40);
            int painted = paint.toRgb(), empty = background.toRgb();
            for (int y = 0; y < 40; ++y)
                for (int x = 0; x < 80; ++x) {
                    boolean inside = leftHalf ? x < 40 : y < 20;
                    assertThat(image.getRgb(x, y)).as("pixel (%d,%d)", x, y).isEqualTo(inside ? painted : empty);
                }
        }

        @Test
        @DisplayName("geometry on the left half: columns 0..39 painted, 40..79 background")
        void leftHalf() {
            assertHalves(renderQuad(-100, 0, -100, 100), true);
        }

        @Test
        @DisplayName("geometry on the top half: rows 0..19 painted, 20..39 background")
        void topHalf() {
            assertHalves(renderQuad(-100, 100, 0, 100), false);
        }
    }

    @Nested
    @DisplayName("printGrid")
    class Grid {
        @Test
        @DisplayName("7x5 image, interval 3: columns 0, 3, 6 and rows 0, 3")
        void linesAtMultiplesOfTheInterval() {
            Color background = new Color(0, 0, 50), yellow = new Color(255, 255, 0);
            ImageWriter image = new ImageWriter("grid", 7, 5);
            Camera.getBuilder()
                    .setLocation(EYE).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                    .setVpSize(7, 5).setVpDistance(10)
                    .setImageWriter(image).setRayTracer(new RayTracerBasic(new Scene("grid").setBackground(background)))
                    .setSummary(false)
                    .build().renderImage().printGrid(3, yellow);
            Set<Integer> gridColumns = Set.of(0, 3, 6), gridRows = Set.of(0, 3);
            for (int y = 0; y < 5; ++y)
                for (int x = 0; x < 7; ++x) {
                    boolean line = gridColumns.contains(x) || gridRows.contains(y);
                    assertThat(image.getRgb(x, y)).as("pixel (%d,%d)", x, y)
                            .isEqualTo(line ? 0xFFFF00 : background.toRgb());
                }
        }

        @ParameterizedTest(name = "interval {0}")
        @CsvSource({"0", "-3"})
        void nonPositiveIntervalRejected(int interval) {
            Camera camera = Camera.getBuilder()
                    .setLocation(EYE).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                    .setVpSize(1, 1).setVpDistance(1)
                    .setImageWriter(new ImageWriter("grid", 2, 2)).setRayTracer(new RayTracerBasic(new Scene("grid")))
                    .build();
            assertThatIllegalArgumentException().isThrownBy(() -> camera.printGrid(interval, Color.BLACK))
                    .withMessageContaining(String.valueOf(interval));
        }
    }
}
