package geometries;

/**
 * What a mesh loader asks before it makes a {@link TriangleMesh}: whether a triangle of its
 * vertices would be rejected, so that it can drop or report the triangle at its line. Static, and
 * apart from {@link TriangleMesh}, so that a student completing {@code TriangleMesh.} sees the
 * shape's own methods only; the scene reader, in another package, calls it.
 *
 * @hidden internal: the mesh loader's check; a scene builds its meshes from a file or arrays
 */
public final class MeshChecks {
    private MeshChecks() {
    }

    /**
     * Whether the triangle of vertices {@code a}, {@code b}, {@code c} of {@code positions} is one
     * the {@link TriangleMesh} constructor (and {@link Triangle}) would reject: two vertices
     * coincide (within the zero tolerance per coordinate), or it is so thin that twice its area is
     * at most 1e-10 of its longest edge squared, or its normal is below the zero tolerance.
     *
     * @param positions x, y, z per vertex, interleaved
     * @param a         the first vertex's index (a vertex, not an array offset)
     * @param b         the second vertex's index
     * @param c         the third vertex's index
     * @return true when the triangle would be rejected
     * @throws ArrayIndexOutOfBoundsException when an index is outside {@code positions}
     */
    public static boolean isDegenerate(double[] positions, int a, int b, int c) {
        return TriangleMesh.isDegenerate(positions, a, b, c);
    }
}
