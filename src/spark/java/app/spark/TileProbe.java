package app.spark;

import java.io.Serializable;

/**
 * Called in the task before each tile is rendered: nothing in production; the fault-injection
 * tests make it fail chosen task attempts to show that retries change no pixel.
 */
@FunctionalInterface
interface TileProbe extends Serializable {
    /** Does nothing. */
    TileProbe NONE = tile -> {
    };

    /** @param tile the tile about to be rendered (the task's context is {@code TaskContext.get()}) */
    void beforeTile(Tile tile);
}
