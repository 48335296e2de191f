package scene.samples;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.SplittableRandom;

import geometries.Sphere;
import geometries.TriangleMesh;
import lighting.PointLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import scene.Scene;
import scene.io.ObjReader;

/**
 * The course's benchmark scene (scene 1 of the performance plan): the Utah teapot, 992 triangles
 * read from the bundled {@code /models/teapot.obj}, with the course's material, light and camera
 * (listed in the OBJ header), plus {@link #SPHERES} small spheres rising from the spout like
 * steam: inside a cone with its apex at the spout's tip {@link #CONE_APEX}, opening upward (+y)
 * with radius {@link #CONE_SLOPE} per unit of height, over heights 0–{@link #CONE_HEIGHT}.
 *
 * <p>Sphere radii are uniform in 0.1–1; their materials have kD uniform in 0–0.1 per channel,
 * kS 0.2, kR 0.1, kT 0 (the plan's figures); the plan leaves shininess and emission open: the
 * spheres get shininess 30 and emissions uniform in 0–120 per channel, so that the steam shows.
 * The course render is 1000×1000 with one ray per pixel, seen through {@link #camera()}.
 * Deterministic: the same seed gives the same scene, drawn from a {@link SplittableRandom}.
 */
public final class TeapotScene {
    /** The seed of {@link #create()}. */
    public static final long DEFAULT_SEED = 992L;
    /** How many steam spheres {@link #create(long)} adds. */
    public static final int SPHERES = 400;
    /** The apex of the steam cone: the tip of the teapot's spout. */
    public static final Point CONE_APEX = new Point(90, 30, 0.2);
    /** The steam cone's radius per unit of height above the apex. */
    public static final double CONE_SLOPE = 0.3;
    /** The steam cone's height above the apex, in scene units. */
    public static final double CONE_HEIGHT = 70;
    /** The bundled mesh (a class-path resource). */
    public static final String MODEL = "/models/teapot.obj";
    /** The course camera stands on −z looking at the origin, +y up. */
    public static final Point CAMERA_LOCATION = new Point(0, 0, -1000);
    /** The side of the course's square view plane. */
    public static final double VP_SIZE = 200;
    /** The course's view-plane distance. */
    public static final double VP_DISTANCE = 1000;

    private TeapotScene() {
    }

    /** @return the teapot with the steam of {@link #DEFAULT_SEED} */
    public static Scene create() {
        return create(DEFAULT_SEED);
    }

    /**
     * @param seed the seed of the steam spheres' placement and materials
     * @return a new scene: the teapot mesh, {@link #SPHERES} spheres, and the course's point light
     */
    public static Scene create(long seed) {
        Scene scene = new Scene("teapot");
        TriangleMesh teapot = readModel();
        teapot.setEmission(new Color(200, 0, 0))
                .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60));
        scene.geometries.add(teapot);

        SplittableRandom random = new SplittableRandom(seed);
        for (int i = 0; i < SPHERES; ++i) {
            double h = random.nextDouble(CONE_HEIGHT);
            // sqrt makes the points uniform over the cone's cross-section disk.
            double r = CONE_SLOPE * h * Math.sqrt(random.nextDouble());
            double a = random.nextDouble(2 * Math.PI);
            Point center = new Point(CONE_APEX.getX() + r * Math.cos(a), CONE_APEX.getY() + h,
                    CONE_APEX.getZ() + r * Math.sin(a));
            double radius = random.nextDouble(0.1, 1);
            Material material = new Material()
                    .setKd(new Double3(random.nextDouble(0.1), random.nextDouble(0.1), random.nextDouble(0.1)))
                    .setKs(0.2).setKr(0.1).setShininess(30);
            Color emission = new Color(random.nextDouble(120), random.nextDouble(120), random.nextDouble(120));
            scene.geometries.add(new Sphere(center, radius).setEmission(emission).setMaterial(material));
        }

        scene.lights.add(new PointLight(new Color(500, 500, 500), new Point(100, 0, -100)).setKq(0.000001));
        return scene;
    }

    /** The bundled model: failing to read it is a packaging error, not something a caller handles. */
    private static TriangleMesh readModel() {
        try {
            return ObjReader.readResource(MODEL);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the bundled teapot model " + MODEL + ": " + e.getMessage(), e);
        }
    }

    /**
     * @return a builder with the course's view (location, direction, view plane) set; add an
     *         image writer and a ray tracer, then build
     */
    public static Camera.Builder camera() {
        return Camera.getBuilder()
                .setLocation(CAMERA_LOCATION)
                .setDirection(Point.ZERO, Vector.AXIS_Y)
                .setVpSize(VP_SIZE, VP_SIZE)
                .setVpDistance(VP_DISTANCE);
    }
}
