package renderer;

/**
 * {@link AntiAliasing#RANDOM}: the pixel cut into columns × rows cells, one ray through a random
 * point of each cell (jittered, so the samples are stratified and never line up).
 */
final class GridSampler extends PixelSampler {
    private final int columns;
    private final int rows;

    GridSampler(Sampling sampling, View.CameraRays rays, RayTracerBase tracer) {
        super(sampling, rays, tracer);
        this.columns = sampling.grid().columns();
        this.rows = sampling.grid().rows();
    }

    /** Camera rays per pixel: one per cell, whatever the lens. */
    static long samplesPerPixel(int columns, int rows) {
        return (long) columns * rows;
    }

    @Override
    void sample(int x, int y, TraceContext ctx) {
        double r = 0, g = 0, b = 0;
        SampleStream rnd = ctx.random;
        for (int row = 0, s = 0; row < rows; ++row) {
            for (int col = 0; col < columns; ++col, ++s) {
                rnd.reset(seed, x, y, s);
                double px = x + (col + rnd.nextDouble()) / columns;
                double py = y + (row + rnd.nextDouble()) / rows;
                trace(px, py, ctx);
                r += ctx.r;
                g += ctx.g;
                b += ctx.b;
            }
        }
        int n = columns * rows;
        ctx.r = r / n;
        ctx.g = g / n;
        ctx.b = b / n;
    }
}
