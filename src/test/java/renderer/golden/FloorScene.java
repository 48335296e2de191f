package renderer.golden;

import static java.awt.Color.WHITE;

import geometries.Plane;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.LightSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * The golden suite's stage for lights and shadows: a sphere of radius 30 resting on the floor
 * y = 0 at the origin, seen from above and in front in a 150 × 150 image. The floor is matte
 * (kS 0), so its colour is emission + ambient + kD·|n·l|·I_L, computable by hand.
 */
final class FloorScene {
    static final Golden.View VIEW = new Golden.View(new Point(0, 80, 250), new Point(0, 20, 0), 150, 250);
    static final int SIZE = 150;
    static final Point SPHERE_CENTRE = new Point(0, 30, 0);
    static final double SPHERE_RADIUS = 30;
    /** Floor emission 20 + ambient 0.1 × 255 = 25.5 per channel: the floor in full shadow. */
    static final double FLOOR_BASE = 20 + 25.5;
    static final double FLOOR_KD = 0.5;

    private FloorScene() {
    }

    /** @return the floor and the sphere lit by {@code light} and a 10 % white ambient light */
    static Scene create(String name, LightSource light) {
        Scene scene = new Scene(name).setBackground(new Color(10, 12, 30))
                .setAmbientLight(new AmbientLight(new Color(WHITE), 0.1));
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(20, 20, 20))
                        .setMaterial(new Material().setKd(FLOOR_KD)),
                new Sphere(SPHERE_CENTRE, SPHERE_RADIUS).setEmission(new Color(70, 20, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60)));
        scene.lights.add(light);
        return scene;
    }

    /** Renders {@code scene} through {@link #VIEW} into target/test-run/images/golden/golden-&lt;what&gt;.png. */
    static ImageWriter render(String what, Scene scene) {
        ImageWriter image = Golden.image(what, SIZE, SIZE);
        VIEW.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene)).build()
                .renderImage().writeToImage();
        return image;
    }

    /** @return the pixel showing floor point (x, 0, z) */
    static int[] floor(double x, double z) {
        return VIEW.pixelOf(new Point(x, 0, z), SIZE);
    }
}
