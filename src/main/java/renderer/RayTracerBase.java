package renderer;

import java.util.Objects;

import geometries.Hit;
import primitives.Color;
import primitives.CourseClassGuard;
import primitives.Point;
import primitives.Ray;
import primitives.Rgb;
import primitives.Vector;
import scene.Scene;

/** Computes the colour a ray sees in a scene. */
public abstract class RayTracerBase {
    /** The scene traced; read-only while rendering. */
    protected final Scene scene;

    /** @param scene the scene rays are traced in; read, never changed */
    protected RayTracerBase(Scene scene) {
        CourseClassGuard.check();
        this.scene = Objects.requireNonNull(scene, "scene");
    }

    /**
     * @param ray a camera ray (or any ray: a tracer may be called directly)
     * @return the colour seen along {@code ray}, on the 0..255 scale, unclamped
     */
    public abstract Color traceRay(Ray ray);

    /**
     * Called once on the render's thread before the workers start: the scene is complete now,
     * so this is where acceleration structures are built.
     */
    void prepare() {
    }

    /**
     * The colour seen along the camera ray that {@code ray} holds as doubles (see
     * {@link Hit#setRay(double, double, double, double, double, double)}): how the render loop
     * calls a tracer of another package, with no {@link Ray} object per ray. By default it builds
     * the {@link Ray} and calls {@link #traceRay(Ray)}; a tracer that queries the scene itself may
     * override it and pass the record straight to {@code Intersectable.closestHit(Hit)}. The
     * record belongs to the calling worker for the duration of the call: its hit fields are free
     * to use, its ray is the camera's.
     *
     * @param ray the record holding the camera ray
     * @return the colour seen along the ray, on the 0..255 scale, unclamped
     */
    protected Color traceRay(Hit ray) {
        return traceRay(new Ray(new Point(ray.headX(), ray.headY(), ray.headZ()),
                new Vector(ray.directionX(), ray.directionY(), ray.directionZ())));
    }

    /**
     * The render loop's entry: traces the camera ray held in {@link TraceContext#cameraRay()},
     * using the worker's scratch state and the sample's random stream. Tracers outside this
     * package get {@link #traceRay(Hit)}.
     *
     * @return the colour seen, on the 0..255 scale: the context's {@link TraceContext#cameraColour()},
     *         valid until its next trace
     */
    Rgb traceRay(TraceContext ctx) {
        return ctx.cameraColour().set(traceRay(ctx.cameraRay()));
    }

    /** A short description of the tracer's settings for the render summary. */
    String describe() {
        return getClass().getSimpleName();
    }
}
