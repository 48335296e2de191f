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
 * those), and for a user's subclass of a library light that overrides an object method (the
 * doubles forms then ask the override).
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

    /** A user's subclass of a library light that changes its falloff: both forms must use it. */
    private static final class Dimmed extends SpotLight {
        Dimmed() {
            super(new Color(300, 200, 100), new Point(1, 2, 3), new Vector(0, 0, -1));
        }

        @Override
        protected double attenuation(Point p) {
            return 1 / (1 + 0.5 * p.distance(position));
        }
    }

    /** A user's subclass of a library light that redefines its direction and intensity. */
    private static final class Tilted extends DirectionalLight {
        Tilted() {
            super(new Color(10, 20, 30), new Vector(0, 0, -1));
        }

        @Override
        public Vector getL(Point p) {
            return new Vector(1, 1, -1).normalize();
        }

        @Override
        public Color getIntensity(Point p) {
            return new Color(Math.abs(p.getX()), 1, 2);
        }
    }

    /** A user's subclass of a point light that only reports another distance. */
    private static final class FarAway extends PointLight {
        FarAway() {
            super(new Color(1, 2, 3), new Point(0, 0, 0));
        }

        @Override
        public double getDistance(Point p) {
            return 2 * super.getDistance(p);
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
                Arguments.of("a user's light (object defaults)", new Lamp()),
                Arguments.of("a user's spot light with its own attenuation", new Dimmed()),
                Arguments.of("a user's directional light with its own direction and intensity", new Tilted()),
                Arguments.of("a user's point light with its own distance", new FarAway()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("lights")
    @DisplayName("getL, getIntensity and getDistance of doubles equal the object forms bit for bit")
    void rawEqualsObjects(String name, LightSource light) {
        Random rnd = new Random(7);
        double[] l = new double[3], c = new double[3];
        for (int i = 0; i < 1000; ++i) {
            Point p = new Point(100 * rnd.nextGaussian(), 100 * rnd.nextGaussian(), 100 * rnd.nextGaussian());
            LightQueries.getL(light, p.getX(), p.getY(), p.getZ(), l);
            Vector lo = light.getL(p);
            assertThat(l).as("getL at %s", p).containsExactly(lo.getX(), lo.getY(), lo.getZ());
            LightQueries.getIntensity(light, p.getX(), p.getY(), p.getZ(), c);
            Color co = light.getIntensity(p);
            assertThat(c).as("getIntensity at %s", p).containsExactly(co.getR(), co.getG(), co.getB());
            assertThat(LightQueries.getDistance(light, p.getX(), p.getY(), p.getZ())).as("getDistance at %s", p)
                    .isEqualTo(light.getDistance(p));
        }
    }

    @org.junit.jupiter.api.Test
    @DisplayName("a user's override of a library light's object method is what the doubles forms answer")
    void overridesAreAsked() {
        double[] mine = new double[3], plain = new double[3];
        // Below the spot light, inside its beam: the user's falloff, not the library's kC + kL·d + kQ·d².
        new Dimmed().getIntensity(1, 2, -7, mine);
        new SpotLight(new Color(300, 200, 100), new Point(1, 2, 3), new Vector(0, 0, -1)).getIntensity(1, 2, -7, plain);
        assertThat(mine).containsExactly(plain[0] * (1 / 6.0), plain[1] * (1 / 6.0), plain[2] * (1 / 6.0));
        new Tilted().getL(5, 5, 5, mine);
        Vector expected = new Vector(1, 1, -1).normalize();
        assertThat(mine).containsExactly(expected.getX(), expected.getY(), expected.getZ());
        assertThat(new FarAway().getDistance(3, 4, 0)).isEqualTo(10);
    }
}
