package scene.samples;

import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Checks;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import scene.Scene;

/**
 * The benchmark scene of the second student report ("glossy", scene 2 of the performance plan):
 * eight spheres in front of a glossy back wall made of an 8×8 grid of square polygons, lit by a
 * directional light, two point lights and a spot light. Only the wall has a reflection spread,
 * so the glossy beam size ({@code RayTracerBasic.setBeamSize}) decides the cost of every camera
 * ray that sees the wall: most of the picture.
 *
 * <p>The report's render is 1000×1000 with beams of 1, 5, 10 and 50 rays, seen through
 * {@link #camera()}. Deterministic: nothing is random.
 */
public final class GlossyScene {
    /** The camera stands on the z axis, in front of the wall. */
    public static final Point CAMERA_LOCATION = new Point(0, 0, 1000);
    /** The camera looks straight down −z with +y up. */
    public static final Vector CAMERA_DIRECTION = new Vector(0, 0, -1);
    /** The side of the square view plane, in scene units. */
    public static final double VP_SIZE = 600;
    /** The view-plane distance, in scene units. */
    public static final double VP_DISTANCE = 1000;
    /**
     * The default reflection spread of the wall: a cone of half-angle atan(0.05) ≈ 2.9° around the
     * mirror direction, enough for the beam size to change the picture (and the cost).
     */
    public static final double DEFAULT_WALL_SPREAD = 0.05;

    /** The wall: z of its plane, half its side, and tiles per side (62.5-unit squares). */
    static final double WALL_Z = -250;
    static final double WALL_HALF_SIDE = 250;
    static final int WALL_TILES = 8;

    private GlossyScene() {
    }

    /** @return the glossy scene with the {@link #DEFAULT_WALL_SPREAD default wall spread} */
    public static Scene create() {
        return create(DEFAULT_WALL_SPREAD);
    }

    /**
     * @param wallSpread the reflection spread of the wall's material (0: a sharp mirror, so the
     *                   beam size has no effect), see {@link Material#reflectionSpread}
     * @return a new glossy scene: 8 spheres, 64 wall polygons, 4 lights
     * @throws IllegalArgumentException when the spread is negative or not finite
     */
    public static Scene create(double wallSpread) {
        Checks.requireNonNegative(wallSpread, "wall reflection spread");
        Scene scene = new Scene("glossy")
                .setBackground(Color.BLACK)
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.15));

        // The report's eight spheres: centre, radius, emission; kD, kS, shininess, kT, kR.
        scene.geometries.add(
                sphere(125, -36, 50, 20, new Color(108, 2, 139), 0.3, 0.2, 5, 0, 0),
                sphere(125, 100, 50, 20, new Color(231, 62, 1), 0.25, 0.3, 5, 0.22, 0),
                sphere(0, -130, -90, 25, new Color(0, 128, 128), 0.25, 0.3, 5, 0, 0.3),
                sphere(0, -130, 90, 25, new Color(0, 128, 85), 0.25, 0.3, 5, 0, 0.3),
                sphere(-63, 30, -200, 50, new Color(15, 5, 107), 0.2, 0.2, 5, 0, 0),
                sphere(48, 30, -200, 50, new Color(212, 175, 55), 0.3, 0.2, 5, 0, 0.1),
                sphere(-180, 90, -70, 20, new Color(255, 0, 0), 0.3, 0.2, 5, 0, 0),
                sphere(-180, -36, -70, 20, new Color(34, 80, 30), 0.3, 0.4, 5, 0.22, 0));

        // The wall: WALL_TILES² squares tiling [−250, 250]² at z = −250, sharing one material.
        Material wall = new Material().setKd(0.2).setKs(0.2).setShininess(5).setKr(0.5)
                .setReflectionSpread(wallSpread);
        double side = 2 * WALL_HALF_SIDE / WALL_TILES;
        for (int row = 0; row < WALL_TILES; ++row)
            for (int col = 0; col < WALL_TILES; ++col) {
                double x0 = -WALL_HALF_SIDE + col * side, y0 = -WALL_HALF_SIDE + row * side;
                // Counter-clockwise seen from the camera, so the normal faces it (+z).
                scene.geometries.add(new Polygon(new Point(x0, y0, WALL_Z), new Point(x0 + side, y0, WALL_Z),
                        new Point(x0 + side, y0 + side, WALL_Z), new Point(x0, y0 + side, WALL_Z))
                        .setMaterial(wall));
            }

        scene.lights.add(new DirectionalLight(new Color(240, 240, 240), new Vector(0, 0, -1)));
        scene.lights.add(new PointLight(new Color(170, 170, 170), new Point(-60, -60, -60)));
        scene.lights.add(new PointLight(new Color(170, 170, 170), new Point(60, 60, -60)));
        scene.lights.add(new SpotLight(new Color(250, 250, 250), new Point(0, 0, -30), new Vector(0, 0, 1)));
        return scene;
    }

    /**
     * @return a builder with the report's view (location, direction, view plane) set; add an
     *         image writer and a ray tracer, then build
     */
    public static Camera.Builder camera() {
        return Camera.getBuilder()
                .setLocation(CAMERA_LOCATION)
                .setDirection(CAMERA_DIRECTION, Vector.AXIS_Y)
                .setVpSize(VP_SIZE, VP_SIZE)
                .setVpDistance(VP_DISTANCE);
    }

    private static Sphere sphere(double x, double y, double z, double radius, Color emission,
                                 double kd, double ks, int shininess, double kt, double kr) {
        return (Sphere) new Sphere(new Point(x, y, z), radius).setEmission(emission)
                .setMaterial(new Material().setKd(kd).setKs(ks).setShininess(shininess).setKt(kt).setKr(kr));
    }
}
