package lighting;

import static lighting.LightAssertions.assertColor;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import primitives.Color;
import primitives.Double3;

class AmbientLightTest {
    @Test
    @DisplayName("the intensity is I_A scaled by a single kA")
    void scalarKa() {
        assertColor(new AmbientLight(new Color(100, 200, 50), 0.5).getIntensity(), 50, 100, 25);
    }

    @Test
    @DisplayName("the intensity is I_A scaled per channel by a Double3 kA")
    void perChannelKa() {
        assertColor(new AmbientLight(new Color(100, 200, 50), new Double3(0.1, 0.2, 0.4)).getIntensity(), 10, 40, 20);
    }

    @Test
    @DisplayName("NONE is black")
    void none() {
        assertColor(AmbientLight.NONE.getIntensity(), 0, 0, 0);
    }

    @Test
    @DisplayName("a negative kA is rejected, naming it")
    void negativeKa() {
        assertThatIllegalArgumentException().isThrownBy(() -> new AmbientLight(new Color(1, 1, 1), -0.5))
                .withMessageContaining("-0.5");
        assertThatIllegalArgumentException()
                .isThrownBy(() -> new AmbientLight(new Color(1, 1, 1), new Double3(0.5, -2, 0.5)))
                .withMessageContaining("-2.0");
    }
}
