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
import geometries.LeanQueries;
import lighting.LightSource;
import primitives.Point;
import primitives.Ray;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;
import scene.samples.ScalingScene;
import scene.samples.TeapotScene;

/**
 * The BVH walks, in ns per ray, over a fixed scene: {@code teapot} ({@link TeapotScene}: 992
 * triangles and 400 spheres, the kind of scene Embree's ~37 Mrays/s figure is for) or
 * {@code scaling-N} ({@link ScalingScene}: N spheres + N triangles, its default seed):
 * <ul>
 * <li>{@code closestHit}: {@link #RAYS} camera rays of a 64×64 view through the scene's camera;</li>
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
    private static final HitVisitor STOP_AT_FIRST = (geometry, t) -> false;

    @Param({ "teapot", "scaling-1000", "scaling-100000" })
    public String scene;

    private Bvh bvh;
    private Ray[] cameraRays;
    private Ray[] shadowRays;
    private double[] shadowDistances;
    private final Hit hit = new Hit();
    private int visited;
    private final HitVisitor countAll = (geometry, t) -> {
        ++visited;
        return true;
    };

    @Setup(Level.Trial)
    public void setUp() {
        Scene s;
        Camera.Builder view;
        if (scene.equals("teapot")) {
            s = TeapotScene.create();
            view = TeapotScene.camera();
        } else if (scene.startsWith("scaling-")) {
            s = ScalingScene.create(Integer.parseInt(scene.substring("scaling-".length())));
            view = ScalingScene.camera();
        } else {
            throw new IllegalArgumentException("unknown scene '" + scene + "': teapot or scaling-N");
        }
        bvh = Bvh.build(s.geometries);
        LightSource light = s.lights.get(0);
        Camera camera = view.setImageWriter(new ImageWriter("jmh", SIDE, SIDE))
                .setRayTracer(new RayTracerBasic(s)).setSummary(false).build();
        cameraRays = new Ray[RAYS];
        List<Ray> shadows = new ArrayList<>();
        List<Double> distances = new ArrayList<>();
        for (int i = 0; i < SIDE; ++i)
            for (int j = 0; j < SIDE; ++j) {
                Ray ray = camera.constructRay(SIDE, SIDE, j, i);
                cameraRays[i * SIDE + j] = ray;
                if (LeanQueries.closestHit(bvh, ray, hit.reset(Double.POSITIVE_INFINITY))) {
                    Point p = hit.point(ray);
                    shadows.add(new Ray(p, light.getL(p).scale(-1), hit.normal(p)));
                    distances.add(light.getDistance(p));
                }
            }
        if (shadows.isEmpty()) throw new IllegalStateException("no camera ray hits the scene " + scene);
        // Exactly RAYS shadow rays (cycling through the hits) so that the per-ray figure is exact.
        shadowRays = new Ray[RAYS];
        shadowDistances = new double[RAYS];
        for (int i = 0; i < RAYS; ++i) {
            shadowRays[i] = shadows.get(i % shadows.size());
            shadowDistances[i] = distances.get(i % shadows.size());
        }
    }

    /** @return the hits, so that nothing is dead code */
    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int closestHit() {
        int hits = 0;
        for (Ray r : cameraRays)
            if (LeanQueries.closestHit(bvh, r, hit.reset(Double.POSITIVE_INFINITY))) ++hits;
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int anyHitFirst() {
        int occluded = 0;
        for (int i = 0; i < RAYS; ++i)
            if (!LeanQueries.visitHits(bvh, shadowRays[i], shadowDistances[i], STOP_AT_FIRST)) ++occluded;
        return occluded;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int anyHitAll() {
        visited = 0;
        for (int i = 0; i < RAYS; ++i) LeanQueries.visitHits(bvh, shadowRays[i], shadowDistances[i], countAll);
        return visited;
    }
}
