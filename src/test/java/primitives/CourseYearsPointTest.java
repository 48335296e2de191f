package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/**
 * Point's protected coordinate field, read the way cohorts' tests in package {@code primitives}
 * read it: {@code xyz} (2023–24, 2024–25) and {@code _xyz} (2025–26). Here rather than in the
 * per-year classes of package {@code geometries}, from where a protected field of Point is out of reach.
 */
class CourseYearsPointTest {
    @Nested
    @DisplayName("xyz (5784, 5785)")
    class Xyz {
        @Test
        @DisplayName("the point's coordinates as a Double3, after each operation")
        void coordinates() {
            Point p = new Point(1, 2, 3);
            assertEquals(new Double3(1, 2, 3), p.xyz);
            assertEquals(new Double3(2, 4, 6), p.add(new Vector(1, 2, 3)).xyz);
            assertEquals(new Double3(-1, -1, -1), new Point(1, 2, 3).subtract(new Point(2, 3, 4)).xyz);
            assertThat(p.xyz.d1).isEqualTo(1);
            assertThat(p.xyz.d3).isEqualTo(3);
            assertEquals(new Double3(0, 0, 0), Point.ZERO.xyz);
            assertEquals(new Double3(0, 0, 1), Vector.AXIS_Z.xyz);
            assertEquals(new Double3(4, 5, 6), new Point(new Double3(4, 5, 6)).xyz);
        }
    }

    @Nested
    @DisplayName("_xyz (5786)")
    class UnderscoreXyz {
        @Test
        @DisplayName("the same object as xyz")
        void sameObject() {
            Point p = new Point(-1.5, 0, 7);
            assertEquals(new Double3(-1.5, 0, 7), p._xyz);
            assertThat(p._xyz).isSameAs(p.xyz);
            Vector v = new Vector(3, 4, 0).normalize();
            assertEquals(new Double3(0.6, 0.8, 0), v._xyz);
            assertThat(v._xyz._d2()).isEqualTo(0.8);
        }
    }
}
