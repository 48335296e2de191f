package renderer;

/**
 * Renders rectangles of one camera's image, for a render split into parts that are rendered
 * apart (on the machines of a cluster) and assembled: each pixel of a rectangle gets exactly the
 * value a whole-image {@link Camera#render()} gives it, because every random number derives from
 * (seed, pixel, sample) and the lattice of CORNERS/ADAPTIVE is keyed by global coordinates. It
 * runs the camera's own render loop (sampling, tiles, threads) on the rectangle and writes the
 * pixels into the camera's image writer, where the caller reads them back with
 * {@link ImageWriter#getRgb(int, int)}.
 *
 * <p>The scene is prepared (its BVH built) once, when this renderer is made, not per rectangle:
 * the scene must not change afterwards. Several threads may render disjoint rectangles at once
 * (they write different pixels); progress lines and the summary of {@link Camera#render()} are
 * not printed.
 */
public final class RegionRenderer {
    private final Camera camera;
    private final int nX, nY;

    RegionRenderer(Camera camera) {
        this.camera = camera;
        this.nX = camera.imageWriter().getNx();
        this.nY = camera.imageWriter().getNy();
        camera.rayTracer().prepare();
    }

    /**
     * Renders the pixels of columns [x0, x1) and rows [y0, y1) into the camera's image writer.
     *
     * @param x0 first column, 0 ≤ x0 &lt; x1
     * @param y0 first row, 0 ≤ y0 &lt; y1
     * @param x1 the column after the last, at most the image width
     * @param y1 the row after the last, at most the image height
     * @return what the rectangle's render did (its pixels, rays and wall time; no preparation)
     * @throws IllegalArgumentException naming the rectangle when it is empty or not inside the image
     * @throws java.util.concurrent.CancellationException when the calling thread is interrupted
     */
    public RenderStats render(int x0, int y0, int x1, int y1) {
        if (x0 < 0 || y0 < 0 || x1 > nX || y1 > nY || x0 >= x1 || y0 >= y1)
            throw new IllegalArgumentException("region [" + x0 + "," + x1 + ")x[" + y0 + "," + y1
                    + ") must be a non-empty rectangle inside the " + nX + "x" + nY + " image");
        return new RenderLoop(camera, x0, y0, x1, y1).run(false);
    }
}
