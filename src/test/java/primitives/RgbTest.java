package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * {@link Rgb}, the renderer's in-place accumulator: each operation gives the bits of the same
 * operation on {@link Color} and {@link Double3} objects (the renderer's images depend on it), it
 * changes the value it is called on and no other, and its products and sums round as written,
 * without fusing or reassociating.
 */
class RgbTest {
    private static double[] channels(Rgb v) {
        return new double[] { v.r(), v.g(), v.b() };
    }

    private static double[] channels(Color c) {
        return new double[] { c.getR(), c.getG(), c.getB() };
    }

    private static double[] channels(Double3 k) {
        return new double[] { k.getD1(), k.getD2(), k.getD3() };
    }

    /** Colours and coefficients with inexact binary sums and products, so that any other rounding shows. */
    static Stream<Arguments> operands() {
        Random rnd = new Random(29);
        return Stream.generate(() -> Arguments.of(
                new Color(rnd.nextDouble() * 300, rnd.nextDouble() * 300, rnd.nextDouble() * 300),
                new Color(rnd.nextDouble() * 300, rnd.nextDouble() * 300, rnd.nextDouble() * 300),
                new Double3(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble()),
                rnd.nextDouble() * 3)).limit(20);
    }

    @Nested
    @DisplayName("the same bits as Color and Double3 (their arithmetic is these kernels)")
    class SameBits {
        @ParameterizedTest(name = "case {index}")
        @MethodSource("primitives.RgbTest#operands")
        void add(Color a, Color b, Double3 k, double s) {
            assertThat(channels(new Rgb().set(a).add(new Rgb().set(b)))).containsExactly(channels(a.add(b)));
        }

        @ParameterizedTest(name = "case {index}")
        @MethodSource("primitives.RgbTest#operands")
        void scaleByADouble(Color a, Color b, Double3 k, double s) {
            assertThat(channels(new Rgb().set(a).scale(s))).containsExactly(channels(a.scale(s)));
            assertThat(channels(new Rgb().setScaled(k, s))).containsExactly(channels(k.scale(s)));
        }

        @ParameterizedTest(name = "case {index}")
        @MethodSource("primitives.RgbTest#operands")
        void scalePerChannel(Color a, Color b, Double3 k, double s) {
            assertThat(channels(new Rgb().set(a).scale(k))).containsExactly(channels(a.scale(k)));
            assertThat(channels(new Rgb().setProduct(new Rgb().set(a), new Rgb().set(k)))).containsExactly(channels(a.scale(k)));
            Double3 k2 = k.scale(0.5);
            assertThat(channels(new Rgb().set(k).scale(k2))).containsExactly(channels(k.product(k2)));
        }

        @ParameterizedTest(name = "case {index}")
        @MethodSource("primitives.RgbTest#operands")
        void reduce(Color a, Color b, Double3 k, double s) {
            assertThat(channels(new Rgb().set(a).reduce(s + 1))).containsExactly(channels(a.reduce(s + 1)));
            assertThat(channels(new Rgb().set(a).reduce(7))).containsExactly(channels(a.reduce(7)));
            assertThat(channels(new Rgb().set(k).reduce(s + 1))).containsExactly(channels(k.reduce(s + 1)));
        }

        @ParameterizedTest(name = "case {index}")
        @MethodSource("primitives.RgbTest#operands")
        void addProductIsAddOfScale(Color a, Color b, Double3 k, double s) {
            assertThat(channels(new Rgb().set(a).addProduct(b, k))).containsExactly(channels(a.add(b.scale(k))));
            assertThat(channels(new Rgb().set(a).addProduct(new Rgb().set(b), new Rgb().set(k))))
                    .containsExactly(channels(a.add(b.scale(k))));
            assertThat(channels(new Rgb().set(a).addScaled(new Rgb().set(b), s))).containsExactly(channels(a.add(b.scale(s))));
            assertThat(channels(new Rgb().set(k).addScaled(k, s))).containsExactly(channels(k.add(k.scale(s))));
        }

        @ParameterizedTest(name = "case {index}")
        @MethodSource("primitives.RgbTest#operands")
        void addProductOfThree(Color a, Color b, Double3 k, double s) {
            Double3 f = k.scale(0.25);
            Rgb sum = new Rgb().set(a).addProduct(new Rgb().set(b), new Rgb().set(k), new Rgb().set(f));
            assertThat(channels(sum)).containsExactly(channels(a.add(b.scale(k).scale(f))));
        }

        @ParameterizedTest(name = "({0},{1},{2}) < {3}")
        @org.junit.jupiter.params.provider.CsvSource({ "0.1, 0.2, 0.3, 0.5", "0.6, 0.2, 0.3, 0.5", "0.1, 0.2, 0.5, 0.5",
                "0, 0, 0, 0", "0, 0, 1e-300, 0" })
        void lowerThanAndIsZero(double a, double b, double c, double bound) {
            Rgb v = new Rgb().set(a, b, c);
            Double3 d = new Double3(a, b, c);
            assertThat(v.lowerThan(bound)).isEqualTo(d.lowerThan(bound));
            assertThat(v.isZero()).isEqualTo(d.isZero());
        }
    }

    @Nested
    @DisplayName("rounding: each product and sum rounded as written")
    class Rounding {
        @Test
        @DisplayName("acc + a·b rounds the product, then the sum: not a fused multiply-add")
        void notFused() {
            double acc = 2.05, a = 0.854, b = 0.8;
            assertThat(acc + a * b).as("the operands tell the two apart").isNotEqualTo(Math.fma(a, b, acc));
            Rgb v = new Rgb().set(acc, acc, acc).addScaled(new Rgb().set(a, a, a), b);
            assertThat(channels(v)).containsOnly(acc + a * b);
        }

        @Test
        @DisplayName("a product of three factors associates as (a·k)·f")
        void threeFactors() {
            double a = 0.1, k = 0.2, f = 0.3;
            assertThat((a * k) * f).as("the operands tell the groupings apart").isNotEqualTo(a * (k * f));
            Rgb v = new Rgb().addProduct(new Rgb().set(a, a, a), new Rgb().set(k, k, k), new Rgb().set(f, f, f));
            assertThat(channels(v)).containsOnly(0 + (a * k) * f);
        }

        @Test
        @DisplayName("a mean is a sum divided by the count, not a sum of scaled terms")
        void mean() {
            double x = 0.1, y = 0.2, z = 0.3;
            Rgb v = new Rgb().add(new Rgb().set(x, y, z)).add(new Rgb().set(z, x, y)).add(new Rgb().set(y, z, x)).reduce(3);
            assertThat(v.r()).isEqualTo(((0 + x) + z + y) / 3);
        }
    }

    @Nested
    @DisplayName("in place")
    class InPlace {
        @Test
        @DisplayName("an operation changes the value it is called on, returns it, and leaves its operands alone")
        void changesOnlyItself() {
            Rgb acc = new Rgb().set(1, 2, 3), a = new Rgb().set(4, 5, 6), k = new Rgb().set(0.5, 0.25, 2);
            assertThat(acc.addProduct(a, k)).isSameAs(acc);
            assertThat(channels(acc)).containsExactly(3, 3.25, 15);
            assertThat(channels(a)).containsExactly(4, 5, 6);
            assertThat(channels(k)).containsExactly(0.5, 0.25, 2);
            assertThat(acc.scale(2).reduce(4).setZero()).isSameAs(acc);
            assertThat(channels(acc)).containsExactly(0, 0, 0);
        }

        @Test
        @DisplayName("a new value is black")
        void newIsBlack() {
            assertThat(channels(new Rgb())).containsExactly(0, 0, 0);
            assertThat(new Rgb().isZero()).isTrue();
        }

        @Test
        @DisplayName("productLowerThan and productIsZero test the product without storing it")
        void productTests() {
            Rgb t = new Rgb().set(0.5, 0.01, 0), w = new Rgb().set(0.001, 0.05, 7);
            assertThat(t.productLowerThan(w, 0.001)).isTrue();
            assertThat(t.productLowerThan(w, 0.0005)).isFalse(); // 0.5·0.001 is not below 0.0005
            assertThat(t.productIsZero(w)).isFalse();
            assertThat(new Rgb().set(0, 3, 0).productIsZero(new Rgb().set(5, 0, 9))).isTrue();
            assertThat(channels(t)).containsExactly(0.5, 0.01, 0);
        }
    }

    @Nested
    @DisplayName("out of the renderer")
    class Out {
        @Test
        @DisplayName("toColor is a new Color of the channels, with Color's check")
        void toColor() {
            assertThat(channels(new Rgb().set(1.5, 300, 0).toColor())).containsExactly(1.5, 300, 0);
            assertThatIllegalArgumentException().isThrownBy(() -> new Rgb().set(1, -2, 3).toColor())
                    .withMessageContaining("(1.0,-2.0,3.0)");
        }

        @Test
        @DisplayName("packed is Color's 0xRRGGBB, clamped")
        void packed() {
            assertThat(new Rgb().set(300, 0.9, 254.99).packed()).isEqualTo(new Color(300, 0.9, 254.99).toRgb()).isEqualTo(0xFF00FE);
        }
    }
}
