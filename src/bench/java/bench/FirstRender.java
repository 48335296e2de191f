package bench;

import java.util.Locale;

import geometries.Sphere;
import lighting.AmbientLight;
import lighting.SpotLight;
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
 * The README's first scene test (two spheres, 500×500, adaptive anti-aliasing, all cores) rendered
 * several times in one JVM, as a JUnit suite renders its scenes: the first render pays for class
 * loading and the JIT, the next ones show the warm speed. Started in a fresh JVM each time by
 * {@code scripts/cold_start_benchmark.py}, which pairs the first render against the second.
 *
 * <p>Argument (optional): the number of renders (default 3). Prints one line per render:
 * {@code render N: R s render, W s write} (seconds, wall clock, the render's build included).
 */
public final class FirstRender {
    private FirstRender() {
    }

    public static void main(String[] args) {
        int renders = args.length > 0 ? Integer.parseInt(args[0]) : 3;
        for (int i = 1; i <= renders; ++i) {
            long t0 = System.nanoTime();
            Camera camera = readmeScene("bench/first-render-" + i);
            camera.renderImage();
            long t1 = System.nanoTime();
            camera.writeToImage();
            long t2 = System.nanoTime();
            System.out.printf(Locale.ROOT, "render %d: %.4f s render, %.4f s write%n", i, (t1 - t0) / 1e9,
                    (t2 - t1) / 1e9);
        }
    }

    /** The scene and camera of README.md's SpheresTest (src/it/starter), named {@code name}. */
    private static Camera readmeScene(String name) {
        Scene scene = new Scene("two spheres").setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        scene.geometries.add(
                new Sphere(new Point(0, 0, -50), 50).setEmission(new Color(0, 0, 100))
                        .setMaterial(new Material().setKd(0.4).setKs(0.3).setShininess(100).setKt(0.3)),
                new Sphere(new Point(0, 0, -50), 25).setEmission(new Color(100, 50, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(100)));
        scene.lights.add(new SpotLight(new Color(1000, 600, 0), new Point(-100, -100, 500), new Vector(-1, -1, -2))
                .setKl(0.0004).setKq(0.0000006));
        return Camera.getBuilder()
                .setLocation(new Point(0, 0, 1000))
                .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(150, 150).setVpDistance(1000)
                .setRayTracer(new RayTracerBasic(scene))
                .setImageWriter(new ImageWriter(name, 500, 500))
                .setAntiAliasing(AntiAliasing.ADAPTIVE)
                .setMultithreading(-2)
                .setSummary(false)
                .build();
    }
}
