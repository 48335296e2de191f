package renderer;

import java.util.function.Supplier;

import primitives.Rgb;

/**
 * {@link AntiAliasing#RANDOM}: the pixel cut into columns × rows cells, one ray through a random
 * point of each cell (jittered, so the samples are stratified and never line up).
 */
final class GridSampler extends PixelSampler {
    private final int columns;
    private final int rows;
    private final Rgb pixel = new Rgb();

    private GridSampler(Plan plan, Estimator estimator) {
        super(plan.seed, plan.lens, estimator);
        this.columns = plan.columns;
        this.rows = plan.rows;
    }

    /**
     * @param seed    the render's seed
     * @param lens    whether the view has a lens (each sample then takes a lens point)
     * @param columns cells across a pixel
     * @param rows    cells down a pixel
     */
    record Plan(long seed, boolean lens, int columns, int rows) implements SamplerPlan {
        @Override
        public AntiAliasing mode() {
            return AntiAliasing.RANDOM;
        }

        @Override
        public long maxSamplesPerPixel() {
            return samplesPerPixel(columns, rows);
        }

        @Override
        public int tileSize() {
            return 16;
        }

        @Override
        public Supplier<PixelSampler> samplers(Estimator estimator, int tileSize, int x0, int y0, int x1, int y1) {
            return () -> new GridSampler(this, estimator);
        }

        @Override
        public String describe() {
            return "RANDOM " + columns + "x" + rows;
        }
    }

    /** Camera rays per pixel: one per cell, whatever the lens. */
    static long samplesPerPixel(int columns, int rows) {
        return (long) columns * rows;
    }

    @Override
    Rgb sample(int x, int y, TraceContext ctx) {
        Rgb sum = pixel.setZero();
        SampleStream rnd = ctx.random;
        for (int row = 0, s = 0; row < rows; ++row) {
            for (int col = 0; col < columns; ++col, ++s) {
                rnd.reset(seed, x, y, s);
                double px = x + (col + rnd.nextDouble()) / columns;
                double py = y + (row + rnd.nextDouble()) / rows;
                sum.add(trace(px, py, ctx));
            }
        }
        return sum.reduce(columns * rows);
    }
}
