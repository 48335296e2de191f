package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.function.Supplier;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Cylinder;
import geometries.Geometry;
import geometries.Polygon;
import geometries.Sphere;
import geometries.TriangleMesh;
import geometries.Tube;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * The render loop allocates nothing per ray for the library's shapes and lights (issue 14's bound:
 * at most 16 bytes per ray). Measured with the JVM's per-thread allocation counter on a render on
 * the calling thread, as the difference between two image sizes, so that what a render allocates
 * once (the BVH, the sampler's caches, the scratch records) cancels out and only the per-ray cost
 * remains. The hot path has no allocation for the JIT to remove, so the bound holds in the
 * interpreter too: nothing here depends on timing or on compilation. A guard checks that the meter
 * does see a shape that allocates.
 */
class AllocationTest {
    /** Issue 14's target. A path with one object per ray exceeds it (a Vector alone is 40 bytes). */
    private static final double BOUND = 16;

    private static final com.sun.management.ThreadMXBean THREADS = threads();

    private static com.sun.management.ThreadMXBean threads() {
        return ManagementFactory.getThreadMXBean() instanceof com.sun.management.ThreadMXBean t
                && t.isThreadAllocatedMemorySupported() ? t : null;
    }

    /**
     * The test scenes' every-effect scene plus every other library shape (polygon, tube, cylinder,
     * a smooth mesh) and a refracting glass ball: every raw query, normal and light path is taken.
     */
    private static Scene everyShape() {
        Scene scene = TestScenes.everyEffect();
        scene.geometries.add(
                new Polygon(new Point(-3, -1, -3.5), new Point(-1, -1, -3.5), new Point(-1, 1, -3.5), new Point(-3, 1, -3.5))
                        .setEmission(new Color(10, 30, 10)).setMaterial(new Material().setKd(0.4).setKs(0.2)),
                new Tube(0.15, new Ray(new Point(0, 1.8, -2), new Vector(1, 0.1, 0))).setEmission(new Color(30, 30, 0))
                        .setMaterial(new Material().setKd(0.4)),
                new Cylinder(0.4, new Ray(new Point(0, -1, -1.5), new Vector(0, 1, 0.2)), 0.8)
                        .setEmission(new Color(0, 30, 30)).setMaterial(new Material().setKd(0.4).setKr(0.3)),
                new TriangleMesh(new double[] { -0.5, 1, -1, 0.5, 1, -1, 0, 2, -1.2, 0, 1.2, -0.5 },
                        new int[] { 0, 1, 2, 0, 3, 1 },
                        new double[] { 0, 0, 1, 0, 0, 1, 0, 0.2, 1, 0, -1, 0.3 })
                        .setEmission(new Color(40, 10, 40)).setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(30)),
                new Sphere(new Point(0, -0.4, 1), 0.5).setEmission(new Color(5, 5, 5))
                        .setMaterial(new Material().setKd(0.02).setKs(0.5).setShininess(200).setKt(0.9).setKr(0.05).setIor(1.5)));
        return scene;
    }

    /** Bytes the calling thread allocates per traced ray, at the margin between a 24×16 and a 72×48 render. */
    private static double bytesPerRay(Supplier<Scene> scene, AntiAliasing mode) {
        return bytesPerRay(scene, mode, false);
    }

    /** The same, with a lens when {@code lens} (each mode's depth-of-field sampler). */
    private static double bytesPerRay(Supplier<Scene> scene, AntiAliasing mode, boolean lens) {
        render(scene.get(), mode, lens, 12, 8); // loads and initialises every class on the path first
        long[] small = render(scene.get(), mode, lens, 24, 16);
        long[] large = render(scene.get(), mode, lens, 72, 48);
        // The larger image sees a larger part of the scene (the view plane grows with it): 9 times
        // the pixels, at least 3 times the rays whatever the sampling decides.
        assertThat(large[1]).as("rays of the larger render").isGreaterThan(small[1] * 3);
        return (double) (large[0] - small[0]) / (large[1] - small[1]);
    }

    /** @return {bytes allocated by the render, rays traced} */
    private static long[] render(Scene scene, AntiAliasing mode, boolean lens, int nx, int ny) {
        Camera.Builder builder = TestScenes.camera(scene, new ImageWriter("allocation", nx, ny)).setAntiAliasing(mode)
                .setMultithreading(0);
        if (lens) builder.setDepthOfField(10, 0.2).setDepthOfFieldSamples(4);
        Camera camera = builder.build();
        long before = THREADS.getCurrentThreadAllocatedBytes();
        RenderStats stats = camera.render();
        long after = THREADS.getCurrentThreadAllocatedBytes();
        return new long[] { after - before, stats.totalRays() };
    }

    @Test
    @DisplayName("at most 16 bytes per ray for the library's shapes and lights, with every effect, without and with anti-aliasing")
    void libraryPathAllocatesNothingPerRay() {
        assumeTrue(THREADS != null, "this JVM counts no per-thread allocation");
        for (AntiAliasing mode : List.of(AntiAliasing.NONE, AntiAliasing.ADAPTIVE))
            assertThat(bytesPerRay(AllocationTest::everyShape, mode)).as("%s", mode).isLessThanOrEqualTo(BOUND);
    }

    @Test
    @DisplayName("at most 16 bytes per ray with depth of field: stratified lens points for NONE, CORNERS and ADAPTIVE")
    void lensSamplersAllocateNothingPerRay() {
        assumeTrue(THREADS != null, "this JVM counts no per-thread allocation");
        for (AntiAliasing mode : List.of(AntiAliasing.NONE, AntiAliasing.CORNERS, AntiAliasing.ADAPTIVE))
            assertThat(bytesPerRay(AllocationTest::everyShape, mode, true)).as("%s with a lens", mode)
                    .isLessThanOrEqualTo(BOUND);
    }

    /** A shape written as a course student would: only the list hook, answered with new objects. */
    private static final class Ball extends Geometry {
        private final Sphere surface = new Sphere(new Point(0, 0, -1), 1.5);

        @Override
        public Vector getNormal(Point point) {
            return surface.getNormal(point);
        }

        @Override
        protected List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance) {
            List<GeoPoint> found = surface.findGeoIntersections(ray, maxDistance);
            return found == null ? null : found.stream().map(gp -> new GeoPoint(this, gp.point)).toList();
        }
    }

    @Test
    @DisplayName("guard: a user's shape answering with lists shows up above the bound (the meter sees allocation)")
    void userShapeAllocates() {
        assumeTrue(THREADS != null, "this JVM counts no per-thread allocation");
        Supplier<Scene> withBall = () -> {
            Scene scene = everyShape();
            scene.geometries.add(new Ball().setMaterial(new Material().setKd(0.5)));
            return scene;
        };
        assertThat(bytesPerRay(withBall, AntiAliasing.NONE)).isGreaterThan(BOUND);
    }
}
