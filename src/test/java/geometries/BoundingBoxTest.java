package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The box of most tests is the cube [1,3]³. Rays are given as raw origin and direction
 * components, as the BVH passes them, so that signed zeros can be spelt out.
 */
class BoundingBoxTest {
    private static final String[] AXIS = { "x", "y", "z" };
    private final BoundingBox cube = new BoundingBox(1, 1, 1, 3, 3, 3);

    /** The slab test for the ray o + t·d, t in [0, tMax]. */
    private static boolean hits(BoundingBox b, double[] o, double[] d, double tMax) {
        return b.intersects(o[0], o[1], o[2], 1 / d[0], 1 / d[1], 1 / d[2], tMax);
    }

    private static boolean hits(BoundingBox b, double[] o, double[] d) {
        return hits(b, o, d, Double.POSITIVE_INFINITY);
    }

    /** A vector with {@code value} on axis {@code axis} and {@code rest} on the other two. */
    private static double[] on(int axis, double value, double rest) {
        double[] v = { rest, rest, rest };
        v[axis] = value;
        return v;
    }

    private static double[] box(BoundingBox b) {
        return new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() };
    }

    static IntStream axes() {
        return IntStream.range(0, 3);
    }

    @Nested
    @DisplayName("construction")
    class Construction {
        @ParameterizedTest(name = "min > max on {0} is rejected")
        @ValueSource(ints = { 0, 1, 2 })
        void invertedAxisIsRejected(int axis) {
            double[] min = { 0, 0, 0 }, max = { 1, 1, 1 };
            min[axis] = 2;
            assertThatIllegalArgumentException().isThrownBy(() -> new BoundingBox(min[0], min[1], min[2], max[0], max[1], max[2]))
                    .withMessageContaining("min <= max").withMessageContaining("2.0");
        }

        @Test
        void nanIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new BoundingBox(Double.NaN, 0, 0, 1, 1, 1));
        }

        @Test
        @DisplayName("a flat box (min = max on an axis) is valid: an axis-aligned triangle has one")
        void flatBoxIsValid() {
            assertThat(box(new BoundingBox(0, 0, 2, 1, 1, 2))).containsExactly(0, 0, 2, 1, 1, 2);
        }
    }

    @Nested
    @DisplayName("padded: every side moved out by 1e-9 · (1 + the largest coordinate magnitude)")
    class Padded {
        @Test
        @DisplayName("near the origin the padding is 1e-9 · (1 + 3)")
        void nearTheOrigin() {
            double e = 4e-9;
            assertThat(box(cube.padded())).containsExactly(new double[] { 1 - e, 1 - e, 1 - e, 3 + e, 3 + e, 3 + e },
                    within(1e-15));
        }

        @Test
        @DisplayName("the padding grows with the coordinates (relative to the largest on any axis) and thickens a flat box")
        void farAndFlat() {
            BoundingBox flat = new BoundingBox(-2e6, 5, 7, 10, 6, 7).padded();
            double e = 1e-9 * (1 + 2e6);
            assertThat(box(flat)).containsExactly(new double[] { -2e6 - e, 5 - e, 7 - e, 10 + e, 6 + e, 7 + e },
                    within(1e-9));
            assertThat(flat.getMaxZ() - flat.getMinZ()).as("thickness of the flat axis").isGreaterThan(0.003);
        }
    }

    @Nested
    @DisplayName("union: the smallest enclosing box, each axis separately")
    class Union {
        @ParameterizedTest(name = "boxes apart along {0} only")
        @ValueSource(ints = { 0, 1, 2 })
        void apartAlongOneAxis(int axis) {
            double[] lo = { 1, 1, 1 }, hi = { 3, 3, 3 };
            lo[axis] = 5;
            hi[axis] = 8;
            BoundingBox other = new BoundingBox(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
            double[] expected = { 1, 1, 1, 3, 3, 3 };
            expected[axis + 3] = 8; // only this axis grows, only upwards
            assertThat(box(cube.union(other))).containsExactly(expected);
            assertThat(box(other.union(cube))).containsExactly(expected);
        }

        @ParameterizedTest(name = "boxes overlapping along {0}, the other reaching lower")
        @ValueSource(ints = { 0, 1, 2 })
        void overlappingAndLower(int axis) {
            double[] lo = { 1.5, 1.5, 1.5 }, hi = { 2.5, 2.5, 2.5 };
            lo[axis] = -4;
            BoundingBox other = new BoundingBox(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
            double[] expected = { 1, 1, 1, 3, 3, 3 };
            expected[axis] = -4;
            assertThat(box(cube.union(other))).containsExactly(expected);
        }

        @Test
        void unionWithAContainedBoxIsTheSameBox() {
            assertThat(box(cube.union(new BoundingBox(2, 2, 2, 2.5, 2.5, 2.5)))).containsExactly(1, 1, 1, 3, 3, 3);
        }

        @Test
        void mixedAxes() {
            BoundingBox other = new BoundingBox(0, 2, -1, 2, 4, 2);
            assertThat(box(cube.union(other))).containsExactly(0, 1, -1, 3, 4, 3);
        }
    }

    static Stream<Arguments> axisDirections() {
        return Stream.of(Arguments.of(0, 1), Arguments.of(0, -1), Arguments.of(1, 1), Arguments.of(1, -1), Arguments.of(2, 1),
                Arguments.of(2, -1));
    }

    @Nested
    @DisplayName("slab test with axis-parallel rays (two direction components are zero)")
    class AxisParallel {
        @ParameterizedTest(name = "along {0} ({1}): inside the other two slabs → hit")
        @MethodSource("geometries.BoundingBoxTest#axisDirections")
        void insideTheSlabs(int axis, int sign) {
            double[] o = on(axis, 2 - 5 * sign, 2); // 5 before the centre, looking at it
            assertThat(hits(cube, o, on(axis, sign, 0))).isTrue();
        }

        @ParameterizedTest(name = "along {0} ({1}): outside one of the other slabs → miss")
        @MethodSource("geometries.BoundingBoxTest#axisDirections")
        void outsideASlab(int axis, int sign) {
            for (int other = 0; other < 3; ++other) {
                if (other == axis) continue;
                for (double off : new double[] { 0.5, 3.5 }) {
                    double[] o = on(axis, 2 - 5 * sign, 2);
                    o[other] = off;
                    assertThat(hits(cube, o, on(axis, sign, 0))).as("offset %s on %s", off, AXIS[other]).isFalse();
                }
            }
        }

        @ParameterizedTest(name = "along {0} ({1}): pointing away → miss")
        @MethodSource("geometries.BoundingBoxTest#axisDirections")
        void pointingAway(int axis, int sign) {
            assertThat(hits(cube, on(axis, 2 - 5 * sign, 2), on(axis, -sign, 0))).isFalse();
        }

        @Test
        @DisplayName("negative zero components (1/-0 = -∞) give the same answers as positive zeros")
        void signedZeros() {
            double[] d = { 1, -0.0, -0.0 };
            assertThat(hits(cube, new double[] { -5, 2, 2 }, d)).isTrue();
            assertThat(hits(cube, new double[] { -5, 0.5, 2 }, d)).isFalse();
            assertThat(hits(cube, new double[] { -5, 2, 3.5 }, d)).isFalse();
        }

        @Test
        @DisplayName("a ray with a single non-zero component hitting the box from inside a face")
        void diagonalInOnePlane() {
            assertThat(hits(cube, new double[] { 0, 0, 2 }, new double[] { 1, 1, 0 })).isTrue();
            assertThat(hits(cube, new double[] { 0, 0, 5 }, new double[] { 1, 1, 0 })).isFalse();
        }
    }

    @Nested
    @DisplayName("the ray's origin exactly on a slab plane (0·∞ = NaN in the slab test)")
    class OriginOnASlabPlane {
        @ParameterizedTest(name = "along x, on the {0} plane of y → touches the face: hit")
        @ValueSource(strings = { "min", "max" })
        void onAFacePlaneParallel(String which) {
            double y = which.equals("min") ? 1 : 3;
            assertThat(hits(cube, new double[] { -5, y, 2 }, new double[] { 1, 0, 0 })).isTrue();
            assertThat(hits(cube, new double[] { -5, y, 2 }, new double[] { 1, -0.0, 0 })).isTrue();
        }

        @Test
        @DisplayName("just outside the face plane: miss")
        void justOutside() {
            assertThat(hits(cube, new double[] { -5, Math.nextDown(1.0), 2 }, new double[] { 1, 0, 0 })).isFalse();
            assertThat(hits(cube, new double[] { -5, Math.nextUp(3.0), 2 }, new double[] { 1, 0, 0 })).isFalse();
        }

        @Test
        @DisplayName("on two slab planes at once (along an edge of the box): hit")
        void alongAnEdge() {
            assertThat(hits(cube, new double[] { -5, 1, 3 }, new double[] { 1, 0, 0 })).isTrue();
        }

        @Test
        @DisplayName("in the plane of a flat box: hit; beside it: miss")
        void flatBox() {
            BoundingBox flat = new BoundingBox(1, 1, 2, 3, 3, 2);
            assertThat(hits(flat, new double[] { -5, 2, 2 }, new double[] { 1, 0, 0 })).isTrue();
            assertThat(hits(flat, new double[] { -5, 2, Math.nextUp(2.0) }, new double[] { 1, 0, 0 })).isFalse();
            assertThat(hits(flat, new double[] { 2, 2, 5 }, new double[] { 0, 0, -1 })).isTrue();
        }

        @Test
        @DisplayName("origin on a slab plane of a non-parallel ray: an ordinary hit or miss")
        void nonParallel() {
            assertThat(hits(cube, new double[] { 1, 0, 2 }, new double[] { 0, 1, 0 })).isTrue();
            assertThat(hits(cube, new double[] { 1, 0, 2 }, new double[] { -1, 1, 0 })).isFalse();
        }
    }

    @Nested
    @DisplayName("ray position relative to the box")
    class Position {
        @Test
        @DisplayName("starting inside: hit in any direction, even with a tiny tMax")
        void startingInside() {
            Random rnd = new Random(3);
            for (int i = 0; i < 100; ++i) {
                double[] d = { rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian() };
                assertThat(hits(cube, new double[] { 2, 2.5, 1.5 }, d, 1e-9)).isTrue();
            }
            assertThat(hits(cube, new double[] { 2, 2, 2 }, new double[] { 0, 0, 1 })).isTrue();
        }

        @Test
        @DisplayName("box behind the ray: miss")
        void behind() {
            assertThat(hits(cube, new double[] { 5, 5, 5 }, new double[] { 1, 1, 1 })).isFalse();
            assertThat(hits(cube, new double[] { 5, 2, 2 }, new double[] { 1, 0, 0 })).isFalse();
        }

        @Test
        @DisplayName("diagonal ray through the box: hit; passing beside a corner: miss")
        void diagonal() {
            assertThat(hits(cube, new double[] { 0, 0, 0 }, new double[] { 1, 1, 1 })).isTrue();
            assertThat(hits(cube, new double[] { 0, 0, 0 }, new double[] { 1, 1, 3.1 })).isFalse(); // z leaves before x, y enter
        }
    }

    @Nested
    @DisplayName("tMax clipping: the box is entered at t = 1 and left at t = 3")
    class Clipping {
        private final double[] o = { 0, 2, 2 }, d = { 1, 0, 0 };

        @ParameterizedTest(name = "tMax = {0}: hit = {1}")
        @org.junit.jupiter.params.provider.CsvSource({ "0.5, false", "0.9999999, false", "1, true", "2, true", "10, true" })
        void clipped(double tMax, boolean expected) {
            assertThat(hits(cube, o, d, tMax)).isEqualTo(expected);
        }
    }

    /**
     * An independent slab test, written the textbook way: a ray parallel to a slab is inside it
     * only if its origin is; otherwise the slab's entry and exit distances clip the interval.
     */
    private static boolean reference(BoundingBox b, double[] o, double[] d, double tMax) {
        double[] min = { b.getMinX(), b.getMinY(), b.getMinZ() }, max = { b.getMaxX(), b.getMaxY(), b.getMaxZ() };
        double enter = 0, exit = tMax;
        for (int a = 0; a < 3; ++a) {
            if (d[a] == 0) {
                if (o[a] < min[a] || o[a] > max[a]) return false;
                continue;
            }
            double t1 = (min[a] - o[a]) / d[a], t2 = (max[a] - o[a]) / d[a];
            enter = Math.max(enter, Math.min(t1, t2));
            exit = Math.min(exit, Math.max(t1, t2));
        }
        return enter <= exit;
    }

    @Test
    @DisplayName("agrees with an independent slab test on random boxes and rays, zero components and origins on planes included")
    void agreesWithTheReference() {
        Random rnd = new Random(11);
        int hitsSeen = 0, checked = 0;
        for (int i = 0; i < 50_000; ++i) {
            double[] lo = new double[3], hi = new double[3], o = new double[3], d = new double[3];
            for (int a = 0; a < 3; ++a) {
                lo[a] = rnd.nextInt(5) - 2;
                hi[a] = lo[a] + rnd.nextInt(3); // flat on some axes
                o[a] = rnd.nextInt(4) == 0 ? (rnd.nextBoolean() ? lo[a] : hi[a]) : 8 * rnd.nextDouble() - 4;
                int kind = rnd.nextInt(4);
                d[a] = kind == 0 ? 0.0 : kind == 1 ? -0.0 : rnd.nextGaussian();
            }
            if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
            double tMax = rnd.nextBoolean() ? Double.POSITIVE_INFINITY : 6 * rnd.nextDouble();
            BoundingBox b = new BoundingBox(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
            if (nearlyTouching(b, o, d, tMax)) continue;
            boolean expected = reference(b, o, d, tMax);
            assertThat(hits(b, o, d, tMax)).as("box %s, origin %s, direction %s, tMax %s", b, java.util.Arrays.toString(o),
                    java.util.Arrays.toString(d), tMax).isEqualTo(expected);
            ++checked;
            if (expected) ++hitsSeen;
        }
        // Both answers must occur often, or the comparison proves little.
        assertThat(hitsSeen).as("hits among %d cases", checked).isGreaterThan(1000);
        assertThat(checked - hitsSeen).as("misses among %d cases", checked).isGreaterThan(1000);
    }

    /** Grazing cases where rounding may decide either way: the two methods may legitimately differ. */
    private static boolean nearlyTouching(BoundingBox b, double[] o, double[] d, double tMax) {
        double[] min = { b.getMinX(), b.getMinY(), b.getMinZ() }, max = { b.getMaxX(), b.getMaxY(), b.getMaxZ() };
        double enter = 0, exit = tMax;
        for (int a = 0; a < 3; ++a) {
            if (d[a] == 0) continue;
            double t1 = (min[a] - o[a]) / d[a], t2 = (max[a] - o[a]) / d[a];
            enter = Math.max(enter, Math.min(t1, t2));
            exit = Math.min(exit, Math.max(t1, t2));
        }
        return Math.abs(enter - exit) < 1e-9;
    }

    /**
     * The kernel as it was written before its axes ordered their distances with one comparison
     * and a swap: the conditional expressions, each comparison on its own.
     */
    private static double conditionalForm(double x0, double y0, double z0, double x1, double y1, double z1, double ox,
                                          double oy, double oz, double ix, double iy, double iz, double tMax) {
        double[] lo = { x0, y0, z0 }, hi = { x1, y1, z1 }, o = { ox, oy, oz }, inv = { ix, iy, iz };
        double t0 = 0, t1 = tMax;
        for (int axis = 0; axis < 3; ++axis) {
            double a = (lo[axis] - o[axis]) * inv[axis], b = (hi[axis] - o[axis]) * inv[axis];
            double near = a > b ? b : a, far = a > b ? a : b;
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
        }
        return t0 <= t1 ? t0 : Double.POSITIVE_INFINITY;
    }

    @Test
    @DisplayName("the kernel's entry distance is the conditional form's, bit for bit: NaN (0·∞), infinite and signed-zero inverses included")
    void kernelBitForBit() {
        Random rnd = new Random(29);
        double[] inverses = { Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0.0, -0.0 };
        int finite = 0;
        for (int i = 0; i < 200_000; ++i) {
            double[] v = new double[13];
            for (int k = 0; k < 6; ++k) v[k] = rnd.nextInt(5) - 2 + (rnd.nextBoolean() ? 0 : rnd.nextDouble());
            for (int k = 6; k < 9; ++k) // origins: often exactly on a slab plane, so that 0·∞ = NaN occurs
                v[k] = rnd.nextInt(3) == 0 ? v[k - 6 + (rnd.nextBoolean() ? 0 : 3)] : 8 * rnd.nextDouble() - 4;
            for (int k = 9; k < 12; ++k)
                v[k] = rnd.nextInt(4) == 0 ? inverses[rnd.nextInt(inverses.length)] : 1 / rnd.nextGaussian();
            v[12] = rnd.nextBoolean() ? Double.POSITIVE_INFINITY : 6 * rnd.nextDouble();
            double expected = conditionalForm(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12]);
            double actual = BoundingBox.entry(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12]);
            assertThat(Double.doubleToRawLongBits(actual)).as("inputs %s", java.util.Arrays.toString(v))
                    .isEqualTo(Double.doubleToRawLongBits(expected));
            if (expected != Double.POSITIVE_INFINITY) ++finite;
        }
        assertThat(finite).as("boxes entered").isGreaterThan(10_000);
    }
}
