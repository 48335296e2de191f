package renderer;

import primitives.Rgb;

/**
 * A sampling strategy: the colour of one pixel from as many camera samples as it chooses. One
 * instance per worker thread (it may keep scratch state); the render loop calls
 * {@link #beginTile} before the pixels of each tile.
 */
interface PixelSampler {
    /** Announces the tile of columns [x0, x1) and rows [y0, y1) about to be sampled. */
    default void beginTile(int x0, int y0, int x1, int y1) {
    }

    /** Samples pixel (column x, row y): @return its colour, valid until the next call */
    Rgb sample(int x, int y, TraceContext ctx);
}
