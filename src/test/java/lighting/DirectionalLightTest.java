package lighting;

import static lighting.LightAssertions.assertColor;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/** A light at infinity: the same intensity and direction everywhere. */
class DirectionalLightTest {
    private final DirectionalLight light = new DirectionalLight(new Color(30, 60, 90), new Vector(0, -3, 4));

    @ParameterizedTest(name = "at ({0}, {1}, {2})")
    @CsvSource({"0, 0, 0", "100, -50, 3", "-1e6, 1e6, 7"})
    @DisplayName("intensity, direction and distance do not depend on the point")
    void sameEverywhere(double x, double y, double z) {
        Point p = new Point(x, y, z);
        assertColor(light.getIntensity(p), 30, 60, 90);
        // (0, −3, 4) has length 5.
        assertThat(light.getL(p)).isEqualTo(new Vector(0, -0.6, 0.8));
        assertThat(light.getDistance(p)).isEqualTo(Double.POSITIVE_INFINITY);
    }

    @Test
    @DisplayName("it has no position and no radius (hard shadows)")
    void noPositionNoRadius() {
        assertThat(light.getPosition()).isNull();
        assertThat(light.getRadius()).isZero();
    }

    @Test
    @DisplayName("a negative intensity is rejected, naming the value")
    void negativeIntensity() {
        assertThatIllegalArgumentException()
                .isThrownBy(() -> new DirectionalLight(new Color(10, -1, 0), new Vector(0, 0, -1)))
                .withMessageContaining("-1.0");
    }
}
