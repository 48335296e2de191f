package geometries;

import static geometries.Hits.assertHits;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The sphere of the course tests: centre (1,0,0), radius 1. The chords are chosen so that the
 * hit points are exact by hand: a line at height 0.6 cuts the circle at x = 1 ± 0.8.
 */
class SphereTest implements GeometryContract {
    private final Sphere sphere = new Sphere(new Point(1, 0, 0), 1);
    private static final Vector X = new Vector(1, 0, 0);

    @Override
    public Intersectable subject() {
        return sphere;
    }

    @Override
    public Ray knownHit() {
        return new Ray(new Point(-1, 0.6, 0), X);
    }

    @Override
    public Ray knownMiss() {
        return new Ray(new Point(-1, 0, 0), new Vector(1, 1, 0));
    }

    @Override
    public Point focus() {
        return new Point(1, 0, 0);
    }

    @Override
    public double extent() {
        return 1.2;
    }

    @Nested
    @DisplayName("construction")
    class Construction {
        @ParameterizedTest(name = "radius {0} is rejected")
        @ValueSource(doubles = { 0, -1, Double.NaN, Double.POSITIVE_INFINITY })
        void nonPositiveRadiusIsRejected(double r) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Sphere(Point.ZERO, r))
                    .withMessageContaining("radius").withMessageContaining(String.valueOf(r));
        }

        @Test
        void boundingBoxIsTheCircumscribedCube() {
            BoundingBox b = new Sphere(new Point(1, -2, 3), 2).getBoundingBox();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(-1, -4, 1, 3, 0, 5);
        }
    }

    @Nested
    @DisplayName("normal")
    class Normal {
        @Test
        void pointsOutwardWithUnitLength() {
            assertThat(sphere.getNormal(new Point(2, 0, 0))).isEqualTo(X);
            Vector n = sphere.getNormal(new Point(1, 0.6, 0.8));
            assertThat(n).isEqualTo(new Vector(0, 0.6, 0.8));
            assertThat(n.length()).isCloseTo(1, within(1e-15));
            assertThat(new Sphere(Point.ZERO, 5).getNormal(new Point(0, -5, 0))).isEqualTo(new Vector(0, -1, 0));
        }
    }

    @Nested
    @DisplayName("the ray's line crosses the sphere")
    class Crossing {
        @Test
        @DisplayName("starts before: two points")
        void startsBefore() {
            assertHits(sphere, new Ray(new Point(-1, 0.6, 0), X), new Point(0.2, 0.6, 0), new Point(1.8, 0.6, 0));
        }

        @Test
        @DisplayName("starts inside: one point")
        void startsInside() {
            assertHits(sphere, new Ray(new Point(0.5, 0.6, 0), X), new Point(1.8, 0.6, 0));
        }

        @Test
        @DisplayName("starts after: none")
        void startsAfter() {
            assertHits(sphere, new Ray(new Point(2, 0.6, 0), X));
        }

        @Test
        @DisplayName("starts on the surface going in: the far point only")
        void startsOnSurfaceGoingIn() {
            assertHits(sphere, new Ray(new Point(0.2, 0.6, 0), X), new Point(1.8, 0.6, 0));
        }

        @Test
        @DisplayName("starts on the surface going out: none")
        void startsOnSurfaceGoingOut() {
            assertHits(sphere, new Ray(new Point(1.8, 0.6, 0), X));
        }

        @Test
        @DisplayName("the line misses the sphere: none")
        void lineMisses() {
            assertHits(sphere, new Ray(new Point(-1, 0, 0), new Vector(1, 1, 0)));
        }
    }

    @Nested
    @DisplayName("the ray's line goes through the centre")
    class ThroughCentre {
        @Test
        @DisplayName("starts before: two points")
        void startsBefore() {
            assertHits(sphere, new Ray(new Point(-1, 0, 0), X), new Point(0, 0, 0), new Point(2, 0, 0));
        }

        @Test
        @DisplayName("starts at the centre: one point")
        void startsAtCentre() {
            assertHits(sphere, new Ray(new Point(1, 0, 0), new Vector(0, 1, 0)), new Point(1, 1, 0));
        }

        @Test
        @DisplayName("starts inside, between surface and centre, going away from the centre: one point")
        void startsInsideGoingOut() {
            assertHits(sphere, new Ray(new Point(1.5, 0, 0), X), new Point(2, 0, 0));
        }

        @Test
        @DisplayName("starts on the surface going in: the opposite point only")
        void startsOnSurfaceGoingIn() {
            assertHits(sphere, new Ray(new Point(0, 0, 0), X), new Point(2, 0, 0));
        }

        @Test
        @DisplayName("starts on the surface going out: none")
        void startsOnSurfaceGoingOut() {
            assertHits(sphere, new Ray(new Point(2, 0, 0), X));
        }

        @Test
        @DisplayName("starts after, going away: none")
        void startsAfter() {
            assertHits(sphere, new Ray(new Point(3, 0, 0), X));
        }

        @Test
        @DisplayName("starts before, pointing away: none")
        void pointsAway() {
            assertHits(sphere, new Ray(new Point(-1, 0, 0), X.scale(-1)));
        }
    }

    @Nested
    @DisplayName("the ray's line is tangent to the sphere: never a hit")
    class Tangent {
        @ParameterizedTest(name = "starting at x = {0}")
        @ValueSource(doubles = { 0, 1, 2 })
        void tangentLineGivesNoHit(double x) {
            // The line y = 1 touches the sphere at (1,1,0): before, at and after the touching point.
            assertHits(sphere, new Ray(new Point(x, 1, 0), X));
        }
    }

    @Test
    @DisplayName("the line is outside and orthogonal to the head-centre line: none")
    void orthogonalOutside() {
        assertHits(sphere, new Ray(new Point(1, 0, 2), new Vector(0, 1, 0)));
    }

    @Test
    @DisplayName("a large far sphere keeps the precision (geometric root finding)")
    void farSphere() {
        Sphere far = new Sphere(new Point(0, 0, -1e6), 10);
        assertHits(far, new Ray(Point.ZERO, new Vector(0, 0, -1)), new Point(0, 0, -1e6 + 10), new Point(0, 0, -1e6 - 10));
    }
}
