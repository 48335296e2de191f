package renderer.golden;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * Speed-ups must not change a single pixel: the BVH against the flat geometry list, and worker
 * threads against the calling thread.
 */
@DisplayName("Golden renders: acceleration changes nothing")
class AccelerationGoldenTest {
    private static final int SIZE = 150;

    /**
     * A 6×6 grid of coloured balls (some of glass) and a ring of triangles on a half-mirror floor:
     * many primitives. {@code effects} makes the floor glossy and the point light an area light,
     * so that every pixel also draws random numbers for beams and shadow samples.
     */
    private static Scene crowd(boolean effects) {
        Scene scene = new Scene("crowd").setBackground(new Color(15, 15, 35))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(15, 15, 15))
                .setMaterial(new Material().setKd(0.4).setKs(0.2).setShininess(20).setKr(0.3)
                        .setReflectionSpread(effects ? 0.05 : 0)));
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) {
                double x = -75 + 30 * i, z = -75 + 30 * j;
                Color c = new Color(40 + 40 * i, 60 + 25 * j, 220 - 35 * i);
                scene.geometries.add(new Sphere(new Point(x, 10, z), 9).setEmission(c.scale(0.5))
                        .setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(40).setKt((i + j) % 5 == 0 ? 0.5 : 0)));
            }
        for (int k = 0; k < 12; ++k) {
            double a = 2 * Math.PI * k / 12, b = a + Math.PI / 12;
            scene.geometries.add(new Triangle(new Point(120 * Math.cos(a), 0.5, 120 * Math.sin(a)),
                    new Point(120 * Math.cos(b), 0.5, 120 * Math.sin(b)),
                    new Point(110 * Math.cos(a + Math.PI / 24), 30, 110 * Math.sin(a + Math.PI / 24)))
                    .setEmission(new Color(30, 90, 60)).setMaterial(new Material().setKd(0.5).setKs(0.3).setShininess(30)));
        }
        scene.lights.add(new DirectionalLight(new Color(120, 110, 100), new Vector(-1, -2, -1)));
        scene.lights.add(new PointLight(new Color(300, 280, 250), new Point(40, 90, 80)).setKl(0.002)
                .setRadius(effects ? 8 : 0));
        return scene;
    }

    private static final Golden.View VIEW = new Golden.View(new Point(0, 120, 260), new Point(0, 0, -10), 200, 260);

    private static ImageWriter renderCrowd(boolean bvh) {
        ImageWriter image = Golden.image(bvh ? "bvh-on" : "bvh-off", SIZE, SIZE);
        VIEW.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(crowd(false)).setBvh(bvh))
                .build().renderImage().writeToImage();
        return image;
    }

    @Test
    @DisplayName("BVH on and off give the same pixels")
    void bvhChangesNothing() {
        int[] on = Golden.pixels(renderCrowd(true));
        int[] off = Golden.pixels(renderCrowd(false));
        assertThat(on).as("BVH on vs off").isEqualTo(off);
        assertThat(Arrays.stream(on).distinct().count()).as("distinct colours in the crowd")
                .isGreaterThan(500);
    }

    @Test
    @DisplayName("two worker threads give the calling thread's pixels (2×2 RANDOM, glossy floor, area light)")
    void threadsChangeNothing() {
        ImageWriter image = Golden.image("multithreaded", SIZE, SIZE);
        ImageWriter single = new ImageWriter("unused", SIZE, SIZE);
        Camera.Builder builder = VIEW.builder().setAntiAliasing(AntiAliasing.RANDOM, 2, 2)
                .setRayTracer(new RayTracerBasic(crowd(true)).setBeamSize(8).setShadowSamples(8));
        builder.setImageWriter(image).setMultithreading(2).build().renderImage().writeToImage();
        builder.setImageWriter(single).setMultithreading(0).build().renderImage();

        assertThat(Golden.pixels(image)).as("2 threads vs the calling thread").isEqualTo(Golden.pixels(single));
        // And the effects are on: the plain crowd (BVH on, same settings otherwise) differs.
        ImageWriter plain = new ImageWriter("unused", SIZE, SIZE);
        VIEW.builder().setAntiAliasing(AntiAliasing.RANDOM, 2, 2).setImageWriter(plain)
                .setRayTracer(new RayTracerBasic(crowd(false))).build().renderImage();
        assertThat(Golden.pixels(image)).as("glossy floor and area light vs plain").isNotEqualTo(Golden.pixels(plain));
    }
}
