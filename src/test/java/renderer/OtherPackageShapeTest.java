package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;

import org.assertj.core.data.Offset;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Geometry;
import geometries.Hit;
import geometries.LeanQueries;
import geometries.Plane;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * A user's shapes written outside package {@code geometries}, as a student's own package would
 * hold them: the engine's queries are package-private there, so such a class cannot override
 * them and inherits the defaults, which must answer through its course hook exactly as the
 * library's shape answers (the engine's closest hit and any-hit walk, and a render with the BVH on
 * and off). The tests in package {@code geometries} cannot show this: a class of that package
 * could override the package-private queries.
 */
class OtherPackageShapeTest {
    private static final Point CENTER = new Point(1, -2, -30);
    private static final double RADIUS = 8;
    private static final Point EYE = new Point(0, 0, 20);
    private static final int N = 20;

    /** A ball written the 2025–26 way: the one hook, answered by a library sphere's list query. */
    private static Geometry ball() {
        return new UserShape(new Sphere(CENTER, RADIUS), p -> p.subtract(CENTER).normalize());
    }

    /** A subclass of the library's sphere that overrides nothing. */
    private static final class PlainSphere extends Sphere {
        PlainSphere() {
            super(CENTER, RADIUS);
        }
    }

    private static List<Ray> rays() {
        List<Ray> rays = new ArrayList<>();
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j)
                rays.add(new Ray(EYE, new Point(-6 + 12.0 * (j + 0.5) / N, 6 - 12.0 * (i + 0.5) / N, 0).subtract(EYE)));
        return rays;
    }

    private static Scene scene(Geometry ball) {
        Scene scene = new Scene("a user's shape").setAmbientLight(new AmbientLight(new Color(30, 30, 30), 1))
                .setBackground(new Color(5, 5, 5));
        scene.geometries.add(new Plane(new Point(0, 0, -60), new Vector(0, 0, 1)).setEmission(new Color(10, 20, 30))
                .setMaterial(new Material().setKd(0.6)));
        scene.geometries.add(new Sphere(new Point(10, 8, -40), 3).setEmission(new Color(0, 40, 0)));
        scene.geometries.add(ball.setEmission(new Color(60, 0, 0))
                .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(30).setKr(0.2)));
        scene.lights.add(new PointLight(new Color(400, 400, 400), new Point(30, 10, 10)).setKl(0.001));
        return scene;
    }

    @Test
    @DisplayName("the engine's queries of a user's shape answer through its hook, as the library's sphere answers")
    void leanQueriesAskTheHook() {
        Geometry ball = ball();
        Sphere sphere = new Sphere(CENTER, RADIUS);
        assertThat(LeanQueries.boundingBox(ball)).as("a user's shape has no box: it stays beside the tree").isNull();
        assertThat(LeanQueries.isLibraryShape(ball)).isFalse();
        int hits = 0;
        for (Ray ray : rays()) {
            Hit mine = new Hit(), theirs = new Hit();
            boolean found = LeanQueries.closestHit(ball, ray, mine.reset(Double.POSITIVE_INFINITY));
            assertThat(found).as("%s", ray).isEqualTo(LeanQueries.closestHit(sphere, ray, theirs.reset(Double.POSITIVE_INFINITY)));
            if (!found) continue;
            ++hits;
            assertThat(mine.getGeometry()).isSameAs(ball);
            assertThat(mine.getT()).as("%s", ray).isCloseTo(theirs.getT(), Offset.offset(1e-9));
            int[] visits = new int[2];
            LeanQueries.visitHits(ball, ray, Double.POSITIVE_INFINITY, (g, t) -> ++visits[0] > 0);
            LeanQueries.visitHits(sphere, ray, Double.POSITIVE_INFINITY, (g, t) -> ++visits[1] > 0);
            assertThat(visits[0]).as("hits of the any-hit walk along %s", ray).isEqualTo(visits[1]);
        }
        assertThat(hits).as("rays on the ball (the test must not be vacuous)").isGreaterThan(N * N / 10);
    }

    @ParameterizedTest(name = "BVH {0}")
    @ValueSource(booleans = { true, false })
    @DisplayName("a user's shape, and a subclass of a library shape, render as the library's sphere")
    void rendersAsTheLibrarySphere(boolean bvh) {
        RayTracerBasic library = new SimpleRayTracer(scene(new Sphere(CENTER, RADIUS))).setBvh(bvh);
        RayTracerBasic user = new SimpleRayTracer(scene(ball())).setBvh(bvh);
        RayTracerBasic subclass = new SimpleRayTracer(scene(new PlainSphere())).setBvh(bvh);
        int onBall = 0;
        for (Ray ray : rays()) {
            Color expected = library.traceRay(ray);
            assertThat(user.traceRay(ray).distance(expected)).as("%s", ray).isLessThan(1e-9);
            assertThat(subclass.traceRay(ray).distance(expected)).as("%s", ray).isLessThan(1e-9);
            if (expected.getR() > 30) ++onBall;
        }
        assertThat(onBall).as("rays whose colour the red ball gives").isGreaterThan(N * N / 10);
    }
}
