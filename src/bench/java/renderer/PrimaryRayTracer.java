package renderer;

import geometries.Bvh;
import geometries.Hit;
import geometries.LeanQueries;
import primitives.Color;
import primitives.Ray;
import scene.Scene;

/**
 * The tracing core alone, for comparison with Embree's primary-ray figure: each camera ray is one
 * closest-hit query through the BVH, with no shading, shadow or secondary rays. White where
 * something is hit, black elsewhere (so the picture still shows the scene's silhouette).
 *
 * <p>It runs through the library's own render loop (tiles, threads, ray generation), so the rate
 * it gives includes generating the camera rays, as a render's would. In package {@code renderer}
 * (apart from the other benchmarks) because the render loop's doubles entry it overrides,
 * {@code traceRay(Hit)}, is package-private: out of a student's code completion.
 */
public final class PrimaryRayTracer extends RayTracerBase {
    private static final Color WHITE = new Color(255, 255, 255);
    private final Bvh bvh;
    // One hit record per thread for the Ray form; the render loop's form uses the camera's record.
    private final ThreadLocal<Hit> hits = ThreadLocal.withInitial(Hit::new);

    /** @param scene the scene whose geometries one tree indexes, built here */
    public PrimaryRayTracer(Scene scene) {
        super(scene);
        this.bvh = Bvh.build(scene.geometries);
    }

    @Override
    public Color traceRay(Ray ray) {
        return LeanQueries.closestHit(bvh, ray, hits.get().reset(Double.POSITIVE_INFINITY)) ? WHITE : Color.BLACK;
    }

    /** The render loop's form: the camera's record goes straight to the walk, no ray object. */
    @Override
    Color traceRay(Hit ray) {
        return LeanQueries.closestHit(bvh, ray.reset(Double.POSITIVE_INFINITY)) ? WHITE : Color.BLACK;
    }
}
