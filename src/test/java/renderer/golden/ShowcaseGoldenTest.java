package renderer.golden;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.RenderStats;
import scene.Scene;
import scene.samples.Showcase;

/**
 * The built-in showcase at 300×300 with adaptive anti-aliasing: the README's hero picture, so
 * the picture users see first is the one CI verifies.
 */
class ShowcaseGoldenTest {

    @Test
    @DisplayName("showcase: background above the wall, lit geometry in the middle, adaptive cheaper than 8×8")
    void showcase() {
        Scene scene = Showcase.create();
        ImageWriter image = Golden.image("showcase", 300, 300);
        RenderStats stats = Camera.getBuilder()
                .setLocation(Showcase.CAMERA_LOCATION).setDirection(Showcase.CAMERA_TARGET, Vector.AXIS_Y)
                .setVpSize(Showcase.VP_SIZE, Showcase.VP_SIZE).setVpDistance(Showcase.VP_DISTANCE)
                .setImageWriter(image).setRayTracer(new RayTracerBasic(scene))
                .setAntiAliasing(AntiAliasing.ADAPTIVE).setMultithreading(2).setSummary(false)
                .build().render();
        image.writeToImage();

        // The top-left corner looks over the wall into the background.
        assertEquals(scene.background.toRgb(), image.getRgb(0, 0), "top-left pixel is the background");
        // The middle of the picture shows lit geometry, not background or black.
        assertTrue(Golden.luma(image.getRgb(150, 170)) > 40, "centre is lit: " + Golden.rgb(image.getRgb(150, 170)));
        // Adaptive sampling spends extra rays only at edges: far fewer than a full 8×8 grid.
        assertTrue(stats.samplesPerPixel() > 1 && stats.samplesPerPixel() < 16,
                "samples per pixel " + stats.samplesPerPixel());
    }
}
