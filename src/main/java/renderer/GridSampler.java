package renderer;

import primitives.Rgb;

/**
 * {@link AntiAliasing#RANDOM}: the pixel cut into columns × rows cells, one ray through a random
 * point of each cell (jittered, so the samples are stratified and never line up).
 */
final class GridSampler implements PixelSampler {
    private final Camera camera;
    private final int columns;
    private final int rows;
    private final Rgb pixel = new Rgb();

    GridSampler(Camera camera, int columns, int rows) {
        this.camera = camera;
        this.columns = columns;
        this.rows = rows;
    }

    @Override
    public Rgb sample(int x, int y, TraceContext ctx) {
        Rgb sum = pixel.setZero();
        SampleStream rnd = ctx.random;
        for (int row = 0, s = 0; row < rows; ++row) {
            for (int col = 0; col < columns; ++col, ++s) {
                rnd.reset(camera.seed(), x, y, s);
                double px = x + (col + rnd.nextDouble()) / columns;
                double py = y + (row + rnd.nextDouble()) / rows;
                sum.add(camera.trace(px, py, ctx));
            }
        }
        return sum.reduce(columns * rows);
    }
}
