package app.spark;

import java.io.Serializable;

/**
 * What a task sends back for a tile: its pixels, packed 0xRRGGBB row by row, and what it cost.
 *
 * @param tile    the tile rendered
 * @param rgb     the tile's pixels, {@code tile.pixels()} of them
 * @param seconds wall time of the tile's render on the executor (without parsing the scene)
 * @param rays    rays traced for the tile, of every kind
 */
record TilePixels(Tile tile, int[] rgb, double seconds, long rays) implements Serializable {
}
