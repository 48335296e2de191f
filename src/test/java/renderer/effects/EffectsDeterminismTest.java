package renderer.effects;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
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
 * Glossy beams, diffuse glass and soft shadows draw random numbers from per-pixel streams, so
 * the image depends on the seed only: not on the number of threads or the order tiles are
 * rendered in.
 */
@DisplayName("Glossy, diffuse glass and soft shadows are deterministic")
class EffectsDeterminismTest {
    private static final int SIZE = 80;

    private static Scene scene() {
        Scene scene = new Scene("all effects").setBackground(new Color(25, 30, 45))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.08));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(25, 25, 25))
                        .setMaterial(new Material().setKd(0.4).setKs(0.2).setShininess(30).setKr(0.5).setReflectionSpread(0.08)),
                new Sphere(new Point(-20, 22, 0), 22).setEmission(new Color(130, 30, 30))
                        .setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(60)),
                new Polygon(new Point(0, 0, 30), new Point(45, 0, 30), new Point(45, 45, 30), new Point(0, 45, 30))
                        .setEmission(new Color(10, 20, 30))
                        .setMaterial(new Material().setKd(0.1).setKt(0.8).setTransmissionSpread(0.15)));
        scene.lights.add(new PointLight(new Color(350, 330, 300), new Point(40, 110, 90)).setKl(0.002).setRadius(10));
        return scene;
    }

    private static ImageWriter render(int threads, long seed) {
        ImageWriter image = new ImageWriter("effects-threads", SIZE, SIZE);
        Camera.getBuilder().setLocation(new Point(0, 70, 200)).setDirection(new Point(0, 15, 0), Vector.AXIS_Y)
                .setVpSize(100, 100).setVpDistance(150).setSummary(false).setAntiAliasing(AntiAliasing.RANDOM, 2, 2).setSeed(seed)
                .setMultithreading(threads).setImageWriter(image)
                .setRayTracer(new RayTracerBasic(scene()).setBeamSize(4).setShadowSamples(4))
                .build().renderImage();
        return image;
    }

    @ParameterizedTest(name = "{0} worker thread(s) give the calling thread's pixels")
    @ValueSource(ints = { 1, 2 })
    void sameImageForAnyThreadCount(int threads) {
        assertThat(Profiles.pixels(render(threads, 3))).as("%d threads vs the calling thread", threads)
                .isEqualTo(Profiles.pixels(render(0, 3)));
    }

    @Test
    @DisplayName("the seed does matter: another seed gives other noise (so the comparison above can fail)")
    void seedChangesTheNoise() {
        assertThat(Profiles.pixels(render(0, 4))).isNotEqualTo(Profiles.pixels(render(0, 3)));
    }
}
