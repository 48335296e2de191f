package renderer;

/**
 * {@link AntiAliasing#NONE}: rays through the pixel centre: one, or with depth of field one per
 * lens sample (each from its own stream).
 */
final class CenterSampler extends PixelSampler {
    private final int samples;

    CenterSampler(Sampling sampling, View.CameraRays rays, RayTracerBase tracer) {
        super(sampling, rays, tracer);
        this.samples = (int) samplesPerPixel(rays.hasLens(), sampling.lensSamples());
    }

    /** Camera rays per pixel: the lens samples with depth of field, else 1. */
    static long samplesPerPixel(boolean depthOfField, int lensSamples) {
        return depthOfField ? lensSamples : 1;
    }

    @Override
    void sample(int x, int y, TraceContext ctx) {
        if (samples == 1) {
            ctx.random.reset(seed, x, y, 0);
            trace(x + 0.5, y + 0.5, ctx);
            return;
        }
        double r = 0, g = 0, b = 0;
        for (int s = 0; s < samples; ++s) {
            ctx.random.reset(seed, x, y, s);
            trace(x + 0.5, y + 0.5, ctx);
            r += ctx.r;
            g += ctx.g;
            b += ctx.b;
        }
        ctx.r = r / samples;
        ctx.g = g / samples;
        ctx.b = b / samples;
    }
}
