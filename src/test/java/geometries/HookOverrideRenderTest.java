package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import lighting.AmbientLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.SimpleRayTracer;
import scene.Scene;

/**
 * A student's subclass of a library shape that overrides the course hook is rendered through its
 * hook, as the course queries answer through it: the engine's doubles path is only ever a faster
 * way to the course's answer. Per shape, with the BVH on and off, pixel by pixel: a hook that
 * answers nothing makes the shape vanish from the render; a hook that passes the library's answer
 * on renders exactly the library's shape; a subclass that overrides nothing keeps the fast path.
 */
class HookOverrideRenderTest {
    private static final Point EYE = new Point(0, 0, 100);
    private static final Color BACKGROUND = new Color(5, 5, 5);
    private static final int N = 12;
    /** A square of two triangles at z = 0, 20 wide: a mesh's positions and indices. */
    private static final double[] SQUARE = { -10, -10, 0, 10, -10, 0, 10, 10, 0, -10, 10, 0 };
    private static final int[] TWO = { 0, 1, 2, 0, 2, 3 };

    /** A subclass whose 2023–24 hook answers nothing: the course query says no hit, so must the render. */
    private static Stream<Arguments> shapes() {
        Ray xAxis = new Ray(new Point(-10, 0, 0), new Vector(1, 0, 0));
        Point a = new Point(-10, -10, 0), b = new Point(10, -10, 0), c = new Point(10, 10, 0), d = new Point(-10, 10, 0);
        return Stream.of(
                Arguments.of("sphere", new Sphere(Point.ZERO, 10), new Sphere(Point.ZERO, 10) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return null;
                    }
                }, new Sphere(Point.ZERO, 10) {
                    @Override
                    protected List<Intersection> calcIntersectionsHelper(Ray ray, double maxDistance) {
                        return super.calcIntersectionsHelper(ray, maxDistance);
                    }
                }),
                Arguments.of("plane", new Plane(new Point(0, 0, -5), new Vector(0, 0, 1)),
                        new Plane(new Point(0, 0, -5), new Vector(0, 0, 1)) {
                            @Override
                            protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                                return null;
                            }
                        }, new Plane(new Point(0, 0, -5), new Vector(0, 0, 1)) {
                            @Override
                            protected List<Intersection> calculateIntersectionsHelper(Ray ray, double maxDistance) {
                                return super.calculateIntersectionsHelper(ray, maxDistance);
                            }
                        }),
                Arguments.of("triangle", new Triangle(a, b, c), new Triangle(a, b, c) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return null;
                    }
                }, new Triangle(a, b, c) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return super.findGeoIntersectionsHelper(ray, maxDistance);
                    }
                }),
                Arguments.of("polygon", new Polygon(a, b, c, d), new Polygon(a, b, c, d) {
                    @Override
                    protected List<Intersection> calcIntersectionsHelper(Ray ray, double maxDistance) {
                        return null;
                    }
                }, new Polygon(a, b, c, d) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return super.findGeoIntersectionsHelper(ray, maxDistance);
                    }
                }),
                Arguments.of("tube", new Tube(5, xAxis), new Tube(5, xAxis) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return null;
                    }
                }, new Tube(5, xAxis) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return super.findGeoIntersectionsHelper(ray, maxDistance);
                    }
                }),
                Arguments.of("mesh", new TriangleMesh(SQUARE, TWO), new TriangleMesh(SQUARE, TWO) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return null;
                    }
                }, new TriangleMesh(SQUARE, TWO) {
                    @Override
                    protected List<Intersection> calcIntersectionsHelper(Ray ray, double maxDistance) {
                        return super.calcIntersectionsHelper(ray, maxDistance);
                    }
                }),
                Arguments.of("cylinder", new Cylinder(5, xAxis, 20), new Cylinder(5, xAxis, 20) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray) {
                        return null;
                    }

                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return null;
                    }
                }, new Cylinder(5, xAxis, 20) {
                    @Override
                    protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                        return super.findGeoIntersectionsHelper(ray, maxDistance);
                    }
                }));
    }

    private static Scene scene(Geometry shape) {
        Scene scene = new Scene("hook override").setAmbientLight(new AmbientLight(new Color(30, 30, 30), 1))
                .setBackground(BACKGROUND);
        scene.geometries.add(shape.setEmission(new Color(60, 0, 0)).setMaterial(new Material().setKd(0.5).setKs(0.3).setShininess(20)));
        // Bounded neighbours, so that the BVH has a tree to walk beside the shape.
        for (int i = 0; i < 4; ++i)
            scene.geometries.add(new Sphere(new Point(-40 + 25 * i, 40, -20), 4).setEmission(new Color(0, 40, 0)));
        scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(30, 30, 60)).setKl(0.001));
        return scene;
    }

    /** The rays of an N×N grid through a 60×60 window at z = 0. */
    private static List<Ray> rays() {
        return Stream.iterate(0, k -> k < N * N, k -> k + 1).map(k -> new Ray(EYE,
                new Point(-30 + 60.0 * (k % N + 0.5) / N, 30 - 60.0 * (k / N + 0.5) / N, 0).subtract(EYE))).toList();
    }

    /** The query of the year whose hook the shape's class declares lowest (the one it overrode). */
    private static List<?> yearsQuery(Geometry shape, Ray ray) {
        return switch (HookCheck.lowestHook(shape.getClass())) {
            case FIND_GEO -> shape.findGeoIntersections(ray);
            case CALCULATE -> shape.calculateIntersections(ray);
            case CALC -> shape.calcIntersections(ray);
        };
    }

    @ParameterizedTest(name = "{0}: a hook that answers nothing hides it, BVH on and off")
    @MethodSource("shapes")
    void blindHookHides(String name, Geometry library, Geometry blind, Geometry passThrough) {
        Scene with = scene(library), without = scene(blind);
        for (boolean bvh : new boolean[] { true, false }) {
            var libraryTracer = new SimpleRayTracer(with).setBvh(bvh);
            var blindTracer = new SimpleRayTracer(without).setBvh(bvh);
            int onShape = 0;
            for (Ray ray : rays()) {
                assertThat(yearsQuery(blind, ray)).as("the course query of the blind %s's year", name).isNull();
                if (library.findIntersections(ray) == null) continue;
                ++onShape;
                assertThat(blindTracer.traceRay(ray)).as("%s, bvh %s, %s", name, bvh, ray)
                        .satisfies(color -> assertThat(color.distance(libraryTracer.traceRay(ray))).isGreaterThan(1));
            }
            assertThat(onShape).as("rays on the %s", name).isGreaterThan(5);
        }
    }

    @Test
    @DisplayName("a Geometries subclass whose hook answers nothing hides its children, BVH on and off")
    void blindList() {
        Geometry inside = new Sphere(Point.ZERO, 10).setEmission(new Color(60, 0, 0));
        Geometries blind = new Geometries(inside) {
            @Override
            protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
                return null;
            }
        };
        Geometry far = new Sphere(new Point(500, 500, -500), 1);
        Scene empty = scene(far), hidden = scene(far), shown = scene(far);
        hidden.geometries.add(blind);
        shown.geometries.add(new Geometries(inside));
        for (boolean bvh : new boolean[] { true, false }) {
            var emptyTracer = new SimpleRayTracer(empty).setBvh(bvh);
            var hiddenTracer = new SimpleRayTracer(hidden).setBvh(bvh);
            var shownTracer = new SimpleRayTracer(shown).setBvh(bvh);
            int onShape = 0;
            for (Ray ray : rays()) {
                assertThat(blind.findGeoIntersections(ray)).isNull();
                Color none = emptyTracer.traceRay(ray);
                assertThat(hiddenTracer.traceRay(ray).distance(none)).as("bvh %s, %s", bvh, ray).isLessThan(1e-9);
                if (shownTracer.traceRay(ray).distance(none) > 1) ++onShape;
            }
            assertThat(onShape).as("rays on the list's sphere when the list is the library's").isGreaterThan(5);
        }
    }

    @ParameterizedTest(name = "{0}: a hook that passes the library's answer on renders the library's shape")
    @MethodSource("shapes")
    void passThroughHookRendersTheSame(String name, Geometry library, Geometry blind, Geometry passThrough) {
        Scene with = scene(library), through = scene(passThrough);
        assertThat(passThrough.answersInDoubles()).as("a hook below the library's class loses the doubles path").isFalse();
        assertThat(library.answersInDoubles()).isTrue();
        for (boolean bvh : new boolean[] { true, false }) {
            var libraryTracer = new SimpleRayTracer(with).setBvh(bvh);
            var userTracer = new SimpleRayTracer(through).setBvh(bvh);
            for (Ray ray : rays())
                assertThat(userTracer.traceRay(ray).distance(libraryTracer.traceRay(ray))).as("%s, bvh %s, %s", name, bvh, ray)
                        .isLessThan(1e-9);
        }
    }
}
