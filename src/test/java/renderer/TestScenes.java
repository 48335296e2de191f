package renderer;

import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/** Scenes shared by the engine tests. */
final class TestScenes {
    private TestScenes() {
    }

    /** Where the engine tests' camera stands: on the z axis, looking along −z with +y up. */
    static final Point EYE = new Point(0, 0, 10);

    /**
     * Every effect that draws random numbers: a glossy reflective floor (spread 0.2), a mirror
     * ball, a frosted glass ball (spread 0.1) in front of a green ball, a triangle, and a point
     * and a spot light with radii (soft shadows) besides a directional light.
     */
    static Scene everyEffect() {
        Scene scene = new Scene("every-effect")
                .setBackground(new Color(10, 10, 30))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.05));
        scene.geometries.add(
                new Plane(new Point(0, -1, 0), new Vector(0, 1, 0)).setEmission(new Color(20, 20, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.3).setShininess(20).setKr(0.3)
                                .setReflectionSpread(0.2)),
                new Sphere(new Point(-1.5, 0, -1), 1).setEmission(new Color(0, 0, 30))
                        .setMaterial(new Material().setKd(0.1).setKs(0.5).setShininess(80).setKr(0.8)),
                new Sphere(new Point(1.5, 0, 0), 0.9).setEmission(new Color(40, 0, 0))
                        .setMaterial(new Material().setKd(0.2).setKs(0.5).setShininess(50).setKt(0.6)
                                .setTransmissionSpread(0.1)),
                new Sphere(new Point(1.5, 0, -2.5), 0.6).setEmission(new Color(0, 80, 0))
                        .setMaterial(new Material().setKd(0.5)),
                new Triangle(new Point(-4, -1, -4), new Point(4, -1, -4), new Point(0, 3, -4))
                        .setEmission(new Color(30, 20, 0)).setMaterial(new Material().setKd(0.3).setKr(0.2)));
        scene.lights.add(new PointLight(new Color(200, 200, 200), new Point(-2, 4, 4)).setKl(0.02).setRadius(0.6));
        scene.lights.add(new SpotLight(new Color(150, 150, 100), new Point(2, 3, 3), new Vector(-0.3, -1, -1))
                .setNarrowBeam(3).setRadius(0.3));
        scene.lights.add(new DirectionalLight(new Color(60, 60, 80), new Vector(0, -1, -0.5)));
        return scene;
    }

    /**
     * A camera on {@link #EYE} over a view plane of 0.1 scene units per pixel at distance 10: pixel
     * (x, y) sees ((x + 0.5 − nX/2)/10, (nY/2 − y − 0.5)/10) on the plane z = 0.
     */
    static Camera.Builder camera(Scene scene, ImageWriter image) {
        return Camera.getBuilder()
                .setLocation(EYE).setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(image.getNx() / 10.0, image.getNy() / 10.0).setVpDistance(10)
                .setImageWriter(image).setRayTracer(new RayTracerBasic(scene).setBeamSize(4).setShadowSamples(4))
                .setSummary(false);
    }
}
