package geometries;

import static geometries.Hits.assertHits;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** The cylinder of radius 1 around the z axis from z = 0 (bottom cap) to z = 2 (top cap). */
class CylinderTest implements GeometryContract {
    private static final Vector X = new Vector(1, 0, 0), Z = new Vector(0, 0, 1);
    private final Cylinder cylinder = new Cylinder(1, new Ray(Point.ZERO, Z), 2);

    @Override
    public Intersectable subject() {
        return cylinder;
    }

    @Override
    public Ray knownHit() {
        return new Ray(new Point(-2, 0, 1), X);
    }

    @Override
    public Ray knownMiss() {
        return new Ray(new Point(-2, 0, 3), X);
    }

    @Override
    public Point focus() {
        return new Point(0, 0, 1);
    }

    @Override
    public double extent() {
        return 1.5;
    }

    @Nested
    @DisplayName("construction")
    class Construction {
        @ParameterizedTest(name = "height {0} is rejected")
        @ValueSource(doubles = { 0, -1, Double.NaN, Double.POSITIVE_INFINITY })
        void nonPositiveHeightIsRejected(double h) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Cylinder(1, new Ray(Point.ZERO, Z), h))
                    .withMessageContaining("height").withMessageContaining(String.valueOf(h));
        }

        @Test
        void nonPositiveRadiusIsRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Cylinder(0, new Ray(Point.ZERO, Z), 1))
                    .withMessageContaining("radius");
        }
    }

    @Nested
    @DisplayName("the shell, within the height")
    class Shell {
        @Test
        @DisplayName("orthogonal to the axis: two shell points")
        void orthogonal() {
            assertHits(cylinder, new Ray(new Point(-2, 0, 1), X), new Point(-1, 0, 1), new Point(1, 0, 1));
        }

        @Test
        @DisplayName("starts inside: one shell point")
        void startsInside() {
            assertHits(cylinder, new Ray(new Point(0, 0, 1), X), new Point(1, 0, 1));
        }

        @Test
        @DisplayName("tangent to the shell: none")
        void tangent() {
            assertHits(cylinder, new Ray(new Point(-2, 1, 1), X));
        }

        @ParameterizedTest(name = "line at z = {0}: none")
        @ValueSource(doubles = { 3, 2.5, -0.5, -1 })
        @DisplayName("the shell's line beyond the height (above or below): none")
        void beyondTheHeight(double z) {
            assertHits(cylinder, new Ray(new Point(-2, 0, z), X));
        }

        @Test
        @DisplayName("oblique, passing above the top: none")
        void obliqueAbove() {
            assertHits(cylinder, new Ray(new Point(-2, 0, 3), new Vector(1, 0, 0.1)));
        }
    }

    @Nested
    @DisplayName("the caps")
    class Caps {
        @Test
        @DisplayName("top cap and shell")
        void topCapThenShell() {
            assertHits(cylinder, new Ray(new Point(0, 0, 2.5), new Vector(1, 0, -1)), new Point(0.5, 0, 2), new Point(1, 0, 1.5));
        }

        @Test
        @DisplayName("bottom cap and shell")
        void bottomCapThenShell() {
            assertHits(cylinder, new Ray(new Point(0, 0, -0.5), new Vector(1, 0, 1)), new Point(0.5, 0, 0), new Point(1, 0, 0.5));
        }

        @ParameterizedTest(name = "at distance {0} from the axis: both caps")
        @ValueSource(doubles = { 0, 0.5, 0.99 })
        @DisplayName("along the axis, inside the radius")
        void alongTheAxisInside(double offset) {
            assertHits(cylinder, new Ray(new Point(offset, 0, -1), Z), new Point(offset, 0, 0), new Point(offset, 0, 2));
            assertHits(cylinder, new Ray(new Point(offset, 0, 3), Z.scale(-1)), new Point(offset, 0, 2), new Point(offset, 0, 0));
        }

        @Test
        @DisplayName("along the axis, outside the radius: none")
        void alongTheAxisOutside() {
            assertHits(cylinder, new Ray(new Point(2, 0, -1), Z));
        }

        @Test
        @DisplayName("along the axis, from inside: the cap ahead only")
        void alongTheAxisFromInside() {
            assertHits(cylinder, new Ray(new Point(0.5, 0, 1), Z), new Point(0.5, 0, 2));
        }

        @Test
        @DisplayName("starting on a cap going in: the other cap; going out: none")
        void startingOnACap() {
            assertHits(cylinder, new Ray(new Point(0.5, 0, 2), Z.scale(-1)), new Point(0.5, 0, 0));
            assertHits(cylinder, new Ray(new Point(0.5, 0, 2), Z));
        }

        @Test
        @DisplayName("through both rims: each rim point once (a rim belongs to its cap, not to the shell)")
        void throughTheRims() {
            assertHits(cylinder, new Ray(new Point(2, 0, 3), new Vector(-1, 0, -1)), new Point(1, 0, 2), new Point(-1, 0, 0));
        }

        @Test
        @DisplayName("along the shell's surface line: none (it only touches the cylinder; a tangent is no hit)")
        void alongTheSurfaceLine() {
            assertHits(cylinder, new Ray(new Point(1, 0, -1), Z));
            assertHits(cylinder, new Ray(new Point(0, -1, 3), Z.scale(-1)));
        }

        @Test
        @DisplayName("along the axis beyond the height, pointing away: none")
        void pointingAway() {
            assertHits(cylinder, new Ray(new Point(0, 0, 3), Z));
        }
    }

    @Nested
    @DisplayName("normal")
    class Normal {
        @Test
        void onTheShellIsRadial() {
            assertThat(cylinder.getNormal(new Point(1, 0, 1))).isEqualTo(X);
            assertThat(cylinder.getNormal(new Point(0, -1, 0.5))).isEqualTo(new Vector(0, -1, 0));
        }

        @Test
        void onTheCapsIsAlongTheAxis() {
            assertThat(cylinder.getNormal(new Point(0.5, 0, 0))).isEqualTo(Z.scale(-1));
            assertThat(cylinder.getNormal(new Point(0.5, 0, 2))).isEqualTo(Z);
        }

        @Test
        @DisplayName("at the cap centres (on the axis: no radial direction exists)")
        void atTheCapCentres() {
            assertThat(cylinder.getNormal(new Point(0, 0, 0))).isEqualTo(Z.scale(-1));
            assertThat(cylinder.getNormal(new Point(0, 0, 2))).isEqualTo(Z);
        }

        static Stream<Arguments> farCylinders() {
            return Stream.of(
                    Arguments.of("axis-aligned, at the scale of course scenes", new Point(0, 0, -500), new Vector(0, 0, 1), 40, 80, 1000),
                    Arguments.of("tilted axis", new Point(30, -20, -400), new Vector(1, 2, 2), 25, 60, 1000),
                    Arguments.of("far from the origin", new Point(3000, 1000, -5000), new Vector(-1, 3, 1), 50, 100, 2000));
        }

        /**
         * The normal at every hit of random camera-like rays must be the one of the surface the
         * point is on: ±axis on a cap, radial on the shell. The class of a point is decided here
         * independently, by its axial coordinate with a tolerance relative to the scene scale.
         */
        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.CylinderTest$Normal#farCylinders")
        void atHitPointsMatchesTheSurfaceHit(String name, Point base, Vector dir, double radius, double height, double distance) {
            Vector v = dir.normalize();
            Cylinder c = new Cylinder(radius, new Ray(base, v), height);
            Point middle = base.add(v.scale(height / 2));
            Random rnd = new Random(5);
            int capHits = 0;
            for (int i = 0; i < 2000; ++i) {
                Vector toEye = new Vector(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalize();
                Point eye = middle.add(toEye.scale(distance));
                Point aim = middle.add(new Vector(rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5)
                        .scale(1.6 * Math.max(radius, height)));
                Ray ray = new Ray(eye, aim.subtract(eye));
                List<Point> hits = c.findIntersections(ray);
                if (hits == null) continue;
                for (Point p : hits) {
                    double s = p.subtract(base).dotProduct(v);
                    double tol = 1e-7 * distance;
                    Vector n = c.getNormal(p);
                    if (Math.abs(s) < tol) {
                        ++capHits;
                        assertThat(n).as("bottom cap normal at %s (axial %s)", p, s).isEqualTo(v.scale(-1));
                    } else if (Math.abs(s - height) < tol) {
                        ++capHits;
                        assertThat(n).as("top cap normal at %s (axial %s)", p, s).isEqualTo(v);
                    } else {
                        assertThat(n.dotProduct(v)).as("shell normal at %s is orthogonal to the axis", p).isCloseTo(0, within(1e-9));
                    }
                }
            }
            assertThat(capHits).as("cap hits (the test must not be vacuous)").isGreaterThan(100);
        }
    }

    /**
     * Cylinders tens or hundreds of thousands of units from the origin: there the axial coordinate
     * of a cap hit carries rounding far above the library's absolute zero tolerance (2^-40), so
     * the normal must come from the surface that was hit (lean path) or from the nearest surface
     * (course path), not from an absolute test on the axial coordinate.
     */
    @Nested
    @DisplayName("normal, far from the origin")
    class FarNormal {
        static Stream<Arguments> farAway() {
            return Stream.of(
                    Arguments.of("2e4 from the origin, tilted axis", new Point(2e4, -1e4, 1.5e4), new Vector(2, -1, 2), 40, 80),
                    Arguments.of("1e5 from the origin, tilted axis", new Point(-6e4, 7e4, 5e4), new Vector(1, 2, 2), 25, 60),
                    Arguments.of("4e5 from the origin, tilted axis", new Point(4e5, 3e5, -2e5), new Vector(-1, 3, 1), 50, 100));
        }

        /**
         * Which surfaces {@code p} lies on, decided independently: its axial coordinate and radial
         * distance with a tolerance relative to the coordinates. A point near a rim is on both a
         * cap and the shell, and either normal is right there.
         */
        private static void assertNormalOfTheSurface(Vector n, Point p, Point base, Vector v, double radius,
                double height, double tol) {
            Vector w = p.subtract(base);
            double s = w.dotProduct(v);
            double rho = Math.sqrt(Math.max(0, w.lengthSquared() - s * s));
            boolean bottom = Math.abs(s) <= tol && rho <= radius + tol;
            boolean top = Math.abs(s - height) <= tol && rho <= radius + tol;
            boolean shell = Math.abs(rho - radius) <= tol && s >= -tol && s <= height + tol;
            assertThat(bottom || top || shell).as("hit %s (axial %s, radial %s) is on the cylinder", p, s, rho).isTrue();
            boolean capNormal = n.equals(v) && top || n.equals(v.scale(-1)) && bottom;
            boolean shellNormal = shell && Math.abs(n.dotProduct(v)) < 1e-9
                    && Math.abs(n.dotProduct(w) - rho) < tol; // radial and outward
            assertThat(capNormal || shellNormal)
                    .as("normal %s at %s (axial %s, radial %s; bottom %s, top %s, shell %s)", n, p, s, rho, bottom, top, shell)
                    .isTrue();
        }

        /** Rays from a camera 3 cylinder sizes away, aimed at random points around the cylinder. */
        private static List<Ray> cameraRays(Point middle, double size) {
            Random rnd = new Random(17);
            List<Ray> rays = new java.util.ArrayList<>();
            for (int i = 0; i < 2000; ++i) {
                Point eye = middle.add(new Vector(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian())
                        .normalize().scale(3 * size));
                Point aim = middle.add(new Vector(rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5)
                        .scale(1.6 * size));
                rays.add(new Ray(eye, aim.subtract(eye)));
            }
            return rays;
        }

        private static double tolerance(Point base) {
            return 1e-9 * Math.max(Math.abs(base.getX()), Math.max(Math.abs(base.getY()), Math.abs(base.getZ())));
        }

        /** The two ways to a hit's normal. */
        enum Path {
            /** closestHit, then the normal of the surface the hit record names. */
            LEAN_PATH_HIT_NORMAL {
                @Override
                Map<Point, Vector> normals(Cylinder c, Ray ray) {
                    Hit hit = new Hit();
                    if (!c.closestHit(ray, hit)) return Map.of();
                    Point p = hit.point(ray);
                    return Map.of(p, hit.normal(p));
                }
            },
            /** The course's list API, then getNormal of each point: the nearest surface decides. */
            LIST_API_GET_NORMAL {
                @Override
                Map<Point, Vector> normals(Cylinder c, Ray ray) {
                    List<Point> hits = c.findIntersections(ray);
                    Map<Point, Vector> result = new java.util.IdentityHashMap<>();
                    if (hits != null) for (Point p : hits) result.put(p, c.getNormal(p));
                    return result;
                }
            };

            abstract Map<Point, Vector> normals(Cylinder c, Ray ray);
        }

        static Stream<Arguments> farAwayByPath() {
            return farAway().flatMap(a -> Stream.of(Path.values()).map(path -> {
                Object[] args = a.get();
                return Arguments.of(args[0], path, args[1], args[2], args[3], args[4]);
            }));
        }

        @ParameterizedTest(name = "{0}, {1}")
        @MethodSource("geometries.CylinderTest$FarNormal#farAwayByPath")
        @DisplayName("the normal at every hit is the one of the surface hit")
        void normalOfTheSurfaceHit(String name, Path path, Point base, Vector dir, double radius, double height) {
            Vector v = dir.normalize();
            Cylinder c = new Cylinder(radius, new Ray(base, v), height);
            int capHits = 0;
            for (Ray ray : cameraRays(base.add(v.scale(height / 2)), Math.max(radius, height)))
                for (Map.Entry<Point, Vector> hit : path.normals(c, ray).entrySet()) {
                    if (Math.abs(hit.getValue().dotProduct(v)) > 0.5) ++capHits;
                    assertNormalOfTheSurface(hit.getValue(), hit.getKey(), base, v, radius, height, tolerance(base));
                }
            assertThat(capHits).as("cap hits (the test must not be vacuous)").isGreaterThan(100);
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("geometries.CylinderTest$FarNormal#farAway")
        @DisplayName("a ray along the axis hits the cap centres, where no radial direction exists")
        void alongTheAxisAtTheCapCentres(String name, Point base, Vector dir, double radius, double height) {
            Vector v = dir.normalize();
            Cylinder c = new Cylinder(radius, new Ray(base, v), height);
            Ray up = new Ray(base.add(v.scale(-height)), v), down = new Ray(base.add(v.scale(2 * height)), v.scale(-1));
            Hit hit = new Hit();
            assertThat(c.closestHit(up, hit.reset(Double.POSITIVE_INFINITY))).isTrue();
            assertThat(hit.normal(hit.point(up))).isEqualTo(v.scale(-1));
            assertThat(c.getNormal(hit.point(up))).isEqualTo(v.scale(-1));
            assertThat(c.closestHit(down, hit.reset(Double.POSITIVE_INFINITY))).isTrue();
            assertThat(hit.normal(hit.point(down))).isEqualTo(v);
            assertThat(c.getNormal(hit.point(down))).isEqualTo(v);
        }
    }

    @Nested
    @DisplayName("bounding box")
    class Bounds {
        @Test
        void axisAligned() {
            BoundingBox b = cylinder.getBoundingBox();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(-1, -1, 0, 1, 1, 2);
        }

        @Test
        void axisAlongNegativeX() {
            BoundingBox b = new Cylinder(2, new Ray(new Point(1, 1, 1), new Vector(-1, 0, 0)), 5).getBoundingBox();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(-4, -1, -1, 1, 3, 3);
        }

        static Stream<Arguments> tiltedAxes() {
            return Stream.of(Arguments.of(new Vector(1, 1, 0)), Arguments.of(new Vector(1, 2, 3)),
                    Arguments.of(new Vector(-3, 0.5, -1)), Arguments.of(new Vector(0, 0.1, 1)));
        }

        /**
         * Independent check: a cylinder's extreme points are on its two rim circles, so the box must
         * contain densely sampled rim points and be no larger than them (up to the sampling error).
         */
        @ParameterizedTest(name = "axis {0}")
        @MethodSource("geometries.CylinderTest$Bounds#tiltedAxes")
        void tiltedAxisBoxIsTightAroundTheRims(Vector axisDir) {
            Vector v = axisDir.normalize();
            Point base = new Point(2, -1, 3);
            double r = 1.5, h = 4;
            BoundingBox b = new Cylinder(r, new Ray(base, v), h).getBoundingBox();
            Vector u = v.crossProduct(Math.abs(v.getX()) < 0.9 ? X : new Vector(0, 1, 0)).normalize();
            Vector w = v.crossProduct(u);
            double[] lo = { Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY };
            double[] hi = { Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY };
            for (int k = 0; k < 7200; ++k) {
                double a = 2 * Math.PI * k / 7200;
                for (double s : new double[] { 0, h }) {
                    // Coordinates by hand: scaling a vector by cos(a) = 0 would be the zero vector.
                    double ca = r * Math.cos(a), sa = r * Math.sin(a);
                    double[] c = { base.getX() + v.getX() * s + u.getX() * ca + w.getX() * sa,
                            base.getY() + v.getY() * s + u.getY() * ca + w.getY() * sa,
                            base.getZ() + v.getZ() * s + u.getZ() * ca + w.getZ() * sa };
                    for (int i = 0; i < 3; ++i) {
                        lo[i] = Math.min(lo[i], c[i]);
                        hi[i] = Math.max(hi[i], c[i]);
                    }
                }
            }
            double sampling = r * (1 - Math.cos(Math.PI / 7200)) + 1e-12;
            double[] min = { b.getMinX(), b.getMinY(), b.getMinZ() }, max = { b.getMaxX(), b.getMaxY(), b.getMaxZ() };
            for (int i = 0; i < 3; ++i) {
                assertThat(min[i]).as("min on axis %d", i).isCloseTo(lo[i], within(sampling)).isLessThanOrEqualTo(lo[i] + 1e-12);
                assertThat(max[i]).as("max on axis %d", i).isCloseTo(hi[i], within(sampling)).isGreaterThanOrEqualTo(hi[i] - 1e-12);
            }
        }
    }
}
