package lighting;

import static lighting.LightAssertions.assertColor;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

import java.util.function.Consumer;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/** A light at a position, attenuated by 1 / (kC + kL·d + kQ·d²). */
class PointLightTest {
    private static final Point POSITION = new Point(1, 2, 3);

    private static PointLight light() {
        return new PointLight(new Color(100, 50, 20), POSITION);
    }

    @Nested
    @DisplayName("direction and distance")
    class Geometry {
        @Test
        @DisplayName("getL points from the light to the point, unit length; getDistance is the distance")
        void towardThePoint() {
            // (4,6,3) − (1,2,3) = (3,4,0), length 5.
            Point p = new Point(4, 6, 3);
            assertThat(light().getL(p)).isEqualTo(new Vector(0.6, 0.8, 0));
            assertThat(light().getDistance(p)).isCloseTo(5, within(1e-12));
            // Straight above: (1,2,7) − (1,2,3) = (0,0,4).
            assertThat(light().getL(new Point(1, 2, 7))).isEqualTo(new Vector(0, 0, 1));
            assertThat(light().getDistance(new Point(1, 2, 7))).isCloseTo(4, within(1e-12));
        }

        @Test
        @DisplayName("position and radius as set; radius 0 by default")
        void positionAndRadius() {
            assertThat(light().getPosition()).isEqualTo(POSITION);
            assertThat(light().getRadius()).isZero();
            assertThat(light().setRadius(0.75).getRadius()).isEqualTo(0.75);
        }
    }

    @Nested
    @DisplayName("attenuation")
    class Attenuation {
        @Test
        @DisplayName("by default (kC = 1, kL = kQ = 0) the intensity is not attenuated")
        void defaultUnattenuated() {
            assertColor(light().getIntensity(new Point(1, 2, 7)), 100, 50, 20);
            assertColor(light().getIntensity(new Point(1000, 2, 3)), 100, 50, 20);
        }

        @Test
        @DisplayName("kC = 2, kL = 0.5, kQ = 0.25 at d = 4: divided by 2 + 2 + 4 = 8")
        void allThree() {
            PointLight l = light().setKc(2).setKl(0.5).setKq(0.25);
            assertColor(l.getIntensity(new Point(1, 2, 7)), 12.5, 6.25, 2.5);
        }

        @Test
        @DisplayName("each coefficient alone, at d = 5")
        void eachAlone() {
            Point p = new Point(4, 6, 3);
            assertColor(light().setKc(4).getIntensity(p), 25, 12.5, 5);
            assertColor(light().setKc(0).setKl(1).getIntensity(p), 20, 10, 4);
            assertColor(light().setKc(0).setKq(1).getIntensity(p), 4, 2, 0.8);
        }

        @Test
        @DisplayName("all coefficients zero: rejected when used, with the denominator in the message")
        void zeroDenominator() {
            PointLight l = light().setKc(0);
            assertThatIllegalArgumentException().isThrownBy(() -> l.getIntensity(new Point(0, 0, 0)))
                    .withMessageContaining("kC=0.0");
        }
    }

    @Nested
    @DisplayName("bad values")
    class BadValues {
        static Stream<Arguments> setters() {
            return Stream.of(
                    Arguments.of("kC", -1.0, (Consumer<PointLight>) l -> l.setKc(-1)),
                    Arguments.of("kL", -0.5, (Consumer<PointLight>) l -> l.setKl(-0.5)),
                    Arguments.of("kQ", -0.01, (Consumer<PointLight>) l -> l.setKq(-0.01)),
                    Arguments.of("kQ", Double.NaN, (Consumer<PointLight>) l -> l.setKq(Double.NaN)),
                    Arguments.of("light radius", -2.0, (Consumer<PointLight>) l -> l.setRadius(-2)));
        }

        @ParameterizedTest(name = "{0} = {1}")
        @MethodSource("setters")
        @DisplayName("negative attenuation or radius is rejected, naming the coefficient and the value")
        void negative(String name, double value, Consumer<PointLight> set) {
            assertThatIllegalArgumentException().isThrownBy(() -> set.accept(light()))
                    .withMessageContaining(name).withMessageContaining(String.valueOf(value));
        }

        @Test
        @DisplayName("a negative intensity is rejected, naming the value")
        void negativeIntensity() {
            assertThatIllegalArgumentException().isThrownBy(() -> new PointLight(new Color(0, 0, -3), POSITION))
                    .withMessageContaining("-3.0");
        }
    }
}
