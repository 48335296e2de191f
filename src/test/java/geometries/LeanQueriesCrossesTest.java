package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * {@link LeanQueries#crosses}: a shape crosses a ray exactly when the any-hit walk would visit
 * one of its hits, under the walk's own acceptance rule (ahead of the head, the distance bound
 * included).
 */
class LeanQueriesCrossesTest {
    private static final Ray ALONG_Z = new Ray(new Point(0, 0, 0), new Vector(0, 0, 1));

    @ParameterizedTest(name = "a sphere at z = {0}, radius 1, bound {1}: {2}")
    @CsvSource({ "5, 10, true", "5, 4, true", "5, 3.5, false", "-5, 10, false", "0, 10, true", "12, 10, false",
            "11, 10, true" })
    @DisplayName("a sphere: ahead and within the bound, the bound inclusive; the far side from inside; nothing behind")
    void sphere(double z, double bound, boolean expected) {
        assertThat(LeanQueries.crosses(new Sphere(new Point(0, 0, z), 1), Hit.of(ALONG_Z), bound)).isEqualTo(expected);
    }

    @Test
    @DisplayName("any shape, any ray: the walk visits a hit exactly when the probe says it crosses")
    void agreesWithTheWalk() {
        Random random = new Random(20261130);
        int[] answers = new int[2]; // how many rays the probe answered false, true: both must be common
        for (int i = 0; i < 20_000; ++i) {
            Geometry shape = shape(random);
            Ray ray = new Ray(point(random), new Vector(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(0.1, 1)));
            double bound = random.nextDouble(0.5, 30);
            int[] visited = { 0 };
            LeanQueries.visitHits(shape, Hit.of(ray), bound, (g, t) -> {
                ++visited[0];
                return true;
            });
            assertThat(LeanQueries.crosses(shape, Hit.of(ray), bound)).as("%s, %s, bound %s", shape, ray, bound)
                    .isEqualTo(visited[0] > 0);
            ++answers[visited[0] > 0 ? 1 : 0];
        }
        assertThat(answers[0]).as("rays that miss").isGreaterThan(1_000);
        assertThat(answers[1]).as("rays that cross").isGreaterThan(1_000);
    }

    private static Point point(Random random) {
        return new Point(random.nextDouble(-10, 10), random.nextDouble(-10, 10), random.nextDouble(-10, 10));
    }

    private static Geometry shape(Random random) {
        Point c = point(random);
        return switch (random.nextInt(4)) {
        case 0 -> new Sphere(c, random.nextDouble(0.5, 4));
        case 1 -> new Plane(c, new Vector(random.nextDouble(-1, 1), random.nextDouble(-1, 1), 1));
        case 2 -> new Triangle(c, c.add(new Vector(random.nextDouble(1, 6), 0, 0.5)), c.add(new Vector(0, random.nextDouble(1, 6), 0.5)));
        default -> new Polygon(c, c.add(new Vector(4, 0, 0)), c.add(new Vector(4, 4, 0)), c.add(new Vector(0, 4, 0)));
        };
    }
}
