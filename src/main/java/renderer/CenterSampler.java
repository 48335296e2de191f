package renderer;

/**
 * {@link AntiAliasing#NONE}: rays through the pixel centre: one, or with depth of field one per
 * lens sample (each from its own stream).
 */
final class CenterSampler implements PixelSampler {
    private final Camera camera;
    private final int samples;

    CenterSampler(Camera camera, int samples) {
        this.camera = camera;
        this.samples = samples;
    }

    @Override
    public void sample(int x, int y, TraceContext ctx) {
        if (samples == 1) {
            ctx.random.reset(camera.seed(), x, y, 0);
            camera.trace(x + 0.5, y + 0.5, ctx);
            return;
        }
        double r = 0, g = 0, b = 0;
        for (int s = 0; s < samples; ++s) {
            ctx.random.reset(camera.seed(), x, y, s);
            camera.trace(x + 0.5, y + 0.5, ctx);
            r += ctx.r;
            g += ctx.g;
            b += ctx.b;
        }
        ctx.r = r / samples;
        ctx.g = g / samples;
        ctx.b = b / samples;
    }
}
