package renderer;

import java.util.concurrent.atomic.AtomicIntegerArray;

/**
 * The pixel corners on the borders between one pass's tiles, traced once for the whole pass and
 * shared by its workers' {@link LatticeSampler}s. Each lattice sampler caches the points of its
 * current tile only, so a corner on a border between two tiles was traced by both: about 2 / tile
 * side of a lattice render's base of one camera ray per pixel (the Sunflow scene at 600×600,
 * ADAPTIVE depth 3 in tiles of 32: 634,199 camera rays, 610,837 with the whole image as one tile).
 * A point's colour depends on its lattice coordinates alone, so the value traced in one tile is
 * the value the other would trace: the image is the same, and each border corner now takes one ray.
 *
 * <p>Only pixel corners: the finer points of a subdivision that fall on a border, fewer than one
 * in ten of the repeated ones there, are still traced by both tiles. A pass whose borders would
 * hold more than {@link #MAX_POINTS} corners (a lattice of 64 points a pixel side over more than
 * about 1500 × 1500 pixels) has none: its borders are traced twice, as before.
 *
 * <p>Each corner is traced by the first worker that needs it; another worker that needs it
 * meanwhile waits for its colour rather than tracing it too, so a render's ray count does not
 * depend on how its workers met (tiles are claimed far apart, {@link RenderLoop}, so they rarely
 * do). A worker whose trace fails gives the corner back, and a waiting one traces it.
 */
final class LatticeSeams {
    /** The most corners a pass keeps: 28 MB of colours and states. */
    static final int MAX_POINTS = 1 << 20;
    private static final int FREE = 0, TRACING = 1, DONE = 2;
    /** Spins before a waiting worker yields its processor to the one tracing the corner. */
    private static final int SPINS = 64;
    private final int x0, y0, width, height, tile;
    /**
     * Corners on the vertical borders (height + 1 each), before those of the horizontal ones
     * (width + 1 each): where two borders cross, the corner is the vertical one's, and its slot in
     * the horizontal one stays unused.
     */
    private final int vertical;
    /** Red, green and blue of each corner, valid once its state is {@link #DONE}. */
    private final double[] rgb;
    private final AtomicIntegerArray state;

    private LatticeSeams(int x0, int y0, int width, int height, int tile, int points) {
        this.x0 = x0;
        this.y0 = y0;
        this.width = width;
        this.height = height;
        this.tile = tile;
        this.vertical = ((width - 1) / tile) * (height + 1);
        this.rgb = new double[3 * points];
        this.state = new AtomicIntegerArray(points);
    }

    /**
     * The borders of a pass over the pixels [x0, x1) × [y0, y1) in tiles of {@code tile} pixels
     * from (x0, y0).
     *
     * @return the pass's seams, or null when it has a single tile or more than {@link #MAX_POINTS}
     *         corners on its borders
     */
    static LatticeSeams of(int x0, int y0, int x1, int y1, int tile) {
        int width = x1 - x0, height = y1 - y0;
        long points = (long) ((width - 1) / tile) * (height + 1) + (long) ((height - 1) / tile) * (width + 1);
        return points == 0 || points > MAX_POINTS ? null : new LatticeSeams(x0, y0, width, height, tile, (int) points);
    }

    /**
     * @return the index of pixel corner (x, y) (the top-left corner of pixel (x, y)) on a border
     *         between two tiles, or −1 when it is inside a tile or on the pass's outer edge
     */
    int index(int x, int y) {
        int dx = x - x0, dy = y - y0;
        if (dx > 0 && dx < width && dx % tile == 0) return (dx / tile - 1) * (height + 1) + dy;
        if (dy > 0 && dy < height && dy % tile == 0) return vertical + (dy / tile - 1) * (width + 1) + dx;
        return -1;
    }

    /**
     * Takes corner {@code s} for tracing, or waits until the worker that took it has its colour.
     *
     * @return true: the caller traces the corner, then {@link #publish}es it (or {@link #release}s
     *         it when the trace fails); false: its colour is ready ({@link #red} and the others)
     */
    boolean claim(int s) {
        for (int spins = 0; ; ++spins) {
            int st = state.get(s);
            if (st == DONE) return false;
            if (st == FREE && state.compareAndSet(s, FREE, TRACING)) return true;
            if (spins < SPINS) Thread.onSpinWait();
            else Thread.yield();
        }
    }

    /** Gives claimed corner {@code s} its colour, for every worker from now on. */
    void publish(int s, double r, double g, double b) {
        rgb[3 * s] = r;
        rgb[3 * s + 1] = g;
        rgb[3 * s + 2] = b;
        state.set(s, DONE); // a volatile write: the colour is seen by whoever reads DONE
    }

    /** Gives back claimed corner {@code s} untraced (the trace failed): the next to need it traces it. */
    void release(int s) {
        state.set(s, FREE);
    }

    /** @return the number of corners kept: their indices are 0 to size − 1 */
    int size() {
        return state.length();
    }

    double red(int s) {
        return rgb[3 * s];
    }

    double green(int s) {
        return rgb[3 * s + 1];
    }

    double blue(int s) {
        return rgb[3 * s + 2];
    }
}
