import org.junit.jupiter.api.Test;

import geometries.Sphere;
import lighting.AmbientLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.RayTracerType;
import scene.Scene;

class SpheresTest {
    private final Scene scene = new Scene("two spheres")
            .setAmbientLight(new AmbientLight(new Color(255, 255, 255)));

    private final Camera.Builder camera = Camera.getBuilder()
            .setLocation(new Point(0, 0, 1000))
            .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
            .setVpSize(150, 150).setVpDistance(1000)
            .setRayTracer(scene, RayTracerType.SIMPLE);

    @Test
    void twoSpheres() {
        scene.geometries.add(
                new Sphere(new Point(0, 0, -50), 50).setEmission(new Color(0, 0, 100))
                        .setMaterial(new Material().setKA(0.1).setKD(0.4).setKS(0.3).setShininess(100).setKT(0.3)),
                new Sphere(new Point(0, 0, -50), 25).setEmission(new Color(100, 50, 20))
                        .setMaterial(new Material().setKA(0.1).setKD(0.5).setKS(0.5).setShininess(100)));
        scene.lights.add(new SpotLight(new Color(1000, 600, 0), new Point(-100, -100, 500), new Vector(-1, -1, -2))
                .setKl(0.0004).setKq(0.0000006));

        camera.setResolution(500, 500)
                .setAntiAliasing(AntiAliasing.ADAPTIVE)   // ← one line per improvement
                .setMultithreading(-2)                    // ← all cores
                .build()
                .renderImage()
                .writeToImage("twoSpheres");              // → images/twoSpheres.png
    }
}
