package bench.jmh;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import geometries.Bvh;
import geometries.Hit;
import geometries.HitVisitor;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;
import scene.samples.ScalingScene;

/**
 * The BVH walks over the fixed random scaling scene ({@code n} spheres + {@code n} triangles,
 * {@link ScalingScene#DEFAULT_SEED}), in ns per ray:
 * <ul>
 * <li>{@code closestHit}: {@link #RAYS} camera rays of a 64×64 view of the scene;</li>
 * <li>{@code anyHitFirst}: the shadow rays from those camera rays' hit points toward the scene's
 * light, stopping at the first occluder (an opaque shadow query);</li>
 * <li>{@code anyHitAll}: the same shadow rays visiting every occluder (the transparent-shadow
 * walk, which cannot stop early).</li>
 * </ul>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class BvhBench {
    static final int SIDE = 64;
    static final int RAYS = SIDE * SIDE;
    /** Toward the scaling scene's directional light (the opposite of its direction). */
    private static final Vector TO_LIGHT = new Vector(1, 2, 1.5);
    private static final HitVisitor STOP_AT_FIRST = (geometry, t) -> false;

    @Param({ "1000", "100000" })
    public int n;

    private Bvh bvh;
    private Ray[] cameraRays;
    private Ray[] shadowRays;
    private final Hit hit = new Hit();
    private int visited;
    private final HitVisitor countAll = (geometry, t) -> {
        ++visited;
        return true;
    };

    @Setup(Level.Trial)
    public void setUp() {
        Scene scene = ScalingScene.create(n);
        bvh = Bvh.build(scene.geometries);
        Camera camera = ScalingScene.camera().setImageWriter(new ImageWriter("jmh", SIDE, SIDE))
                .setRayTracer(new RayTracerBasic(scene)).setSummary(false).build();
        cameraRays = new Ray[RAYS];
        List<Ray> shadows = new ArrayList<>();
        for (int i = 0; i < SIDE; ++i)
            for (int j = 0; j < SIDE; ++j) {
                Ray ray = camera.constructRay(SIDE, SIDE, j, i);
                cameraRays[i * SIDE + j] = ray;
                if (bvh.closestHit(ray, hit.reset(Double.POSITIVE_INFINITY))) {
                    Point p = hit.point(ray);
                    shadows.add(new Ray(p, TO_LIGHT, hit.normal(p)));
                }
            }
        if (shadows.isEmpty()) throw new IllegalStateException("no camera ray hits the scaling scene of n = " + n);
        // Exactly RAYS shadow rays (cycling through the hits) so that the per-ray figure is exact.
        shadowRays = new Ray[RAYS];
        for (int i = 0; i < RAYS; ++i) shadowRays[i] = shadows.get(i % shadows.size());
    }

    /** @return the hits, so that nothing is dead code */
    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int closestHit() {
        int hits = 0;
        for (Ray r : cameraRays)
            if (bvh.closestHit(r, hit.reset(Double.POSITIVE_INFINITY))) ++hits;
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int anyHitFirst() {
        int occluded = 0;
        for (Ray r : shadowRays)
            if (!bvh.visitHits(r, Double.POSITIVE_INFINITY, STOP_AT_FIRST)) ++occluded;
        return occluded;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int anyHitAll() {
        visited = 0;
        for (Ray r : shadowRays) bvh.visitHits(r, Double.POSITIVE_INFINITY, countAll);
        return visited;
    }
}
