package app.spark;

import java.io.Serializable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import renderer.RegionRenderer;

/**
 * The frames of a job: the value the driver broadcasts. Spark deserializes a broadcast value
 * once per executor JVM and hands every task there the same instance, so the parsed scenes it
 * caches (a prepared region renderer per frame) are made once per JVM, not once per task. Tasks
 * of one JVM run concurrently: they share a frame's renderer, and each gets its tile's pixels.
 */
final class FrameSet implements Serializable {
    private static final long serialVersionUID = 1L;
    /**
     * Frames kept parsed per JVM. Tiles are scheduled frame by frame, so a JVM works on one or
     * two frames at a time; a few more absorb retries, and the bound keeps a long animation from
     * holding every frame's scene.
     */
    private static final int CACHED_FRAMES = 4;

    private final List<Frame> frames;
    /** Per JVM, made on first use: frame index → its prepared renderer (least recently used first). */
    private transient Map<Integer, RegionRenderer> cache;

    FrameSet(List<Frame> frames) {
        this.frames = List.copyOf(frames);
    }

    List<Frame> frames() {
        return frames;
    }

    /**
     * Renders a tile with the library's own render loop and returns its pixels.
     *
     * @throws IllegalStateException when the frame's scene cannot be parsed (see
     *                               {@link Frame#executorRenderer()})
     */
    TilePixels render(Tile tile) {
        RegionRenderer.Pixels p = prepared(tile.frame()).render(tile.x0(), tile.y0(), tile.x1(), tile.y1());
        return new TilePixels(tile, p.rgb(), p.stats().seconds(), p.stats().totalRays());
    }

    /** The frame's prepared renderer, parsed on the first use in this JVM. */
    private synchronized RegionRenderer prepared(int frame) {
        if (cache == null) cache = new LinkedHashMap<>(CACHED_FRAMES * 2, 0.75f, true) {
            private static final long serialVersionUID = 1L;

            @Override
            protected boolean removeEldestEntry(Map.Entry<Integer, RegionRenderer> eldest) {
                return size() > CACHED_FRAMES;
            }
        };
        RegionRenderer r = cache.get(frame);
        if (r == null) {
            r = frames.get(frame).executorRenderer();
            cache.put(frame, r);
        }
        return r;
    }
}
