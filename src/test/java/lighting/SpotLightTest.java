package lighting;

import static lighting.LightAssertions.assertColor;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/**
 * A point light scaled by max(0, dir·l)^narrowBeam. The spot at the origin points along −z
 * (given unnormalized, as (0,0,−2)).
 */
class SpotLightTest {
    private static SpotLight spot() {
        return new SpotLight(new Color(200, 100, 40), Point.ZERO, new Vector(0, 0, -2));
    }

    @Test
    @DisplayName("on the axis: the point light's intensity, attenuated the same way")
    void onAxis() {
        // d = 2: 1 + 0.25·4 = 2.
        assertColor(spot().setKq(0.25).getIntensity(new Point(0, 0, -2)), 100, 50, 20);
        assertThat(spot().getL(new Point(0, 0, -2))).isEqualTo(new Vector(0, 0, -1));
        assertThat(spot().getDistance(new Point(0, 0, -2))).isEqualTo(2);
    }

    @ParameterizedTest(name = "narrow beam {0}: factor 0.8^{0} = {1}")
    @CsvSource({"1, 0.8", "2, 0.64", "3, 0.512", "0.5, 0.894427190999916"})
    @DisplayName("off the axis: scaled by cos^narrowBeam")
    void offAxis(double narrowBeam, double factor) {
        // (3, 0, −4): l = (0.6, 0, −0.8), cos = 0.8, d = 5, kQ·d² = 0.04·25 = 1, so / 2.
        Color c = spot().setKq(0.04).setNarrowBeam(narrowBeam).getIntensity(new Point(3, 0, -4));
        assertColor(c, 200 * factor / 2, 100 * factor / 2, 40 * factor / 2);
    }

    @ParameterizedTest(name = "at ({0}, {1}, {2})")
    @CsvSource({"0, 0, 5", "3, 0, 4", "4, 0, 0", "0, -7, 0"})
    @DisplayName("behind the spot or beside it (cos <= 0): black")
    void behind(double x, double y, double z) {
        assertColor(spot().getIntensity(new Point(x, y, z)), 0, 0, 0);
        assertColor(spot().setNarrowBeam(5).getIntensity(new Point(x, y, z)), 0, 0, 0);
    }

    @Test
    @DisplayName("the fluent setters return the SpotLight, so they chain with setNarrowBeam")
    void fluent() {
        SpotLight s = spot().setKc(1).setKl(0.1).setKq(0.01).setRadius(0.5).setNarrowBeam(4);
        assertThat(s.getRadius()).isEqualTo(0.5);
        assertThat(s.getPosition()).isEqualTo(Point.ZERO);
    }

    @ParameterizedTest(name = "narrow beam {0}")
    @ValueSource(doubles = {0, -1, Double.NaN, Double.POSITIVE_INFINITY})
    @DisplayName("a narrow beam that is not a positive finite number is rejected, naming the value")
    void badNarrowBeam(double narrowBeam) {
        assertThatIllegalArgumentException().isThrownBy(() -> spot().setNarrowBeam(narrowBeam))
                .withMessageContaining("narrow beam").withMessageContaining(String.valueOf(narrowBeam));
    }
}
