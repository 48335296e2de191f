package renderer;

import primitives.Rgb;

/**
 * {@link AntiAliasing#NONE}: rays through the pixel centre: one, or with depth of field one per
 * lens sample (each from its own stream).
 */
final class CenterSampler implements PixelSampler {
    private final Camera camera;
    private final int samples;
    private final Rgb pixel = new Rgb();

    CenterSampler(Camera camera, int samples) {
        this.camera = camera;
        this.samples = samples;
    }

    @Override
    public Rgb sample(int x, int y, TraceContext ctx) {
        if (samples == 1) {
            ctx.random.reset(camera.seed(), x, y, 0);
            return camera.trace(x + 0.5, y + 0.5, ctx);
        }
        Rgb sum = pixel.setZero();
        for (int s = 0; s < samples; ++s) {
            ctx.random.reset(camera.seed(), x, y, s);
            sum.add(camera.trace(x + 0.5, y + 0.5, ctx));
        }
        return sum.reduce(samples);
    }
}
