package renderer.effects;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import geometries.Plane;
import geometries.Polygon;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * How much a glossy mirror blurs. The camera looks straight down at a mirror floor (kR 1, no
 * light, black background), so it sees the ceiling as if from (0, −100, 0), 100 units below the
 * floor. Above the camera hang two white half-planes with an edge along x at z = 0: a near one at
 * height 110 reflected in the left half of the floor, a far one at height 1000 in the right half.
 * The image shows each edge as a black-to-white step across the middle row; its 10 %–90 % width,
 * averaged over 50 columns, measures the blur.
 *
 * <p>Expected width. A beam aims uniformly at a disk of radius {@code spread} at unit distance,
 * so at height h the reflected points cover a disk of radius spread·h around the mirror image.
 * Seen from 100 + h away through a view plane at distance 100 with 5 pixels per unit, that is a
 * disk of radius ρ = 500·spread·h / (100 + h) pixels; a straight edge blurred by a uniform disk of
 * radius ρ rises from 10 % to 90 % over 1.374·ρ.
 */
@DisplayName("Glossy reflection: the blur grows with the spread and with the distance of what is reflected")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class GlossyBlurTest {
    private static final double NEAR_HEIGHT = 110, FAR_HEIGHT = 1000;
    /** Columns over floor x ∈ [−15, −5] (the near half-plane) and x ∈ [5, 15] (the far one). */
    private static final int NEAR_FROM = 25, NEAR_TO = 75, FAR_FROM = 125, FAR_TO = 175;
    /** 10 %–90 % width of a straight edge blurred by a uniform disk, per unit of its radius. */
    private static final double DISK_EDGE_WIDTH = 1.374;
    private static final int BEAM = 64;

    private static Scene scene(double spread) {
        Scene scene = new Scene("glossy stripes");
        Color white = new Color(255, 255, 255);
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Y).setMaterial(new Material().setKr(1).setReflectionSpread(spread)),
                new Polygon(new Point(-1000, NEAR_HEIGHT, 0), new Point(0, NEAR_HEIGHT, 0),
                        new Point(0, NEAR_HEIGHT, 1000), new Point(-1000, NEAR_HEIGHT, 1000)).setEmission(white),
                new Polygon(new Point(0, FAR_HEIGHT, 0), new Point(10000, FAR_HEIGHT, 0),
                        new Point(10000, FAR_HEIGHT, 10000), new Point(0, FAR_HEIGHT, 10000)).setEmission(white));
        return scene;
    }

    private static ImageWriter render(double spread) {
        ImageWriter image = new ImageWriter("effects-glossy-" + spread, Profiles.SIZE, Profiles.SIZE);
        Profiles.topDown().setImageWriter(image).setRayTracer(new RayTracerBasic(scene(spread)).setBeamSize(BEAM))
                .build().renderImage();
        return image;
    }

    private static int nearWidth(ImageWriter image) {
        return Profiles.edgeWidth(Profiles.alongY(image, NEAR_FROM, NEAR_TO));
    }

    private static int farWidth(ImageWriter image) {
        return Profiles.edgeWidth(Profiles.alongY(image, FAR_FROM, FAR_TO));
    }

    private static double expectedWidth(double spread, double height) {
        return DISK_EDGE_WIDTH * 500 * spread * height / (100 + height);
    }

    private ImageWriter mirror, slightlyGlossy, glossy;

    @BeforeAll
    void renderAll() {
        mirror = render(0);
        slightlyGlossy = render(0.02);
        glossy = render(0.05);
    }

    @Test
    @DisplayName("a perfect mirror (spread 0) keeps both edges sharp")
    void perfectMirrorIsSharp() {
        assertThat(nearWidth(mirror)).as("near edge width, spread 0").isLessThanOrEqualTo(1);
        assertThat(farWidth(mirror)).as("far edge width, spread 0").isLessThanOrEqualTo(1);
    }

    @Nested
    @DisplayName("the blur grows")
    class Grows {
        @Test
        @DisplayName("with the distance of the reflected object: far edge wider than near edge")
        void withDistance() {
            // Expected ratio (1000/1100) / (110/210) ≈ 1.74.
            for (ImageWriter image : new ImageWriter[] { slightlyGlossy, glossy })
                assertThat((double) farWidth(image)).as("far edge width of %s, near is %d", image.getImageName(),
                        nearWidth(image)).isGreaterThan(1.4 * nearWidth(image));
        }

        @Test
        @DisplayName("with the spread: spread 0.05 blurs about 2.5 × as wide as 0.02")
        void withSpread() {
            assertThat((double) nearWidth(glossy)).as("near edge width at 0.05, vs %d at 0.02", nearWidth(slightlyGlossy))
                    .isGreaterThan(2.0 * nearWidth(slightlyGlossy));
            assertThat((double) farWidth(glossy)).as("far edge width at 0.05, vs %d at 0.02", farWidth(slightlyGlossy))
                    .isGreaterThan(2.0 * farWidth(slightlyGlossy));
        }
    }

    @ParameterizedTest(name = "spread {0}, {1} object: width 1.374·500·spread·h/(100+h) within 10 % + 1 px")
    @CsvSource({ "0.02, near", "0.02, far", "0.05, near", "0.05, far" })
    @DisplayName("the spread means the tangent of the cone half-angle: the width matches the geometry")
    void widthMatchesTheSpreadsMeaning(double spread, String which) {
        ImageWriter image = spread == 0.02 ? slightlyGlossy : glossy;
        boolean near = which.equals("near");
        double expected = expectedWidth(spread, near ? NEAR_HEIGHT : FAR_HEIGHT);
        int measured = near ? nearWidth(image) : farWidth(image);
        assertThat((double) measured).as("edge width in pixels, expected %.1f", expected)
                .isBetween(0.9 * expected - 1, 1.1 * expected + 1);
    }
}
