package app.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;

/**
 * A rectangle of one frame's image, the unit of work of a task: columns [x0, x1), rows [y0, y1)
 * of frame {@code frame}.
 *
 * @param frame the frame's index in the job
 * @param x0    first column
 * @param y0    first row
 * @param x1    the column after the last
 * @param y1    the row after the last
 */
record Tile(int frame, int x0, int y0, int x1, int y1) implements Serializable {
    /** @return the pixels in this tile */
    int pixels() {
        return (x1 - x0) * (y1 - y0);
    }

    /**
     * Cuts a frame of width × height pixels into square tiles of {@code side} pixels (smaller at
     * the right and bottom edges), row by row.
     */
    static List<Tile> cut(int frame, int width, int height, int side) {
        List<Tile> tiles = new ArrayList<>();
        for (int y = 0; y < height; y += side)
            for (int x = 0; x < width; x += side)
                tiles.add(new Tile(frame, x, y, Math.min(width, x + side), Math.min(height, y + side)));
        return tiles;
    }
}
