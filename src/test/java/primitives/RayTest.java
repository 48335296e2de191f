package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Intersectable.GeoPoint;
import geometries.Sphere;

class RayTest {
    private final Point head = new Point(1, 2, 3);

    @Nested
    @DisplayName("construction")
    class Construction {
        @Test
        void directionIsNormalized() {
            Ray ray = new Ray(head, new Vector(0, 3, 4));
            assertThat(ray.getDirection()).isEqualTo(new Vector(0, 0.6, 0.8));
            assertThat(ray.getDirection().length()).isCloseTo(1, within(1e-15));
            assertThat(ray.getHead()).isEqualTo(head);
        }

        @Test
        @DisplayName("a huge direction vector (its squared length overflows) still gives a unit direction")
        void hugeDirectionIsNormalized() {
            Ray ray = new Ray(Point.ZERO, new Vector(1e155, 1e155, 0));
            assertThat(ray.getDirection().length()).isCloseTo(1, within(1e-15));
            assertThat(ray.getDirection()).isEqualTo(new Vector(1, 1, 0).normalize());
        }
    }

    @Nested
    @DisplayName("the DELTA constructor moves the head off a surface")
    class DeltaConstructor {
        private final Vector normal = new Vector(0, 0, 1);

        @Test
        @DisplayName("direction on the normal's side: head moved by +DELTA along the normal")
        void leavingOnTheNormalSide() {
            Ray ray = new Ray(head, new Vector(1, 0, 1), normal);
            assertThat(ray.getHead()).isEqualTo(new Point(1, 2, 3 + Ray.DELTA));
            assertThat(ray.getDirection()).isEqualTo(new Vector(1, 0, 1).normalize());
        }

        @Test
        @DisplayName("direction against the normal: head moved by -DELTA along the normal")
        void enteringAgainstTheNormal() {
            Ray ray = new Ray(head, new Vector(1, 0, -1), normal);
            assertThat(ray.getHead()).isEqualTo(new Point(1, 2, 3 - Ray.DELTA));
        }

        @Test
        @DisplayName("the side is decided by the direction, whatever way the normal points")
        void flippedNormal() {
            Ray ray = new Ray(head, new Vector(1, 0, 1), normal.scale(-1));
            assertThat(ray.getHead()).isEqualTo(new Point(1, 2, 3 + Ray.DELTA));
        }

        @Test
        @DisplayName("a direction tangent to the surface keeps the head")
        void tangentKeepsHead() {
            Ray ray = new Ray(head, new Vector(1, 1, 0), normal);
            assertThat(ray.getHead()).isEqualTo(head);
        }

        @ParameterizedTest(name = "n·d = {0}")
        @ValueSource(doubles = { 0x1p-40, -0x1p-40, 0x1.0000000000001p-40, 0x1.fffffffffffffp-41, -0x1.fffffffffffffp-41,
                0.0, -0.0, 1e-300, -1e-300, 0.3, -0.3, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY })
        @DisplayName("the offset is alignZero's: 0 within the zero tolerance, ±DELTA beyond it, −DELTA for NaN")
        void offsetAsAlignZeroDecides(double dot) {
            assertThat(Ray.headOffset(1, 0, 0, dot, 0, 0)).isEqualTo(withAlignZero(dot));
        }

        @Test
        @DisplayName("the offset is alignZero's on random products near the tolerance")
        void offsetOnRandomProducts() {
            Random rnd = new Random(17);
            for (int i = 0; i < 100_000; ++i) {
                double dot = Math.scalb(rnd.nextDouble() * 4 - 2, -40 + rnd.nextInt(3) - 1);
                assertThat(Ray.headOffset(1, 0, 0, dot, 0, 0)).as("n·d = %s", dot).isEqualTo(withAlignZero(dot));
            }
        }

        /** The rule as it was written with {@link Util#alignZero}. */
        private static double withAlignZero(double dot) {
            double nd = Util.alignZero(dot);
            return nd == 0 ? 0 : nd > 0 ? Ray.DELTA : -Ray.DELTA;
        }
    }

    @Nested
    @DisplayName("getPoint")
    class GetPoint {
        private final Ray ray = new Ray(head, new Vector(0, 0, 2));

        @Test
        void zeroIsTheHead() {
            assertThat(ray.getPoint(0)).isEqualTo(head);
        }

        @Test
        void positiveAndNegativeDistances() {
            assertThat(ray.getPoint(5)).isEqualTo(new Point(1, 2, 8));
            assertThat(ray.getPoint(-1)).isEqualTo(new Point(1, 2, 2));
        }

        @Test
        @DisplayName("the distance is along the unit direction, whatever length the direction had")
        void distanceIsMetric() {
            assertThat(ray.getPoint(3).distance(head)).isEqualTo(3);
        }
    }

    @Nested
    @DisplayName("findClosestPoint / findClosestGeoPoint")
    class Closest {
        private final Ray ray = new Ray(Point.ZERO, new Vector(1, 0, 0));
        private final Point near = new Point(1, 0, 0);
        private final Point mid = new Point(2, 1, 0);
        private final Point far = new Point(-5, 0, 0); // behind the head, yet a distance is a distance

        static Stream<Arguments> positions() {
            return Stream.of(Arguments.of("first", 0), Arguments.of("middle", 1), Arguments.of("last", 2));
        }

        private List<Point> withClosestAt(int index) {
            List<Point> points = new ArrayList<>(List.of(mid, far));
            points.add(index, near);
            return points;
        }

        @ParameterizedTest(name = "closest point is {0} in the list")
        @MethodSource("primitives.RayTest$Closest#positions")
        void closestPointAnywhereInTheList(String where, int index) {
            assertThat(ray.findClosestPoint(withClosestAt(index))).isSameAs(near);
        }

        @ParameterizedTest(name = "closest geo point is {0} in the list")
        @MethodSource("primitives.RayTest$Closest#positions")
        void closestGeoPointAnywhereInTheList(String where, int index) {
            Sphere s = new Sphere(Point.ZERO, 1);
            List<GeoPoint> geoPoints = new ArrayList<>();
            for (Point p : withClosestAt(index)) geoPoints.add(new GeoPoint(s, p));
            assertThat(ray.findClosestGeoPoint(geoPoints)).isSameAs(geoPoints.get(index));
        }

        @Test
        void emptyOrNullListGivesNull() {
            assertThat(ray.findClosestPoint(List.of())).isNull();
            assertThat(ray.findClosestPoint(null)).isNull();
            assertThat(ray.findClosestGeoPoint(List.of())).isNull();
            assertThat(ray.findClosestGeoPoint(null)).isNull();
        }

        @Test
        void singlePointIsTheClosest() {
            assertThat(ray.findClosestPoint(List.of(far))).isSameAs(far);
        }
    }
}
