package renderer.effects;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Percentage.withPercentage;

import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Plane;
import geometries.Polygon;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * The penumbra of a straight shadow edge. The camera looks straight down at a matte floor; a
 * light at (−30, 100, 0) shines past the edge x = −15 of a large horizontal board at height 50
 * (outside the camera's view), so the hard shadow covers the floor x &lt; 0 and its edge is the
 * line x = 0, the image's middle column. No ambient light: the shadow is black.
 *
 * <p>A disk light of radius R blurs the edge symmetrically about the hard edge: on the floor, a
 * point of the disk offset by δ across the edge moves the edge by about −δ. So the penumbra's
 * width grows in proportion to R, and the light it lets through (integrated across the edge)
 * is the hard shadow's: what the dark side gains the bright side loses.
 */
@DisplayName("Soft shadows: the penumbra widens with the light's radius and keeps the hard shadow's light")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class SoftShadowTest {
    private static final Point LIGHT = new Point(-30, 100, 0);
    private static final int SAMPLES = 64;
    /** Rows over floor z ∈ [−10, 10]: the edge is straight along z, so every row is a sample of the profile. */
    private static final int ROW_FROM = 50, ROW_TO = 150;
    /** Columns over floor x ∈ [−9, 9]: the widest penumbra (R = 6) with a margin. */
    private static final int WINDOW_FROM = 55, WINDOW_TO = 145;

    private final Map<Double, double[]> profiles = new HashMap<>();

    private static Scene scene(double radius) {
        Scene scene = new Scene("straight shadow edge");
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Y).setMaterial(new Material().setKd(1)),
                new Polygon(new Point(-300, 50, -300), new Point(-15, 50, -300), new Point(-15, 50, 300),
                        new Point(-300, 50, 300)));
        scene.lights.add(new PointLight(new Color(200, 200, 200), LIGHT).setRadius(radius));
        return scene;
    }

    @BeforeAll
    void renderAll() {
        for (double radius : new double[] { 0, 2, 4, 6 }) {
            ImageWriter image = new ImageWriter("effects-penumbra-" + radius, Profiles.SIZE, Profiles.SIZE);
            Profiles.topDown().setImageWriter(image)
                    .setRayTracer(new RayTracerBasic(scene(radius)).setShadowSamples(SAMPLES)).build().renderImage();
            profiles.put(radius, Profiles.alongX(image, ROW_FROM, ROW_TO));
        }
    }

    private int width(double radius) {
        return Profiles.edgeWidth(profiles.get(radius));
    }

    @Test
    @DisplayName("radius 0 is the hard shadow: black left of x = 0, lit right of it")
    void hardShadowIsAStep() {
        double[] hard = profiles.get(0.0);
        assertThat(hard[Profiles.SIZE / 2 - 1]).as("floor just left of x = 0").isZero();
        assertThat(hard[Profiles.SIZE / 2]).as("floor just right of x = 0").isGreaterThan(150);
        assertThat(width(0)).as("hard edge width").isLessThanOrEqualTo(1);
    }

    @Test
    @DisplayName("the 10 %–90 % width grows in proportion to the radius")
    void penumbraWidensWithRadius() {
        int w2 = width(2), w4 = width(4), w6 = width(6);
        assertThat(w2).as("penumbra width in pixels for R = 2").isGreaterThan(width(0) + 4);
        assertThat(w4).as("penumbra width for R = 4 (R = 2: %d)", w2).isGreaterThan(w2);
        assertThat(w6).as("penumbra width for R = 6 (R = 4: %d)", w4).isGreaterThan(w4);
        assertThat((double) w6 / w2).as("width ratio R = 6 over R = 2").isBetween(2.4, 3.6);
    }

    @ParameterizedTest(name = "R = {0}: light across the penumbra within 5 % of the hard shadow's")
    @ValueSource(doubles = { 2, 4, 6 })
    void penumbraKeepsTheLight(double radius) {
        double hard = Profiles.mean(profiles.get(0.0), WINDOW_FROM, WINDOW_TO);
        double soft = Profiles.mean(profiles.get(radius), WINDOW_FROM, WINDOW_TO);
        assertThat(hard).as("mean brightness across the hard edge").isGreaterThan(50);
        assertThat(soft).as("mean brightness across the penumbra, hard shadow %.2f", hard)
                .isCloseTo(hard, withPercentage(5));
    }
}
