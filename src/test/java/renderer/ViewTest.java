package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.MissingResourceException;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * {@link View}: the value {@link Camera.Builder#view()} checks a camera's view with, before
 * any image or tracer exists, refusing exactly what {@code build()} refuses with the same
 * exception and message; its rays are the camera's.
 */
class ViewTest {
    private static Camera.Builder complete() {
        return Camera.getBuilder().setLocation(new Point(1, 2, 3)).setDirection(new Point(1, 2, -7))
                .setVpSize(4, 3).setVpDistance(10).setResolution(8, 6).setSummary(false);
    }

    @Nested
    @DisplayName("view() refuses what build() refuses, with the same exception and message")
    class SameChecks {
        static Stream<Arguments> broken() {
            return Stream.of(
                    Arguments.of("no location", (UnaryOperator<Camera.Builder>) b -> Camera.getBuilder()),
                    Arguments.of("no direction", (UnaryOperator<Camera.Builder>) b -> Camera.getBuilder().setLocation(Point.ZERO)),
                    Arguments.of("no view plane size", (UnaryOperator<Camera.Builder>) b -> Camera.getBuilder()
                            .setLocation(Point.ZERO).setDirection(new Point(0, 0, -1))),
                    Arguments.of("no view plane distance, and a bad width", (UnaryOperator<Camera.Builder>) b -> Camera.getBuilder()
                            .setLocation(Point.ZERO).setDirection(new Point(0, 0, -1)).setVpSize(-1, 1)),
                    Arguments.of("no view plane distance", (UnaryOperator<Camera.Builder>) b -> Camera.getBuilder()
                            .setLocation(Point.ZERO).setDirection(new Point(0, 0, -1)).setVpSize(1, 1)),
                    Arguments.of("a zero height", (UnaryOperator<Camera.Builder>) b -> b.setVpSize(4, 0)),
                    Arguments.of("a NaN distance", (UnaryOperator<Camera.Builder>) b -> b.setVpDistance(Double.NaN)),
                    Arguments.of("a 0x4 resolution", (UnaryOperator<Camera.Builder>) b -> b.setResolution(0, 4)),
                    Arguments.of("a target at the location", (UnaryOperator<Camera.Builder>) b -> b.setDirection(new Point(1, 2, 3))),
                    Arguments.of("a target along +y", (UnaryOperator<Camera.Builder>) b -> b.setDirection(new Point(1, 9, 3))),
                    Arguments.of("a target along the up vector", (UnaryOperator<Camera.Builder>) b ->
                            b.setDirection(new Point(4, 2, 3), new Vector(-1, 0, 0))),
                    Arguments.of("a resolution and a bad target: the resolution first", (UnaryOperator<Camera.Builder>) b ->
                            b.setResolution(-1, 1).setDirection(new Point(1, 2, 3))));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("broken")
        void sameFailure(String what, UnaryOperator<Camera.Builder> breakIt) {
            Camera.Builder builder = breakIt.apply(complete());
            Throwable byBuild = catchThrown(builder::build);
            Throwable byView = catchThrown(builder::view);
            assertThat(byBuild).as("build()").isNotNull();
            assertThat(byView).as("view()").isExactlyInstanceOf(byBuild.getClass()).hasMessage(byBuild.getMessage());
            if (byBuild instanceof MissingResourceException m)
                assertThat(((MissingResourceException) byView).getKey()).isEqualTo(m.getKey());
        }

        private static Throwable catchThrown(Runnable call) {
            try {
                call.run();
                return null;
            } catch (RuntimeException e) {
                return e;
            }
        }
    }

    @Nested
    @DisplayName("the view a builder makes")
    class Built {
        @Test
        @DisplayName("holds the builder's location, orthonormal frame, view plane, resolution and lens")
        void parts() {
            View view = complete().setDepthOfField(12, 0.5).view();
            assertThat(view.location()).isEqualTo(new Point(1, 2, 3));
            assertThat(view.frame().to()).isEqualTo(new Vector(0, 0, -1));
            assertThat(view.frame().up()).isEqualTo(new Vector(0, 1, 0));
            assertThat(view.frame().right()).isEqualTo(new Vector(1, 0, 0));
            assertThat(view.plane()).isEqualTo(new View.ViewPlane(4, 3, 10, 8, 6));
            assertThat(view.lens()).isEqualTo(new View.Lens(0.5, 12));
        }

        @Test
        @DisplayName("without an image writer or tracer: a 40000x40000 resolution allocates nothing")
        void noImage() {
            assertThat(complete().setResolution(40_000, 40_000).view().plane().nX()).isEqualTo(40_000);
        }

        @Test
        @DisplayName("is the built camera's: same frame and the same rays, bit for bit")
        void cameraDelegates() {
            Camera.Builder builder = complete().setDirection(new Point(-3, 5, -20), new Vector(0.1, 1, 0));
            View view = builder.view();
            Camera camera = builder.build();
            assertThat(camera.getVRight()).isEqualTo(view.frame().right());
            for (int i = 0; i < 6; ++i)
                for (int j = 0; j < 8; ++j) {
                    Ray a = view.constructRay(8, 6, j, i), b = camera.constructRay(j, i);
                    assertThat(a.getDirection().getX()).isEqualTo(b.getDirection().getX());
                    assertThat(a.getDirection().getY()).isEqualTo(b.getDirection().getY());
                    assertThat(a.getDirection().getZ()).isEqualTo(b.getDirection().getZ());
                }
        }
    }

    @Nested
    @DisplayName("the value's own checks")
    class Checks {
        @Test
        @DisplayName("a frame that is not orthonormal and right-handed is refused, naming it")
        void frame() {
            Vector x = new Vector(1, 0, 0), y = new Vector(0, 1, 0), z = new Vector(0, 0, 1);
            assertThat(View.Frame.of(z.negate(), y).right()).isEqualTo(x);
            assertThatIllegalArgumentException().isThrownBy(() -> new View.Frame(z.negate(), y, x.negate()))
                    .withMessageContaining("right = to x up");
            assertThatIllegalArgumentException().isThrownBy(() -> new View.Frame(z, new Vector(0, 2, 0), x.negate()))
                    .withMessageContaining("unit vectors");
        }

        @ParameterizedTest(name = "aperture {0}, focal distance {1}")
        @CsvSource({ "-1, 10, aperture radius", "0.5, 0, focal distance", "0, -1, focal distance", "NaN, 1, aperture radius" })
        @DisplayName("a lens with a negative aperture, or an aperture without a focal distance, is refused")
        void lens(double aperture, double focal, String named) {
            assertThatIllegalArgumentException().isThrownBy(() -> new View.Lens(aperture, focal)).withMessageContaining(named);
        }

        @Test
        @DisplayName("a pinhole has aperture 0, whatever its focal distance")
        void pinhole() {
            assertThat(View.Lens.PINHOLE.isPinhole()).isTrue();
            assertThat(new View.Lens(0, 7).isPinhole()).isTrue();
            assertThat(new View.Lens(0.1, 7).isPinhole()).isFalse();
        }

        @Test
        @DisplayName("constructRay refuses a pixel outside the resolution, naming it")
        void outside() {
            View view = complete().view();
            assertThatThrownBy(() -> view.constructRay(2, 2, 2, 0)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("pixel (2,0) is outside the 2x2 view plane");
            assertThatThrownBy(() -> view.constructRay(0, 2, 0, 0)).hasMessage("resolution must be positive, got 0x2");
        }
    }
}
