package renderer;

/**
 * Internal, for {@code app.spark}: renders rectangles of one camera's image, for a render split
 * into parts that are rendered apart (on the machines of a cluster) and assembled: each pixel of a
 * rectangle gets exactly the value a whole-image {@link Camera#render()} gives it, because every
 * random number derives from (seed, pixel, sample) and the lattice of CORNERS/ADAPTIVE is keyed by
 * global coordinates. It runs the camera's own render loop (sampling, tiles, threads) on the
 * rectangle and returns the rectangle's pixels; no image of the whole size is needed.
 *
 * <p>The scene is prepared (its BVH built) once, when this renderer is made, not per rectangle:
 * the scene must not change afterwards. Several threads may render rectangles at once; progress
 * lines and the summary of {@link Camera#render()} are not printed.
 *
 * @hidden internal: public only for app.spark's executors
 */
public final class RegionRenderer {
    private final RenderLoop loop;
    /** The tracer as this renderer prepared it, once, for every rectangle. */
    private final PreparedTracer prepared;
    private final String name;
    private final int nX, nY;

    /**
     * A rectangle's pixels and what its render did.
     *
     * @param rgb   the pixels, 0xRRGGBB, row by row: (x1 - x0) × (y1 - y0) of them, pixel (x, y)
     *              at index (y - y0)·(x1 - x0) + (x - x0); the caller's to keep
     * @param stats what the rectangle's render did (its pixels, rays and wall time; no preparation)
     *
     * @hidden internal: public only for app.spark
     */
    public record Pixels(int[] rgb, RenderStats stats) {
    }

    /**
     * A renderer of rectangles of a camera's image; it prepares the scene now, once.
     *
     * @param camera the camera whose image is rendered in parts (its image writer only names the render)
     * @return a new region renderer over the camera
     */
    public static RegionRenderer of(Camera camera) {
        return new RegionRenderer(camera.setup(), camera.imageWriter().getImageName());
    }

    /**
     * A renderer of rectangles of the image {@code camera} would render, checked as its
     * {@code build()} checks it, without allocating the image: what a cluster's executor renders its
     * tiles with. It prepares the scene now, once.
     *
     * @param camera the builder whose settings are rendered
     * @return a new region renderer over those settings
     * @throws java.util.MissingResourceException as {@link Camera.Builder#build()}
     * @throws IllegalArgumentException           as {@link Camera.Builder#build()}
     */
    public static RegionRenderer of(Camera.Builder camera) {
        return camera.regionRenderer();
    }

    /**
     * Prepares the tracer for its scene, once for every rectangle.
     *
     * @param name labels worker threads and messages
     */
    RegionRenderer(RenderSetup setup, String name) {
        this.loop = setup.loop(null);
        this.name = name;
        this.nX = setup.view().plane().nX();
        this.nY = setup.view().plane().nY();
        this.prepared = setup.tracer().prepareFor(SceneStamp.of(setup.tracer(), name));
    }

    /**
     * Renders the pixels of columns [x0, x1) and rows [y0, y1).
     *
     * @param x0 first column, 0 ≤ x0 &lt; x1
     * @param y0 first row, 0 ≤ y0 &lt; y1
     * @param x1 the column after the last, at most the image width
     * @param y1 the row after the last, at most the image height
     * @return the rectangle's pixels and what its render did
     * @throws IllegalArgumentException naming the rectangle when it is empty or not inside the image
     * @throws java.util.concurrent.CancellationException when the calling thread is interrupted
     */
    public Pixels render(int x0, int y0, int x1, int y1) {
        if (x0 < 0 || y0 < 0 || x1 > nX || y1 > nY || x0 >= x1 || y0 >= y1)
            throw new IllegalArgumentException("region [" + x0 + "," + x1 + ")x[" + y0 + "," + y1
                    + ") must be a non-empty rectangle inside the " + nX + "x" + nY + " image");
        return loop.region(name, prepared, x0, y0, x1, y1);
    }
}
