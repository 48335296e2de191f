package scene.io;

/**
 * The limits a scene file and its OBJ meshes are held to, so that a file from someone else can
 * neither exhaust the memory nor overflow a computation: each is refused at load with a message
 * that names it (docs/scene-format.md, "Limits", lists them with the render's own limits:
 * {@code Camera.maxThreads()}, {@code Camera.MAX_SAMPLES_PER_PIXEL} and
 * {@link RenderSettings#MAX_RAYS_PER_PIXEL}).
 */
public final class Limits {
    /** The largest scene file, in bytes (16 MiB): a scene file is read whole. */
    public static final long MAX_SCENE_BYTES = 16L << 20;
    /**
     * The deepest element nesting of a scene file: the format needs 4
     * ({@code <scene><geometries><sphere><material>}); deeper files are malformed.
     */
    public static final int MAX_NESTING_DEPTH = 8;
    /**
     * The largest OBJ file, in bytes (256 MiB, about 6 million triangles): OBJ files are streamed
     * line by line, and the mesh they make takes several times their size in memory.
     */
    public static final long MAX_OBJ_BYTES = 256L << 20;
    /** The longest line of an OBJ file, in characters (a face of over 3,000 corners fits). */
    public static final int MAX_OBJ_LINE_LENGTH = 65_536;
    /**
     * The largest magnitude of a number in a scene file. Together with
     * {@link #MIN_MAGNITUDE} it keeps every product the renderer forms (colour × coefficient ×
     * attenuation × samples, coordinates squared) far from the range of a double.
     */
    public static final double MAX_MAGNITUDE = 1e9;
    /**
     * The smallest positive size, distance or factor in a scene file (a radius, vp-distance, kc,
     * a spread...; coordinates may be smaller): smaller ones are below the library's precision (it
     * takes |x| &lt; 1e-10 for zero), and their inverses (an attenuation of 1 / kc) would overflow.
     */
    public static final double MIN_MAGNITUDE = 1e-9;

    private Limits() {
    }
}
