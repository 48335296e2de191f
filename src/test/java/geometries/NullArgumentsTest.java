package geometries;

import static org.assertj.core.api.Assertions.assertThatNullPointerException;

import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.assertj.core.api.ThrowableAssert.ThrowingCallable;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * A null argument to a geometry's constructor is refused at once with a
 * {@link NullPointerException} that names the parameter, not later, bare, while rendering.
 */
class NullArgumentsTest {
    private static final Point A = new Point(0, 0, 0), B = new Point(1, 0, 0), C = new Point(0, 1, 0);

    static Stream<Arguments> constructors() {
        return Stream.of(
                Arguments.of("new Sphere(null, 1)", (ThrowingCallable) () -> new Sphere(null, 1), "sphere center"),
                Arguments.of("new Sphere(1, null)", (ThrowingCallable) () -> new Sphere(1, null), "sphere center"),
                Arguments.of("new Triangle(null, null, null)", (ThrowingCallable) () -> new Triangle(null, null, null),
                        "polygon vertex 0"),
                Arguments.of("new Triangle(a, b, null)", (ThrowingCallable) () -> new Triangle(A, B, null), "polygon vertex 2"),
                Arguments.of("new Polygon(a, null, c)", (ThrowingCallable) () -> new Polygon(A, null, C), "polygon vertex 1"),
                Arguments.of("new Plane(null, null, null)", (ThrowingCallable) () -> new Plane(null, null, (Point) null),
                        "plane point p1"),
                Arguments.of("new Plane(a, b, null)", (ThrowingCallable) () -> new Plane(A, B, (Point) null), "plane point p3"),
                Arguments.of("new Plane(null, normal)", (ThrowingCallable) () -> new Plane(null, Vector.AXIS_Z), "plane point q"),
                Arguments.of("new Plane(q, null)", (ThrowingCallable) () -> new Plane(A, (Vector) null), "plane normal"),
                Arguments.of("new Tube(1, null)", (ThrowingCallable) () -> new Tube(1, null), "tube axis"),
                Arguments.of("new Cylinder(1, null, 1)", (ThrowingCallable) () -> new Cylinder(1, null, 1), "tube axis"),
                Arguments.of("new Ray(null, v)", (ThrowingCallable) () -> new Ray(null, Vector.AXIS_X), "ray head"),
                Arguments.of("new Ray(p, null)", (ThrowingCallable) () -> new Ray(A, null), "ray direction"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("constructors")
    @DisplayName("a null argument is named")
    void namesTheParameter(String call, ThrowingCallable construction, String parameter) {
        assertThatNullPointerException().isThrownBy(construction).withMessage(parameter);
    }
}
