package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import geometries.Intersectable;
import geometries.Plane;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * The course's camera–geometry integration table: the camera at the origin (or at z = 0.5) looking
 * along −z, a 3x3 view plane of side 3 at distance 1, so the nine rays go through
 * (x, y, −1) with x, y ∈ {−1, 0, 1} (relative to the camera). Each case counts all intersection
 * points of the nine rays with one geometry; the counts are worked out geometrically in the
 * comments.
 */
class CameraIntegrationTest {
    private static Camera camera(Point location) {
        return Camera.getBuilder()
                .setRayTracer(new RayTracerBasic(new Scene("integration")))
                .setImageWriter(new ImageWriter("integration", 3, 3))
                .setLocation(location)
                .setDirection(new Vector(0, 0, -1), new Vector(0, -1, 0))
                .setVpSize(3, 3).setVpDistance(1)
                .setSummary(false)
                .build();
    }

    /** The number of intersection points of the nine pixel-centre rays with {@code geometry}. */
    private static int count(Camera camera, Intersectable geometry) {
        int total = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                List<Point> points = geometry.findIntersections(camera.constructRay(3, 3, j, i));
                if (points != null) total += points.size();
            }
        return total;
    }

    private static final Point ORIGIN = Point.ZERO;
    private static final Point HALF_FORWARD = new Point(0, 0, 0.5);

    @Nested
    @DisplayName("sphere")
    class Spheres {
        @Test
        @DisplayName("small sphere in front: only the centre ray, twice")
        void small() {
            // Radius 1 at z = −3: the side rays pass 3/√2 ≈ 2.1 from its centre, the corners √6 ≈ 2.4.
            assertThat(count(camera(ORIGIN), new Sphere(new Point(0, 0, -3), 1))).isEqualTo(2);
        }

        @Test
        @DisplayName("big sphere in front: all nine rays, twice each")
        void big() {
            // From z = 0.5, the corner ray (t, t, 0.5 − t) passes √6 ≈ 2.449 < 2.5 from (0,0,−2.5).
            assertThat(count(camera(HALF_FORWARD), new Sphere(new Point(0, 0, -2.5), 2.5))).isEqualTo(18);
        }

        @Test
        @DisplayName("medium sphere: centre and sides twice, corners miss")
        void medium() {
            // Corner ray min distance² = 150/36 ≈ 4.17 > 4; side ray min distance² = 3.125 < 4.
            assertThat(count(camera(HALF_FORWARD), new Sphere(new Point(0, 0, -2), 2))).isEqualTo(10);
        }

        @Test
        @DisplayName("camera inside the sphere: every ray leaves it once")
        void cameraInside() {
            assertThat(count(camera(ORIGIN), new Sphere(new Point(0, 0, -1), 4))).isEqualTo(9);
        }

        @Test
        @DisplayName("sphere behind the camera: nothing")
        void behind() {
            assertThat(count(camera(ORIGIN), new Sphere(new Point(0, 0, 1), 0.5))).isZero();
        }
    }

    @Nested
    @DisplayName("plane")
    class Planes {
        @Test
        @DisplayName("parallel to the view plane: every ray once")
        void parallel() {
            assertThat(count(camera(ORIGIN), new Plane(new Point(0, 0, -5), new Vector(0, 0, 1)))).isEqualTo(9);
        }

        @Test
        @DisplayName("slightly tilted: every ray once")
        void tilted() {
            // Normal (0,1,2): the plane y + 2z = −10 meets every ray s·(x, y, −1) at s = 10/(2 − y) > 0.
            assertThat(count(camera(ORIGIN), new Plane(new Point(0, 0, -5), new Vector(0, 1, 2)))).isEqualTo(9);
        }

        @Test
        @DisplayName("steep: the bottom row of rays runs parallel to it and misses")
        void steep() {
            // Normal (0,1,1): plane y + z = −5, met at s = 5/(1 − y). The bottom row (i = 2; up is
            // −y, so its rays go toward +y) has direction (x, 1, −1), parallel to it: 9 − 3 = 6.
            assertThat(count(camera(ORIGIN), new Plane(new Point(0, 0, -5), new Vector(0, 1, 1)))).isEqualTo(6);
        }
    }

    @Nested
    @DisplayName("triangle")
    class Triangles {
        @Test
        @DisplayName("small: only the centre ray")
        void small() {
            Triangle t = new Triangle(new Point(0, 1, -2), new Point(-1, -1, -2), new Point(1, -1, -2));
            assertThat(count(camera(ORIGIN), t)).isEqualTo(1);
        }

        @Test
        @DisplayName("tall: the centre ray and the one below it")
        void large() {
            // The pixel (1, 2) ray reaches z = −2 at (0, 2, −2), inside the tall triangle (apex y = 20);
            // the pixel (1, 0) ray reaches (0, −2, −2), below its base.
            Triangle t = new Triangle(new Point(0, 20, -2), new Point(-1, -1, -2), new Point(1, -1, -2));
            assertThat(count(camera(ORIGIN), t)).isEqualTo(2);
        }
    }
}
