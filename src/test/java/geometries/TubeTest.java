package geometries;

import static geometries.Hits.assertHits;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** The tube of radius 1 around the z axis (infinite both ways: the axis head is just a point on it). */
class TubeTest implements GeometryContract {
    private final Tube tube = new Tube(1, new Ray(Point.ZERO, new Vector(0, 0, 1)));
    private static final Vector X = new Vector(1, 0, 0);

    @Override
    public Intersectable subject() {
        return tube;
    }

    @Override
    public Ray knownHit() {
        return new Ray(new Point(-2, 0, 1), X);
    }

    @Override
    public Ray knownMiss() {
        return new Ray(new Point(-2, 2, 1), X);
    }

    @Override
    public Point focus() {
        return new Point(0, 0, 0.5);
    }

    @Override
    public double extent() {
        return 1.5;
    }

    @Override
    public boolean bounded() {
        return false;
    }

    @Nested
    @DisplayName("construction and normal")
    class Construction {
        @ParameterizedTest(name = "radius {0} is rejected")
        @ValueSource(doubles = { 0, -2, Double.NaN })
        void nonPositiveRadiusIsRejected(double r) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Tube(r, new Ray(Point.ZERO, X)))
                    .withMessageContaining("radius").withMessageContaining(String.valueOf(r));
        }

        @Test
        void normalIsRadialAndUnit() {
            assertThat(tube.getNormal(new Point(1, 0, 5))).isEqualTo(X);
            assertThat(tube.getNormal(new Point(0, -1, -3))).isEqualTo(new Vector(0, -1, 0));
            assertThat(tube.getNormal(new Point(0.6, 0.8, 2))).isEqualTo(new Vector(0.6, 0.8, 0));
        }

        @Test
        @DisplayName("normal at a point level with the axis head (the projection is the head itself)")
        void normalLevelWithTheHead() {
            assertThat(tube.getNormal(new Point(0, 1, 0))).isEqualTo(new Vector(0, 1, 0));
        }

        @Test
        void normalOnATiltedTube() {
            Tube tilted = new Tube(Math.sqrt(2), new Ray(new Point(1, 1, 1), new Vector(1, 1, 0)));
            // (2,0,1) is √2 from the axis line: its foot is (1,1,1), so the normal is (1,-1,0)/√2.
            assertThat(tilted.getNormal(new Point(2, 0, 1))).isEqualTo(new Vector(1, -1, 0).normalize());
        }

        @Test
        void isUnbounded() {
            assertThat(tube.getBoundingBox()).isNull();
        }
    }

    @Nested
    @DisplayName("rays crossing the shell")
    class Crossing {
        @Test
        @DisplayName("orthogonal to the axis, through it: two points")
        void orthogonalThroughAxis() {
            assertHits(tube, new Ray(new Point(-2, 0, 1), X), new Point(-1, 0, 1), new Point(1, 0, 1));
        }

        @Test
        @DisplayName("orthogonal to the axis, off it: two points")
        void orthogonalOffAxis() {
            assertHits(tube, new Ray(new Point(-2, 0.6, 0), X), new Point(-0.8, 0.6, 0), new Point(0.8, 0.6, 0));
        }

        @Test
        @DisplayName("oblique: two points at different heights")
        void oblique() {
            assertHits(tube, new Ray(new Point(-2, 0, 0), new Vector(1, 0, 1)), new Point(-1, 0, 1), new Point(1, 0, 3));
        }

        @Test
        @DisplayName("on the far side of the axis head (the tube is infinite both ways): two points")
        void belowTheHead() {
            assertHits(tube, new Ray(new Point(-2, 0, -10), X), new Point(-1, 0, -10), new Point(1, 0, -10));
        }

        @Test
        @DisplayName("starts inside: one point")
        void startsInside() {
            assertHits(tube, new Ray(new Point(0.5, 0, 0), new Vector(1, 0, 1)), new Point(1, 0, 0.5));
        }

        @Test
        @DisplayName("starts on the axis: one point")
        void startsOnTheAxis() {
            assertHits(tube, new Ray(new Point(0, 0, 7), new Vector(0, -1, 0)), new Point(0, -1, 7));
        }

        @Test
        @DisplayName("starts on the shell going in: the opposite point only")
        void startsOnShellGoingIn() {
            assertHits(tube, new Ray(new Point(1, 0, 0), X.scale(-1)), new Point(-1, 0, 0));
        }

        @Test
        @DisplayName("starts on the shell going out: none")
        void startsOnShellGoingOut() {
            assertHits(tube, new Ray(new Point(1, 0, 0), X));
        }

        @Test
        @DisplayName("starts after the shell: none")
        void startsAfter() {
            assertHits(tube, new Ray(new Point(2, 0, 0), X));
        }
    }

    @Nested
    @DisplayName("rays along the axis direction: never a hit")
    class AlongTheAxis {
        @ParameterizedTest(name = "at distance {0} from the axis")
        @ValueSource(doubles = { 0, 0.5, 1, 2 })
        void parallelToTheAxis(double offset) {
            assertHits(tube, new Ray(new Point(offset, 0, -5), new Vector(0, 0, 1)));
            assertHits(tube, new Ray(new Point(offset, 0, 5), new Vector(0, 0, -1)));
        }
    }

    @Nested
    @DisplayName("tangent rays: never a hit")
    class Tangent {
        @ParameterizedTest(name = "starting at x = {0}")
        @ValueSource(doubles = { -2, 0, 2 })
        void tangentToTheShell(double x) {
            assertHits(tube, new Ray(new Point(x, 1, 0), X));
        }

        @Test
        void obliqueTangent() {
            assertHits(tube, new Ray(new Point(-2, 1, 0), new Vector(1, 0, 1)));
        }
    }
}
