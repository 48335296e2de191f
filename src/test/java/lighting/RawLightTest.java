package lighting;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Color;
import primitives.Point;
import primitives.Vector;

/**
 * The renderer asks lights about points given as doubles ({@code getL(x, y, z, out)} and so on).
 * Those answers are bit for bit the object methods' for the library's lights (whose object forms
 * call them) and for a user's light that implements only the object methods (the defaults call
 * those).
 */
class RawLightTest {
    /** A light written by a user: only the course's three methods. */
    private static final class Lamp implements LightSource {
        private final Point position = new Point(3, 4, 5);

        @Override
        public Color getIntensity(Point p) {
            return new Color(100, 50, 25).scale(1 / (1 + p.distance(position)));
        }

        @Override
        public Vector getL(Point p) {
            return p.subtract(position).normalize();
        }

        @Override
        public double getDistance(Point p) {
            return p.distance(position);
        }
    }

    static Stream<Arguments> lights() {
        return Stream.of(
                Arguments.of("point light", new PointLight(new Color(500, 400, 300), new Point(10, 20, 30)).setKl(0.01).setKq(0.001)),
                Arguments.of("spot light, narrow beam 3", new SpotLight(new Color(700, 600, 900), new Point(-15, 22, 15),
                        new Vector(1, -1.6, -1)).setKl(0.001).setKq(0.00001).setNarrowBeam(3)),
                Arguments.of("spot light, plain cosine", new SpotLight(new Color(70, 60, 90), new Point(0, 10, 0),
                        new Vector(0, -1, 0))),
                Arguments.of("directional light", new DirectionalLight(new Color(240, 240, 240), new Vector(1, -1, -3))),
                Arguments.of("a user's light (object defaults)", new Lamp()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("lights")
    @DisplayName("getL, getIntensity and getDistance of doubles equal the object forms bit for bit")
    void rawEqualsObjects(String name, LightSource light) {
        Random rnd = new Random(7);
        double[] l = new double[3], c = new double[3];
        for (int i = 0; i < 1000; ++i) {
            Point p = new Point(100 * rnd.nextGaussian(), 100 * rnd.nextGaussian(), 100 * rnd.nextGaussian());
            light.getL(p.getX(), p.getY(), p.getZ(), l);
            Vector lo = light.getL(p);
            assertThat(l).as("getL at %s", p).containsExactly(lo.getX(), lo.getY(), lo.getZ());
            light.getIntensity(p.getX(), p.getY(), p.getZ(), c);
            Color co = light.getIntensity(p);
            assertThat(c).as("getIntensity at %s", p).containsExactly(co.getR(), co.getG(), co.getB());
            assertThat(light.getDistance(p.getX(), p.getY(), p.getZ())).as("getDistance at %s", p)
                    .isEqualTo(light.getDistance(p));
        }
    }
}
