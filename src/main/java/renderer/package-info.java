/**
 * From a scene to a picture: {@link renderer.Camera} (built by {@link renderer.Camera.Builder},
 * which validates every setting), the tracer {@link renderer.RayTracerBasic}, the image
 * {@link renderer.ImageWriter} and what a render did, {@link renderer.RenderStats}. One render
 * loop serves every anti-aliasing mode, depth of field and thread count; every random number
 * comes from a stream keyed by (seed, pixel, sample), so images do not depend on threads.
 */
package renderer;
