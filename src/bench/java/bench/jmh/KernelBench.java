package bench.jmh;

import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import geometries.BoundingBox;
import geometries.Hit;
import geometries.LeanQueries;
import geometries.Sphere;
import geometries.Triangle;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The intersection kernels one ray at a time, in ns per ray: {@code Sphere.closestHit},
 * {@code Triangle.closestHit} (the Möller–Trumbore kernel a mesh shares) and the slab test
 * {@code BoundingBox.intersects}. Each invocation runs {@link #RAYS} fixed random rays that start
 * 10 units away and aim at random points of a box 1.5 times the shape's, so that about half of
 * them hit: a realistic mix of the early-out and the full paths, with the rays read through
 * {@code Ray} objects as the renderer reads them.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class KernelBench {
    static final int RAYS = 1024;

    private Ray[] rays;
    // The same rays as flat arrays with inverted directions, as the BVH walk feeds the slab test.
    private double[] ox, oy, oz, ix, iy, iz;
    private Sphere sphere;
    private Triangle triangle;
    private BoundingBox box;
    private final Hit hit = new Hit();

    @Setup
    public void setUp() {
        sphere = new Sphere(Point.ZERO, 1);
        triangle = new Triangle(new Point(-1, -1, 0.1), new Point(1, -1, -0.1), new Point(0, 1.2, 0));
        box = new BoundingBox(-1, -1, -1, 1, 1, 1);
        SplittableRandom random = new SplittableRandom(42);
        rays = new Ray[RAYS];
        ox = new double[RAYS];
        oy = new double[RAYS];
        oz = new double[RAYS];
        ix = new double[RAYS];
        iy = new double[RAYS];
        iz = new double[RAYS];
        for (int i = 0; i < RAYS; ++i) {
            // A head on the sphere of radius 10 (uniform direction), aimed at a point of [-1.5, 1.5]³.
            double z = random.nextDouble(-1, 1), a = random.nextDouble(2 * Math.PI), s = Math.sqrt(1 - z * z);
            Point head = new Point(10 * s * Math.cos(a), 10 * s * Math.sin(a), 10 * z);
            Point target = new Point(random.nextDouble(-1.5, 1.5), random.nextDouble(-1.5, 1.5), random.nextDouble(-1.5, 1.5));
            Ray ray = new Ray(head, target.subtract(head));
            rays[i] = ray;
            Vector d = ray.getDirection();
            ox[i] = head.getX();
            oy[i] = head.getY();
            oz[i] = head.getZ();
            ix[i] = 1 / d.getX();
            iy[i] = 1 / d.getY();
            iz[i] = 1 / d.getZ();
        }
    }

    /** @return the hits, so that nothing is dead code */
    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int sphereClosestHit() {
        int hits = 0;
        for (Ray r : rays) {
            hit.reset(Double.POSITIVE_INFINITY);
            if (LeanQueries.closestHit(sphere, r, hit)) ++hits;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int triangleClosestHit() {
        int hits = 0;
        for (Ray r : rays) {
            hit.reset(Double.POSITIVE_INFINITY);
            if (LeanQueries.closestHit(triangle, r, hit)) ++hits;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int boxIntersects() {
        int hits = 0;
        for (int i = 0; i < RAYS; ++i)
            if (box.intersects(ox[i], oy[i], oz[i], ix[i], iy[i], iz[i], Double.POSITIVE_INFINITY)) ++hits;
        return hits;
    }
}
