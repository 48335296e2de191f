package lighting;

import static org.assertj.core.api.Assertions.assertThatNullPointerException;

import java.util.stream.Stream;

import org.assertj.core.api.ThrowableAssert.ThrowingCallable;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Color;
import primitives.Double3;
import primitives.Point;
import primitives.Vector;

/** A null argument to a light's constructor is refused at once, naming the parameter. */
class NullArgumentsTest {
    private static final Color WHITE = new Color(255, 255, 255);

    static Stream<Arguments> constructors() {
        return Stream.of(
                Arguments.of("new AmbientLight(null, kA)", (ThrowingCallable) () -> new AmbientLight(null, Double3.ONE),
                        "ambient intensity"),
                Arguments.of("new AmbientLight(iA, null)", (ThrowingCallable) () -> new AmbientLight(WHITE, (Double3) null),
                        "ambient factor kA"),
                Arguments.of("new AmbientLight(null, 1)", (ThrowingCallable) () -> new AmbientLight(null, 1),
                        "ambient intensity"),
                Arguments.of("new DirectionalLight(c, null)", (ThrowingCallable) () -> new DirectionalLight(WHITE, null),
                        "light direction"),
                Arguments.of("new PointLight(null, null)", (ThrowingCallable) () -> new PointLight(null, null),
                        "light intensity"),
                Arguments.of("new SpotLight(null, null, null)", (ThrowingCallable) () -> new SpotLight(null, null, null),
                        "light intensity"),
                Arguments.of("new SpotLight(c, p, null)", (ThrowingCallable) () -> new SpotLight(WHITE, Point.ZERO, null),
                        "spot direction"),
                Arguments.of("new SpotLight(c, null, v)", (ThrowingCallable) () -> new SpotLight(WHITE, null, Vector.AXIS_X),
                        "light position"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("constructors")
    @DisplayName("a null argument is named")
    void namesTheParameter(String call, ThrowingCallable construction, String parameter) {
        assertThatNullPointerException().isThrownBy(construction).withMessage(parameter);
    }
}
