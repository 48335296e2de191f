package lighting;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.assertj.core.api.SoftAssertions;

import primitives.Color;

/** Colour comparison for light tests, with a stated tolerance (Color.equals is the course's, kept for students). */
final class LightAssertions {
    private LightAssertions() {
    }

    /** Asserts each channel of {@code actual} within 1e-9 of the hand-computed value. */
    static void assertColor(Color actual, double r, double g, double b) {
        assertThat(actual).isNotNull();
        SoftAssertions soft = new SoftAssertions();
        soft.assertThat(actual.getR()).as("red of " + actual).isCloseTo(r, within(1e-9));
        soft.assertThat(actual.getG()).as("green of " + actual).isCloseTo(g, within(1e-9));
        soft.assertThat(actual.getB()).as("blue of " + actual).isCloseTo(b, within(1e-9));
        soft.assertAll();
    }
}
