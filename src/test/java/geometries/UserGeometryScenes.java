package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.RayTracerBasic;
import renderer.SimpleRayTracer;
import scene.Scene;

/**
 * The check behind every course year's "a user's own geometry renders correctly": a shape written
 * the way a student writes it (one year's hook, no bounding box) must look exactly like the
 * library's sphere with the same surface, in a scene where the BVH holds the other shapes and the
 * user's shape stays beside it, lit by a point light so that it also casts a shadow.
 */
final class UserGeometryScenes {
    /** The ball's centre and radius, the one every year's user shape is built with. */
    static final Point CENTER = Point.ZERO;
    static final double RADIUS = 10;
    /** Where the ball's shadow falls on the wall: the light at (60,0,50) through the centre to z = −50. */
    private static final Point SHADOW = new Point(-60, 0, -50);
    private static final Point EYE = new Point(0, 0, 100);
    private static final int N = 24;

    private UserGeometryScenes() {
    }

    private static Scene scene(Geometry ball) {
        Scene scene = new Scene("user geometry").setAmbientLight(new AmbientLight(new Color(30, 30, 30), 1))
                .setBackground(new Color(5, 5, 5));
        scene.geometries.add(new Plane(new Point(0, 0, -50), new Vector(0, 0, 1))
                .setEmission(new Color(10, 20, 30)).setMaterial(new Material().setKd(0.6)));
        for (int i = 0; i < 6; ++i) // bounded: these go into the BVH
            scene.geometries.add(new Sphere(new Point(-50 + 20 * i, 45, -20), 6).setEmission(new Color(0, 40, 0))
                    .setMaterial(new Material().setKd(0.4).setKs(0.3).setShininess(20)));
        if (ball != null)
            scene.geometries.add(ball.setEmission(new Color(60, 0, 0))
                    .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30).setKr(0.2)));
        scene.lights.add(new PointLight(new Color(400, 400, 400), new Point(60, 0, 50)).setKl(0.001));
        return scene;
    }

    /**
     * Asserts that {@code userBall}, a user's shape with the surface of a sphere at
     * {@link #CENTER} with {@link #RADIUS}, is traced like that library sphere, with the BVH on
     * and off, and that it casts its shadow.
     */
    static void assertRendersLikeTheLibrarySphere(Geometry userBall) {
        assertThat(userBall.getBoundingBox()).as("a user's shape has no bounding box").isNull();
        Scene user = scene(userBall);
        assertThat(Bvh.build(user.geometries).unboundedCount()).as("the wall and the user's ball beside the BVH").isEqualTo(2);
        Scene library = scene(new Sphere(CENTER, RADIUS));
        Scene without = scene(null);
        for (boolean bvh : new boolean[] { true, false }) {
            RayTracerBasic userTracer = new SimpleRayTracer(user).setBvh(bvh);
            RayTracerBasic libraryTracer = new SimpleRayTracer(library).setBvh(bvh);
            int onBall = 0;
            for (int i = 0; i < N; ++i)
                for (int j = 0; j < N; ++j) {
                    // Through a 120×120 window at z = 0: covers the ball, its shadow and the spheres.
                    Ray ray = new Ray(EYE, new Point(-60 + 120.0 * (j + 0.5) / N, 60 - 120.0 * (i + 0.5) / N, 0).subtract(EYE));
                    Color expected = libraryTracer.traceRay(ray);
                    assertThat(userTracer.traceRay(ray).distance(expected)).as("pixel (%d,%d), bvh %s", j, i, bvh)
                            .isLessThan(1e-9);
                    if (userBall.findIntersections(ray) != null) ++onBall;
                }
            assertThat(onBall).as("pixels on the user's ball").isGreaterThan(10);
            Ray toShadow = new Ray(EYE, SHADOW.subtract(EYE));
            assertThat(userTracer.traceRay(toShadow).getR()).as("the wall in the ball's shadow, bvh %s", bvh)
                    .isLessThan(new SimpleRayTracer(without).traceRay(toShadow).getR() - 10);
        }
    }
}
