package renderer;

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
}
