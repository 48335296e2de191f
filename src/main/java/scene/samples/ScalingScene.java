package scene.samples;

import java.util.SplittableRandom;

import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import scene.Scene;

/**
 * The scaling benchmark (scene 4 of the performance plan): {@code n} random spheres and {@code n}
 * random triangles scattered in a cube, one directional light, no reflection or transparency,
 * so that the render cost is camera rays plus one shadow ray per hit and measures how the
 * intersection cost grows with the number of primitives.
 *
 * <p>The cube is cut into about {@code n} cells of side {@code s = SIDE / cbrt(n)} and every
 * primitive is about the size of a cell (spheres of radius 0.15–0.4·s, triangles spanning up to
 * 0.8·s), so the density of primitives per cell, and with it the number of cells a ray crosses
 * before it hits something, is the same for every {@code n}: only the search for the primitives
 * gets harder. (A ray crossing the whole cube meets more cells as {@code n} grows, so more of the
 * picture is covered: about 55% of the camera rays hit something for n = 10², 73% for 10³, 94% for
 * 10⁵.) With the BVH the time per ray should grow like log n, without it like n.
 *
 * <p>Deterministic: the same {@code (n, seed)} gives the same scene, drawn from a
 * {@link SplittableRandom}. Primitives share a small palette of emissions and materials so that
 * a million of them cost memory only for their geometry.
 */
public final class ScalingScene {
    /** The seed of {@link #create(int)}. */
    public static final long DEFAULT_SEED = 20240607L;
    /** The side of the cube the primitives fill, centred at the origin, in scene units. */
    public static final double SIDE = 200;
    /** The camera stands on the z axis in front of the cube's +z face. */
    public static final Point CAMERA_LOCATION = new Point(0, 0, 450);
    /** The view-plane side: the cube's front face (at distance 350) just fills the picture. */
    public static final double VP_SIZE = 200;
    /** The view-plane distance, in scene units. */
    public static final double VP_DISTANCE = 350;
    /** The largest {@code n} accepted (2·10⁷ primitives need several GB of heap). */
    public static final int MAX_N = 10_000_000;

    private static final int PALETTE = 8;

    private ScalingScene() {
    }

    /**
     * @param n spheres, and again triangles, to scatter (1..{@link #MAX_N})
     * @return {@code n} spheres and {@code n} triangles from {@link #DEFAULT_SEED}
     * @throws IllegalArgumentException when {@code n} is out of range
     */
    public static Scene create(int n) {
        return create(n, DEFAULT_SEED);
    }

    /**
     * @param n    spheres, and again triangles, to scatter (1..{@link #MAX_N})
     * @param seed the seed of the random placement
     * @return a new scene with {@code 2n} geometries (spheres first, then triangles) and one light
     * @throws IllegalArgumentException when {@code n} is out of range
     */
    public static Scene create(int n, long seed) {
        if (n < 1 || n > MAX_N)
            throw new IllegalArgumentException("scaling scene needs 1.." + MAX_N + " primitives of each kind, got " + n);
        SplittableRandom random = new SplittableRandom(seed);
        Color[] emission = new Color[PALETTE];
        Material[] material = new Material[PALETTE];
        for (int i = 0; i < PALETTE; ++i) {
            emission[i] = new Color(random.nextDouble(20, 120), random.nextDouble(20, 120), random.nextDouble(20, 120));
            material[i] = new Material().setKd(random.nextDouble(0.3, 0.7)).setKs(0.3).setShininess(20);
        }

        Scene scene = new Scene("scaling-" + n)
                .setBackground(new Color(10, 10, 20))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.1));
        double cell = SIDE / Math.cbrt(n);
        double half = SIDE / 2;
        for (int i = 0; i < n; ++i) {
            int k = random.nextInt(PALETTE);
            Point c = randomPoint(random, half);
            scene.geometries.add(new Sphere(c, cell * random.nextDouble(0.15, 0.4))
                    .setEmission(emission[k]).setMaterial(material[k]));
        }
        for (int i = 0; i < n; ++i) {
            int k = random.nextInt(PALETTE);
            Point c = randomPoint(random, half);
            Triangle t = randomTriangle(random, c, 0.4 * cell);
            scene.geometries.add(t.setEmission(emission[k]).setMaterial(material[k]));
        }
        scene.lights.add(new DirectionalLight(new Color(220, 220, 200), new Vector(-1, -2, -1.5)));
        return scene;
    }

    /**
     * @return a builder with the scaling view (location, direction, view plane) set; add an image
     *         writer and a ray tracer, then build
     */
    public static Camera.Builder camera() {
        return Camera.getBuilder()
                .setLocation(CAMERA_LOCATION)
                .setDirection(new Vector(0, 0, -1), Vector.AXIS_Y)
                .setVpSize(VP_SIZE, VP_SIZE)
                .setVpDistance(VP_DISTANCE);
    }

    private static Point randomPoint(SplittableRandom random, double half) {
        return new Point(random.nextDouble(-half, half), random.nextDouble(-half, half), random.nextDouble(-half, half));
    }

    /**
     * Three vertices within {@code reach} of {@code c} on each axis; redrawn in the (rare) case
     * they are nearly collinear, which {@link Triangle} rejects.
     */
    private static Triangle randomTriangle(SplittableRandom random, Point c, double reach) {
        while (true) {
            Point a = offset(random, c, reach), b = offset(random, c, reach), d = offset(random, c, reach);
            Vector ab = b.subtract(a), ad = d.subtract(a);
            // |ab × ad| = twice the area; demand a shape not thinner than 1/20 of its longest edge.
            double cx = ab.getY() * ad.getZ() - ab.getZ() * ad.getY();
            double cy = ab.getZ() * ad.getX() - ab.getX() * ad.getZ();
            double cz = ab.getX() * ad.getY() - ab.getY() * ad.getX();
            double area2 = Math.sqrt(cx * cx + cy * cy + cz * cz);
            double longest = Math.max(ab.lengthSquared(), Math.max(ad.lengthSquared(), d.distanceSquared(b)));
            if (area2 > 0.05 * longest) return new Triangle(a, b, d);
        }
    }

    private static Point offset(SplittableRandom random, Point c, double reach) {
        return new Point(c.getX() + random.nextDouble(-reach, reach), c.getY() + random.nextDouble(-reach, reach),
                c.getZ() + random.nextDouble(-reach, reach));
    }
}
