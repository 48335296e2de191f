package renderer.golden;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Percentage.withPercentage;
import static renderer.golden.Golden.blue;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import geometries.Sphere;
import geometries.Triangle;
import primitives.Color;
import primitives.Point;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * Every anti-aliasing mode on the same flat scene: a white triangle with slanted edges and a red
 * ball on black, emission only. One pixel of the view plane is one scene unit at z = 0, and the
 * ball has no blue, so the blue channel of a pixel is 255 × the share of it the triangle covers:
 * summed over the image it must give the triangle's area, whatever the mode.
 */
@DisplayName("Golden renders: anti-aliasing modes")
class AntiAliasingGoldenTest {
    private static final int SIZE = 120;
    private static final Golden.View VIEW = new Golden.View(new Point(0, 0, 120), Point.ZERO, SIZE, 120);
    private static final Point A = new Point(-45, -40, 0), B = new Point(50, -25, 0), C = new Point(-15, 48, 0);
    /** |AB × AC| / 2 = |95·88 − 15·30| / 2, in square pixels. */
    private static final double TRIANGLE_AREA = 3955;
    /** About 95 + 73 + 88 pixels lie on the three edges; most are partly covered. */
    private static final int MIN_BLENDED_EDGE_PIXELS = 150;

    private static Scene scene() {
        Scene scene = new Scene("anti-aliasing");
        scene.geometries.add(new Triangle(A, B, C).setEmission(new Color(255, 255, 255)),
                new Sphere(new Point(35, 35, -10), 15).setEmission(new Color(255, 0, 0)));
        return scene;
    }

    /** The camera of a mode: RANDOM with a 4×4 grid, ADAPTIVE down to 1/8 pixel with threshold 8. */
    private static Camera camera(AntiAliasing mode, ImageWriter image) {
        Camera.Builder builder = VIEW.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene()))
                .setAntiAliasing(mode);
        if (mode == AntiAliasing.RANDOM) builder.setAntiAliasingGrid(4, 4);
        if (mode == AntiAliasing.ADAPTIVE) builder.setAdaptive(3, 8);
        return builder.build();
    }

    private static ImageWriter render(AntiAliasing mode) {
        ImageWriter image = Golden.image("aa-" + mode.name().toLowerCase(), SIZE, SIZE);
        camera(mode, image).renderImage().writeToImage();
        return image;
    }

    private static double coveredArea(ImageWriter image) {
        double sum = 0;
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x) sum += blue(image.getRgb(x, y)) / 255.0;
        return sum;
    }

    private static int blendedPixels(ImageWriter image) {
        int count = 0;
        for (int y = 0; y < SIZE; ++y)
            for (int x = 0; x < SIZE; ++x) {
                int b = blue(image.getRgb(x, y));
                if (b > 0 && b < 255) ++count;
            }
        return count;
    }

    @ParameterizedTest(name = "{0}: the covered area is the triangle's area within 0.5 %")
    @EnumSource(AntiAliasing.class)
    void areaIsPreserved(AntiAliasing mode) {
        ImageWriter image = render(mode);
        assertThat(coveredArea(image)).as("triangle area from the blue channel, %s", mode)
                .isCloseTo(TRIANGLE_AREA, withPercentage(0.5));
        if (mode == AntiAliasing.NONE)
            assertThat(blendedPixels(image)).as("pixels between black and white without anti-aliasing").isZero();
        else
            assertThat(blendedPixels(image)).as("blended edge pixels with %s", mode)
                    .isGreaterThanOrEqualTo(MIN_BLENDED_EDGE_PIXELS);
    }

    @Test
    @DisplayName("ADAPTIVE refines only at edges: more rays than one per pixel corner, fewer than CORNERS")
    void adaptiveRefinesOnlyEdges() {
        long corners = cameraRays(AntiAliasing.CORNERS);
        long random = cameraRays(AntiAliasing.RANDOM);
        long adaptive = cameraRays(AntiAliasing.ADAPTIVE);
        assertThat(random).as("4x4 RANDOM rays").isEqualTo(16L * SIZE * SIZE);
        // One ray per pixel corner where the image is flat, more at the edges; CORNERS traces the
        // corners and every pixel's centre.
        assertThat(adaptive).as("ADAPTIVE camera rays").isGreaterThan((SIZE + 1L) * (SIZE + 1)).isLessThan(corners);
    }

    /** Renders a mode again (without writing it) for its ray count. */
    private static long cameraRays(AntiAliasing mode) {
        return camera(mode, new ImageWriter("unused", SIZE, SIZE)).render().cameraRays();
    }
}
