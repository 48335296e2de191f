package renderer;

import primitives.Color;

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
    public Color sample(int x, int y, TraceContext ctx) {
        if (samples == 1) {
            ctx.random.reset(camera.seed(), x, y, 0);
            return camera.trace(x + 0.5, y + 0.5, ctx);
        }
        double r = 0, g = 0, b = 0;
        for (int s = 0; s < samples; ++s) {
            ctx.random.reset(camera.seed(), x, y, s);
            Color c = camera.trace(x + 0.5, y + 0.5, ctx);
            r += c.getR();
            g += c.getG();
            b += c.getB();
        }
        return new Color(r / samples, g / samples, b / samples);
    }
}
