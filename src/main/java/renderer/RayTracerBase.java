package renderer;

import java.util.Objects;

import geometries.Hit;
import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/** Computes the colour a ray sees in a scene. */
public abstract class RayTracerBase {
    /** The scene traced; read-only while rendering. */
    protected final Scene scene;

    /** @param scene the scene rays are traced in; read, never changed */
    protected RayTracerBase(Scene scene) {
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
     * The render loop's entry: traces the camera ray held in {@link TraceContext#cameraRay()}
     * (as doubles) and leaves the colour seen in {@code ctx.r, ctx.g, ctx.b}, using the worker's
     * scratch state and the sample's random stream. Tracers outside this package simply get
     * {@link #traceRay(Ray)}, with the ray as an object.
     */
    void traceRay(TraceContext ctx) {
        Hit h = ctx.cameraRay();
        Color c = traceRay(new Ray(new Point(h.headX(), h.headY(), h.headZ()),
                new Vector(h.directionX(), h.directionY(), h.directionZ())));
        ctx.r = c.getR();
        ctx.g = c.getG();
        ctx.b = c.getB();
    }

    /** A short description of the tracer's settings for the render summary. */
    String describe() {
        return getClass().getSimpleName();
    }
}
