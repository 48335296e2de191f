package app.spark;

import java.io.Serializable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import renderer.ImageWriter;
import renderer.RegionRenderer;
import renderer.RenderStats;

/**
 * The frames of a job: the value the driver broadcasts. Spark deserializes a broadcast value
 * once per executor JVM and hands every task there the same instance, so the parsed scenes it
 * caches (a prepared camera per frame) are made once per JVM, not once per task. Tasks of one
 * JVM run concurrently: they share a frame's camera and write disjoint rectangles of its image.
 */
final class FrameSet implements Serializable {
    private static final long serialVersionUID = 1L;
    /**
     * Frames kept parsed per JVM. Tiles are scheduled frame by frame, so a JVM works on one or
     * two frames at a time; a few more absorb retries, and the bound keeps a long animation from
     * holding every frame's scene and image.
     */
    private static final int CACHED_FRAMES = 4;

    private final List<Frame> frames;
    /** Per JVM, made on first use: frame index → its prepared renderer (least recently used first). */
    private transient Map<Integer, Prepared> cache;

    /** A frame's image with the renderer (over a camera writing there) that prepared its scene once. */
    private record Prepared(ImageWriter image, RegionRenderer renderer) {
    }

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
     *                               {@link Frame#executorCamera(ImageWriter)})
     */
    TilePixels render(Tile tile) {
        Prepared p = prepared(tile.frame());
        RenderStats stats = p.renderer().render(tile.x0(), tile.y0(), tile.x1(), tile.y1());
        int[] rgb = new int[tile.pixels()];
        int i = 0;
        for (int y = tile.y0(); y < tile.y1(); ++y)
            for (int x = tile.x0(); x < tile.x1(); ++x) rgb[i++] = p.image().getRgb(x, y);
        return new TilePixels(tile, rgb, stats.seconds(), stats.totalRays());
    }

    /** The frame's prepared camera, parsed on the first use in this JVM. */
    private synchronized Prepared prepared(int frame) {
        if (cache == null) cache = new LinkedHashMap<>(CACHED_FRAMES * 2, 0.75f, true) {
            private static final long serialVersionUID = 1L;

            @Override
            protected boolean removeEldestEntry(Map.Entry<Integer, Prepared> eldest) {
                return size() > CACHED_FRAMES;
            }
        };
        Prepared p = cache.get(frame);
        if (p == null) {
            Frame f = frames.get(frame);
            ImageWriter image = f.settings().newImageWriter();
            p = new Prepared(image, f.executorCamera(image).regionRenderer());
            cache.put(frame, p);
        }
        return p;
    }
}
