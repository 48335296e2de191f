package renderer;

import java.util.Objects;

import geometries.Hit;
import primitives.Color;
import primitives.CourseClassGuard;
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
        CourseClassGuard.check();
        this.scene = Objects.requireNonNull(scene, "scene");
    }

    /**
     * @param ray a camera ray (or any ray: a tracer may be called directly)
     * @return the colour seen along {@code ray}, on the 0..255 scale, unclamped
     */
    public abstract Color traceRay(Ray ray);

    /** The scene as this tracer was last prepared for it; null before, or after a setting that the preparation depends on changed. */
    private SceneStamp prepared;

    /**
     * Builds what tracing needs from the scene as it is now (acceleration structures, checked
     * lights). Entered only through {@link #prepareFor}, which holds the tracer's lock.
     *
     * @return the tracing over what was built; by default the course's {@link #traceRay(Hit)}
     */
    PreparedTracer prepare() {
        return ctx -> ctx.cameraColour().set(traceRay(ctx.cameraRay()));
    }

    /**
     * The one way into {@link #prepare()}: a render prepares for the scene it stamped as it
     * started (and compares the stamp at its end), on its own thread before the workers start;
     * a region renderer once for all its regions; a direct call when the scene changed since.
     *
     * @param scene the scene's state now, the one the tracer is prepared for
     * @return the tracing prepared for that state, which the render holds
     */
    final synchronized PreparedTracer prepareFor(SceneStamp scene) {
        prepared = null; // until prepare() succeeds: a failed preparation is tried again
        PreparedTracer tracing = prepare();
        prepared = scene;
        return tracing;
    }

    /**
     * Prepares for a call outside a render: the first time, and again when the scene's lists,
     * their shapes or its lights changed since the last preparation ({@link SceneStamp}), or a
     * setting the preparation depends on did.
     */
    final synchronized void prepareIfChanged() {
        if (prepared == null || prepared.changed()) prepareFor(SceneStamp.of(this, "a direct traceRay call"));
    }

    /**
     * The parts of the scene a render reads, as they are now: what {@link SceneStamp} compares
     * at the start and the end of a render. Read here because this class holds the scene (the
     * course's constructor), so that no other class of the renderer needs the course's
     * {@code Scene}.
     */
    final SceneStamp.Parts sceneParts() {
        return new SceneStamp.Parts(scene.name, scene.geometries, scene.lights, scene.background, scene.ambientLight);
    }

    /** @return the name of the scene traced ({@code Scene.name}), for reports; read here for the reason above */
    final String sceneName() {
        return scene.name;
    }

    /** Makes the next call outside a render prepare again: a setting the preparation depends on changed. */
    final synchronized void forgetPreparation() {
        prepared = null;
    }

    /**
     * A worker's scratch state for this tracer: the camera ray's record, the random stream and
     * what the tracer keeps per thread. One per render thread, never shared.
     */
    TraceContext newContext() {
        return new TraceContext(0, 0);
    }

    /**
     * Holds the sampling's most camera rays per pixel, times the rays this tracer may trace per
     * camera ray, to {@link RayBudget#MAX_RAYS_PER_PIXEL}; a tracer of another kind traces one.
     *
     * @param sampling what the render's sampling takes
     * @throws IllegalArgumentException naming the factors and their product when it is over
     */
    void requireRayBudget(SamplerPlan sampling) {
        RayBudget.requireCameraRays(sampling.mode(), sampling.maxSamplesPerPixel());
    }

    /**
     * The colour seen along the camera ray that {@code ray} holds as doubles (see {@code RayHit}):
     * how the render loop calls a tracer other than the library's own, with no {@link Ray} object
     * per ray. By default it builds the {@link Ray} and calls {@link #traceRay(Ray)}, which is
     * what a student's tracer overrides; a tracer of package {@code renderer} that queries the
     * scene itself may override this one and pass the record straight to
     * {@code LeanQueries.closestHit(Intersectable, Hit)}. Package-private, so that it stays out of
     * the code completion of a student's subclass. The record belongs to the calling worker for
     * the duration of the call: its hit fields are free to use, its ray is the camera's.
     *
     * @param ray the record holding the camera ray
     * @return the colour seen along the ray, on the 0..255 scale, unclamped
     */
    Color traceRay(Hit ray) {
        return traceRay(new Ray(new Point(ray.headX(), ray.headY(), ray.headZ()),
                new Vector(ray.directionX(), ray.directionY(), ray.directionZ())));
    }

    /** @return how the tracer finds hits, after a comma, for the end of the summary line; "" when there is nothing to say */
    String walk() {
        return "";
    }

    /** @return the tracer's settings in words, for the render's summary line */
    String describe() {
        return getClass().getSimpleName();
    }
}
