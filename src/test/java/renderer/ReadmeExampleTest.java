package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Sphere;
import lighting.AmbientLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/** The README's course-style scene test, verbatim but for the assertions: the example must work. */
class ReadmeExampleTest {
    private final Scene scene = new Scene("two spheres")
            .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));

    private final Camera.Builder camera = Camera.getBuilder()
            .setLocation(new Point(0, 0, 1000))
            .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
            .setVpSize(150, 150).setVpDistance(1000)
            .setRayTracer(new RayTracerBasic(scene));

    @Test
    @DisplayName("the README example renders images/twoSpheres.png with the inner sphere seen through the outer one")
    void twoSpheres() throws Exception {
        scene.geometries.add(
                new Sphere(new Point(0, 0, -50), 50).setEmission(new Color(0, 0, 100))
                        .setMaterial(new Material().setKd(0.4).setKs(0.3).setShininess(100).setKt(0.3)),
                new Sphere(new Point(0, 0, -50), 25).setEmission(new Color(100, 50, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(100)));
        scene.lights.add(new SpotLight(new Color(1000, 600, 0), new Point(-100, -100, 500), new Vector(-1, -1, -2))
                .setKl(0.0004).setKq(0.0000006));

        ImageWriter image = new ImageWriter("twoSpheres", 500, 500);
        Path png = image.getPath();
        Files.deleteIfExists(png);
        camera.setImageWriter(image)
                .setAntiAliasing(AntiAliasing.ADAPTIVE)
                .setMultithreading(-2)
                .build()
                .renderImage()
                .writeToImage();

        assertThat(png).exists();
        // The centre looks through the transparent outer sphere (kT 0.3) at the orange inner one:
        // more red than blue, unlike the rim, which shows the blue outer sphere alone.
        int centre = image.getRgb(250, 250), rim = image.getRgb(250, 250 - 150);
        assertThat((centre >> 16) & 0xFF).as("centre red").isGreaterThan(centre & 0xFF);
        assertThat(rim & 0xFF).as("rim blue").isGreaterThan((rim >> 16) & 0xFF);
        Files.deleteIfExists(png);
    }
}
