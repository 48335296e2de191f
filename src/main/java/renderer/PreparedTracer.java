package renderer;

import geometries.LeanQueries;
import primitives.Rgb;

/**
 * A tracer prepared for one state of its scene ({@link RayTracerBase#prepareFor}): the colour of
 * the camera ray a worker's context holds. A render holds the one it prepared for all its pixels,
 * so that a later preparation (a direct {@code traceRay} call after the scene changed) never
 * reaches a render under way.
 */
@FunctionalInterface
interface PreparedTracer {
    /**
     * @param ctx the worker's scratch state, holding the camera ray ({@link TraceContext#cameraRay()})
     * @return the colour seen, on the 0..255 scale: the context's {@link TraceContext#cameraColour()},
     *         valid until its next trace
     */
    Rgb traceRay(TraceContext ctx);

    /**
     * Told, from a render's worker, that the render has at least {@link RenderLoop#LONG_RENDER_SECONDS}
     * of work left at its pace so far: worth a start-up cost that pays back over seconds (the
     * scene's tree warms its vector walk, {@link LeanQueries#expectLongWalk}). Cheap and idempotent:
     * called after each tile from then on. By default nothing.
     */
    default void expectLongRender() {
    }

    /**
     * Told, before any worker starts, how many camera rays the render traces at least: a render
     * long from the start may take the faster walk from its first ray (the scene's tree,
     * {@link LeanQueries#expectCameraRays}). By default nothing.
     *
     * @param cameraRays pixels times the fewest camera rays a pixel takes
     */
    default void expectCameraRays(long cameraRays) {
    }
}
