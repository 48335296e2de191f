package scene.io;

import java.io.FileNotFoundException;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;

import geometries.MeshChecks;
import geometries.TriangleMesh;
import primitives.Util;

/**
 * Reads the geometry of a Wavefront OBJ file into one {@link TriangleMesh}.
 *
 * <p>What it reads:
 * <ul>
 * <li>{@code v x y z} (optionally followed by {@code w}, or by an {@code r g b} colour, both
 * ignored) and {@code vn x y z} (any non-zero length);</li>
 * <li>{@code f} with three or more corners, each {@code v}, {@code v/vt}, {@code v//vn} or
 * {@code v/vt/vn}; indices start at 1, negative ones count back from the last element defined
 * before the line (-1 is the last). A face of n corners is cut into the fan (0, i, i+1), which is
 * right for the convex faces OBJ exporters write (convexity is not checked).</li>
 * <li>{@code #} starts a comment anywhere on a line; blank lines are skipped. {@code vt} lines are
 * counted (so that texture indices can be range-checked) but not used; every other keyword
 * ({@code o}, {@code g}, {@code s}, {@code usemtl}, {@code mtllib}, {@code l}, ...) is ignored,
 * since none of them changes the triangles.</li>
 * </ul>
 *
 * <p>Normals: the mesh is smooth-shaded only when every corner of every face names a normal;
 * otherwise it is flat-shaded and the normals are ignored. An OBJ corner may pair a vertex with
 * any normal (a vertex on a crease has one per side), while the mesh keeps one normal per
 * vertex, so a smooth mesh's vertices are the distinct (vertex, normal) pairs the faces use,
 * numbered in order of first use (a vertex with two normals becomes two vertices at the same
 * place). A flat mesh keeps the file's vertices in file order, used or not.
 *
 * <p>Errors: a malformed number or index, an index of 0 or out of range, a face of fewer than 3
 * corners, a non-finite number, a zero normal, a degenerate face or a file without faces throws
 * an {@link ObjFormatException} whose message is {@code source:line: what is wrong} (line 0 for the
 * file as a whole).
 *
 * <p>Limits: the text is streamed line by line (never read whole); a line longer than
 * {@link Limits#MAX_OBJ_LINE_LENGTH} characters or a text longer than {@link Limits#MAX_OBJ_BYTES}
 * is refused at the line where the limit is crossed, and {@link #read(Path)} refuses a file that
 * is not a regular file (a device such as {@code /dev/zero}, a pipe) or is larger than the limit
 * before reading it. The reader
 * returns a whole mesh or throws; it never returns part of a file. Numbers are read the same in
 * every default {@link Locale} ({@code 1.5}, never {@code 1,5}), and exactly as
 * {@link Double#parseDouble} would read them.
 *
 * <p>Speed: a hand-written tokenizer over each line, no regular expressions, and no string per
 * number for up to 15 significant digits. A million-triangle file (500,000 vertices, 39 MB) loads
 * in about 2 s in a fresh JVM and 0.3 s once the JIT has compiled the reader (2-core machine).
 */
public final class ObjReader {
    /** Powers of ten exactly representable as doubles, for the exact fast path of number parsing. */
    private static final double[] POWERS_OF_TEN = { 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10,
            1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
    /** Integers below 2^53 are exact doubles. */
    private static final long EXACT_LIMIT = 1L << 53;
    /** More significant digits than this go to {@link Double#parseDouble} (the long would overflow). */
    private static final int MAX_FAST_DIGITS = 18;

    private final String source;

    // What has been read so far. Positions and normals: x, y, z per element.
    private double[] positions = new double[3 * 1024];
    private int vertexCount;
    private double[] normals = new double[3 * 64];
    private int normalCount;
    private int texCoordCount;
    // Per triangle corner: its vertex index and its normal index (-1 when the file gives none), 0-based.
    private int[] cornerVertex = new int[3 * 1024];
    private int[] cornerNormal = new int[3 * 1024];
    private int cornerCount;
    private boolean everyCornerHasNormal = true;
    // The corners of the face being read.
    private int[] faceVertex = new int[8];
    private int[] faceNormal = new int[8];

    // The line being read: its text up to any comment, the cursor and the current token.
    private String line;
    private int lineNumber;
    private int end;
    private int cursor;
    private int tokenStart;
    private int tokenEnd;

    private ObjReader(String source) {
        this.source = source;
    }

    /**
     * Reads an OBJ file (UTF-8; bytes that are not UTF-8 can only occur in comments and names,
     * which are ignored). Error messages name the file as given.
     *
     * @param file the OBJ file
     * @return the mesh, smooth-shaded when every face corner has a normal, else flat
     * @throws ObjFormatException when the content is malformed
     * @throws IOException        when the file cannot be read
     * @throws OutOfMemoryError   when the mesh does not fit the heap, naming the file, its size,
     *                            the triangles read, the limit and {@code -Xmx}
     */
    public static TriangleMesh read(Path file) throws IOException {
        Objects.requireNonNull(file, "file");
        // Refused before a byte is read: a device or a pipe (/dev/zero never ends), a directory,
        // and a file beyond the size limit. The stream is bounded as well, should the file grow.
        if (!Files.isRegularFile(file)) {
            if (!Files.exists(file)) throw new NoSuchFileException(file.toString());
            throw new ObjFormatException(file.toString(), 0, "not a regular file (a device, a pipe or a folder)");
        }
        long size = Files.size(file);
        if (size > Limits.MAX_OBJ_BYTES)
            throw new ObjFormatException(file.toString(), 0, "the file has " + size + " bytes, more than the limit of "
                    + Limits.MAX_OBJ_BYTES + " bytes");
        try (Reader reader = new InputStreamReader(Files.newInputStream(file), StandardCharsets.UTF_8)) {
            return read(reader, file.toString(), size);
        }
    }

    /**
     * Reads OBJ text to its end; does not close {@code reader}.
     *
     * @param reader     the OBJ text
     * @param sourceName what error messages call the text (a file name)
     * @return the mesh, smooth-shaded when every face corner has a normal, else flat
     * @throws ObjFormatException when the content is malformed
     * @throws IOException        when {@code reader} fails
     * @throws OutOfMemoryError   when the mesh does not fit the heap, naming the source, the
     *                            triangles read, the limit and {@code -Xmx}
     */
    public static TriangleMesh read(Reader reader, String sourceName) throws IOException {
        return read(reader, sourceName, -1);
    }

    /**
     * As {@link #read(Reader, String)}, knowing the text's size for the message of a lack of memory.
     *
     * @param reader     the OBJ text
     * @param sourceName what messages call the text (a file name)
     * @param bytes      the text's size in bytes (the file's), or -1 when unknown
     * @return the mesh
     * @throws ObjFormatException when the content is malformed
     * @throws IOException        when {@code reader} fails
     * @throws OutOfMemoryError naming the source, its size, what was read, the limit and {@code -Xmx}
     *                          ({@link #memoryMessage}), when the mesh does not fit the heap
     */
    static TriangleMesh read(Reader reader, String sourceName, long bytes) throws IOException {
        Objects.requireNonNull(reader, "reader");
        Objects.requireNonNull(sourceName, "source name");
        ObjReader parser = new ObjReader(sourceName);
        LineReader lines = new LineReader(reader, Limits.MAX_OBJ_LINE_LENGTH, Limits.MAX_OBJ_BYTES);
        boolean whole = false;
        try {
            for (String text = lines.readLine(); text != null; text = lines.readLine()) parser.parseLine(text);
            whole = true;
            return parser.toMesh();
        } catch (LineReader.LimitExceededException e) {
            ++parser.lineNumber; // the line being read
            throw parser.error(e.getMessage());
        } catch (OutOfMemoryError e) {
            // A file within the size limit can still outgrow a small heap (a 147 MB, 4.5-million-
            // triangle file needs about 600 MB to read). What was read is let go first, so that the
            // message can be made; the error then says which file, how far, and how to give more.
            long triangles = parser.cornerCount / 3, vertices = parser.vertexCount;
            parser.release();
            throw outOfMemory(e, sourceName, bytes, triangles, vertices, whole);
        }
    }

    /**
     * The error for an OBJ text that did not fit the heap (arguments as {@link #memoryMessage}).
     *
     * @param cause the JVM's error
     * @return an error whose message is {@link #memoryMessage} with this JVM's limit, caused by {@code cause}
     */
    static OutOfMemoryError outOfMemory(OutOfMemoryError cause, String source, long bytes, long triangles, long vertices,
                                        boolean whole) {
        OutOfMemoryError named = new OutOfMemoryError(memoryMessage(source, bytes, triangles, vertices, whole,
                Runtime.getRuntime().maxMemory()));
        named.initCause(cause);
        return named;
    }

    /** Lets go of what has been read (after a lack of memory). */
    private void release() {
        positions = null;
        normals = null;
        cornerVertex = null;
        cornerNormal = null;
        line = null;
    }

    /**
     * The one line of an OBJ text that did not fit the heap: {@code the OBJ file meshes/big.obj
     * (147 MB) did not fit in memory: 2104533 triangles and 1052270 vertices read when Java ran
     * out; Java may use at most 900 MB here (give Java more memory with -Xmx; on Spark's driver,
     * spark-submit --driver-memory)}. Sizes below 10 MB have a decimal.
     *
     * @param source    the file as named to the reader
     * @param bytes     its size in bytes, or -1 when unknown
     * @param triangles the triangles read before memory ran out
     * @param vertices  the vertices read before memory ran out
     * @param whole     whether the whole text had been read (the mesh was being made)
     * @param max       the heap's limit ({@link Runtime#maxMemory()}; {@link Long#MAX_VALUE}: none)
     * @return the line, starting with "the OBJ file "
     */
    static String memoryMessage(String source, long bytes, long triangles, long vertices, boolean whole, long max) {
        long mb = 1 << 20;
        String size = bytes < 0 ? "" : bytes < 10 * mb ? String.format(Locale.ROOT, " (%.1f MB)", (double) bytes / mb)
                : " (" + (bytes + mb / 2) / mb + " MB)";
        String read = whole ? "read whole (" + triangles + " triangles, " + vertices + " vertices), Java ran out making the mesh"
                : triangles == 0 && vertices == 0 ? "Java ran out before a vertex was read"
                : triangles + " triangles and " + vertices + " vertices read when Java ran out";
        return "the OBJ file " + Messages.visible(source) + size + " did not fit in memory: " + read
                + (max == Long.MAX_VALUE ? "" : "; Java may use at most " + max / mb + " MB here")
                + " (give Java more memory with -Xmx; on Spark's driver, spark-submit --driver-memory)";
    }

    /**
     * Reads an OBJ file from the class path, such as the bundled {@code "/models/teapot.obj"}.
     *
     * @param classpathResource an absolute resource name (starting with '/')
     * @return the mesh, smooth-shaded when every face corner has a normal, else flat
     * @throws IllegalArgumentException when the name is not absolute
     * @throws FileNotFoundException    naming the resource when it does not exist
     * @throws ObjFormatException       when the content is malformed
     * @throws IOException              when the resource cannot be read
     */
    public static TriangleMesh readResource(String classpathResource) throws IOException {
        Objects.requireNonNull(classpathResource, "classpath resource");
        if (!classpathResource.startsWith("/"))
            throw new IllegalArgumentException("classpath resource must be absolute (start with '/'), got '"
                    + classpathResource + "'");
        InputStream in = ObjReader.class.getResourceAsStream(classpathResource);
        if (in == null) throw new FileNotFoundException("classpath resource " + classpathResource + " not found");
        try (Reader reader = new InputStreamReader(in, StandardCharsets.UTF_8)) {
            return read(reader, classpathResource);
        }
    }

    private ObjFormatException error(String problem) {
        return new ObjFormatException(source, lineNumber, problem);
    }

    private void parseLine(String text) throws ObjFormatException {
        ++lineNumber;
        line = text;
        int hash = text.indexOf('#');
        end = hash < 0 ? text.length() : hash;
        cursor = 0;
        if (!nextToken()) return;
        int length = tokenEnd - tokenStart;
        char first = line.charAt(tokenStart), second = length == 2 ? line.charAt(tokenStart + 1) : 0;
        if (length == 1 && first == 'v') parseVertex();
        else if (length == 1 && first == 'f') parseFace();
        else if (length == 2 && first == 'v' && second == 'n') parseNormal();
        else if (length == 2 && first == 'v' && second == 't') ++texCoordCount;
        // Anything else is a keyword that does not change the triangles: ignored.
    }

    /** Moves to the next whitespace-separated token of the line; false at the end (or a comment). */
    private boolean nextToken() {
        int i = cursor;
        while (i < end && line.charAt(i) <= ' ') ++i;
        if (i == end) {
            cursor = i;
            return false;
        }
        tokenStart = i;
        while (i < end && line.charAt(i) > ' ') ++i;
        tokenEnd = cursor = i;
        return true;
    }

    private String token() {
        return line.substring(tokenStart, tokenEnd);
    }

    private void parseVertex() throws ObjFormatException {
        double x = 0, y = 0, z = 0;
        int n = 0;
        for (; nextToken(); ++n) {
            double d = number("vertex coordinate");
            if (n == 0) x = d;
            else if (n == 1) y = d;
            else if (n == 2) z = d;
        }
        if (n != 3 && n != 4 && n != 6)
            throw error("a vertex needs x y z (optionally followed by w, or by r g b), got " + n + " numbers");
        if (3 * vertexCount + 3 > positions.length) positions = Arrays.copyOf(positions, 2 * positions.length);
        positions[3 * vertexCount] = x;
        positions[3 * vertexCount + 1] = y;
        positions[3 * vertexCount + 2] = z;
        ++vertexCount;
    }

    private void parseNormal() throws ObjFormatException {
        double x = 0, y = 0, z = 0;
        int n = 0;
        for (; nextToken(); ++n) {
            double d = number("normal coordinate");
            if (n == 0) x = d;
            else if (n == 1) y = d;
            else if (n == 2) z = d;
        }
        if (n != 3) throw error("a vertex normal needs x y z, got " + n + " numbers");
        // The mesh's own test of a zero normal, so that the mesh never rejects what the reader passed.
        if (Util.isZero(x) && Util.isZero(y) && Util.isZero(z))
            throw error("vertex normal (" + x + "," + y + "," + z + ") has zero length");
        if (3 * normalCount + 3 > normals.length) normals = Arrays.copyOf(normals, 2 * normals.length);
        normals[3 * normalCount] = x;
        normals[3 * normalCount + 1] = y;
        normals[3 * normalCount + 2] = z;
        ++normalCount;
    }

    private void parseFace() throws ObjFormatException {
        int n = 0;
        while (nextToken()) {
            if (n == faceVertex.length) {
                faceVertex = Arrays.copyOf(faceVertex, 2 * n);
                faceNormal = Arrays.copyOf(faceNormal, 2 * n);
            }
            parseCorner(n++);
        }
        if (n < 3) throw error("a face needs at least 3 vertices, got " + n);
        for (int j = 1; j + 1 < n; ++j) {
            int a = faceVertex[0], b = faceVertex[j], c = faceVertex[j + 1];
            if (MeshChecks.isDegenerate(positions, a, b, c))
                throw error((n == 3 ? "degenerate face" : "degenerate triangle (corners 1, " + (j + 1) + ", " + (j + 2)
                        + ") of a " + n + "-vertex face") + ": vertices " + vertex(a) + ", " + vertex(b) + ", "
                        + vertex(c) + " coincide or are collinear (or enclose an area below the zero tolerance)");
        }
        int triangles = n - 2;
        if (cornerCount + 3 * triangles > cornerVertex.length) {
            int capacity = Math.max(2 * cornerVertex.length, cornerCount + 3 * triangles);
            cornerVertex = Arrays.copyOf(cornerVertex, capacity);
            cornerNormal = Arrays.copyOf(cornerNormal, capacity);
        }
        for (int j = 1; j + 1 < n; ++j) {
            addCorner(0);
            addCorner(j);
            addCorner(j + 1);
        }
    }

    private void addCorner(int corner) {
        cornerVertex[cornerCount] = faceVertex[corner];
        cornerNormal[cornerCount] = faceNormal[corner];
        ++cornerCount;
    }

    /** Vertex {@code index} (0-based) as the file numbers it, with its position. */
    private String vertex(int index) {
        return (index + 1) + " (" + positions[3 * index] + "," + positions[3 * index + 1] + ","
                + positions[3 * index + 2] + ")";
    }

    /** Reads the current token, a face corner {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn}. */
    private void parseCorner(int n) throws ObjFormatException {
        int s = tokenStart, e = tokenEnd;
        int slash1 = slash(s, e);
        int slash2 = slash1 < 0 ? -1 : slash(slash1 + 1, e);
        if (slash2 >= 0 && slash(slash2 + 1, e) >= 0)
            throw error("face vertex '" + token() + "' has more than three parts (v/vt/vn)");
        faceVertex[n] = index(s, slash1 < 0 ? e : slash1, vertexCount, "vertex", "vertices");
        int normal = -1;
        if (slash1 >= 0) {
            int texEnd = slash2 < 0 ? e : slash2;
            if (texEnd > slash1 + 1) index(slash1 + 1, texEnd, texCoordCount, "texture coordinate", "texture coordinates");
            else if (slash2 < 0) throw error("face vertex '" + token() + "' has an empty texture coordinate index");
            if (slash2 >= 0) normal = index(slash2 + 1, e, normalCount, "normal", "normals");
        }
        if (normal < 0) everyCornerHasNormal = false;
        faceNormal[n] = normal;
    }

    /** @return the position of the first '/' in [from, to) of the line, or -1 */
    private int slash(int from, int to) {
        for (int i = from; i < to; ++i)
            if (line.charAt(i) == '/') return i;
        return -1;
    }

    /**
     * Parses the index in [from, to) of the line and resolves it against the {@code count} elements
     * defined so far.
     *
     * @return the 0-based index
     */
    private int index(int from, int to, int count, String what, String plural) throws ObjFormatException {
        if (from == to) throw error("face vertex '" + token() + "' has an empty " + what + " index");
        int i = from;
        boolean negative = line.charAt(i) == '-';
        if (negative || line.charAt(i) == '+') ++i;
        long value = 0;
        int digits = 0;
        for (; i < to; ++i, ++digits) {
            char c = line.charAt(i);
            if (c < '0' || c > '9' || digits == 18) {
                digits = -1;
                break;
            }
            value = value * 10 + (c - '0');
        }
        if (digits <= 0)
            throw error("malformed " + what + " index '" + line.substring(from, to) + "' in face vertex '" + token() + "'");
        if (negative) value = -value;
        if (value == 0)
            throw error(what + " index 0 is invalid: OBJ indices start at 1 (negative ones count back from the last)");
        long resolved = value > 0 ? value - 1 : count + value;
        if (resolved < 0 || resolved >= count)
            throw error(what + " index " + value + " is out of range: " + (count == 0 ? "no " + plural
                    : count + " " + (count == 1 ? what : plural)) + " defined before this line");
        return (int) resolved;
    }

    /** Parses the current token as a finite decimal number. */
    private double number(String what) throws ObjFormatException {
        double d = parseDecimal(line, tokenStart, tokenEnd);
        if (Double.isNaN(d)) {
            String word = token().toLowerCase(Locale.ROOT);
            if (word.startsWith("-") || word.startsWith("+")) word = word.substring(1);
            if (word.equals("nan") || word.equals("inf") || word.equals("infinity"))
                throw error(what + " '" + token() + "' is not a finite number");
            throw error("malformed " + what + " '" + token() + "'");
        }
        if (Double.isInfinite(d)) throw error(what + " '" + token() + "' is not a finite number (too large)");
        return d;
    }

    /**
     * Parses {@code [+-]digits[.digits][(e|E)[+-]digits]} (digits on at least one side of the
     * point) in [from, to) of {@code s}, rounding exactly as {@link Double#parseDouble}: up to 18
     * significant digits and a power of ten up to 10^22 need one correctly rounded multiplication
     * or division of two exact doubles (Clinger's fast path); anything longer goes to
     * {@link Double#parseDouble}.
     *
     * @return the value (infinite when too large), or NaN when the text is not such a number
     */
    static double parseDecimal(String s, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (s.charAt(i) == '+' || s.charAt(i) == '-')) negative = s.charAt(i++) == '-';
        long mantissa = 0;
        int significant = 0; // digits in mantissa after its leading zeros
        int exponent = 0;
        boolean anyDigit = false;
        boolean tooLong = false;
        boolean fraction = false;
        for (; i < to; ++i) {
            char c = s.charAt(i);
            if (c == '.' && !fraction) {
                fraction = true;
                continue;
            }
            if (c < '0' || c > '9') break;
            anyDigit = true;
            if (significant == MAX_FAST_DIGITS) {
                tooLong = true;
                continue;
            }
            mantissa = mantissa * 10 + (c - '0');
            if (mantissa != 0) ++significant;
            if (fraction) --exponent;
        }
        if (!anyDigit) return Double.NaN;
        if (i < to && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            ++i;
            boolean negativeExponent = false;
            if (i < to && (s.charAt(i) == '+' || s.charAt(i) == '-')) negativeExponent = s.charAt(i++) == '-';
            int start = i, e = 0;
            for (; i < to && s.charAt(i) >= '0' && s.charAt(i) <= '9'; ++i)
                if (e < 100_000) e = e * 10 + (s.charAt(i) - '0');
            if (i == start) return Double.NaN;
            exponent += negativeExponent ? -e : e;
        }
        if (i != to) return Double.NaN;
        if (mantissa == 0 && !tooLong) return negative ? -0.0 : 0.0;
        if (tooLong || mantissa >= EXACT_LIMIT || exponent < -22 || exponent > 22)
            return Double.parseDouble(s.substring(from, to)); // the syntax is checked: no exception
        double value = exponent >= 0 ? mantissa * POWERS_OF_TEN[exponent] : mantissa / POWERS_OF_TEN[-exponent];
        return negative ? -value : value;
    }

    private TriangleMesh toMesh() throws ObjFormatException {
        if (cornerCount == 0) throw error("no faces: an OBJ mesh needs at least one 'f' line");
        int[] triangles = Arrays.copyOf(cornerVertex, cornerCount);
        if (!everyCornerHasNormal) return new TriangleMesh(Arrays.copyOf(positions, 3 * vertexCount), triangles);

        // Smooth: one mesh vertex per distinct (vertex, normal) pair, in order of first use. Most
        // vertices have a single normal, so the first one is kept in an array and only the others
        // (vertices on creases) go through a map.
        int[] firstNormal = new int[vertexCount];
        int[] firstSlot = new int[vertexCount];
        Arrays.fill(firstNormal, -1);
        Map<Long, Integer> otherSlots = new HashMap<>();
        double[] meshPositions = new double[3 * vertexCount];
        double[] meshNormals = new double[3 * vertexCount];
        int slots = 0;
        for (int i = 0; i < cornerCount; ++i) {
            int v = cornerVertex[i], n = cornerNormal[i];
            int slot;
            if (firstNormal[v] == n) {
                slot = firstSlot[v];
            } else {
                Integer known = null;
                Long key = null;
                if (firstNormal[v] >= 0) {
                    key = (long) v << 32 | n;
                    known = otherSlots.get(key);
                }
                if (known != null) {
                    slot = known;
                } else {
                    slot = slots++;
                    if (3 * slots > meshPositions.length) {
                        meshPositions = Arrays.copyOf(meshPositions, 2 * meshPositions.length);
                        meshNormals = Arrays.copyOf(meshNormals, 2 * meshNormals.length);
                    }
                    System.arraycopy(positions, 3 * v, meshPositions, 3 * slot, 3);
                    System.arraycopy(normals, 3 * n, meshNormals, 3 * slot, 3);
                    if (key == null) {
                        firstNormal[v] = n;
                        firstSlot[v] = slot;
                    } else {
                        otherSlots.put(key, slot);
                    }
                }
            }
            triangles[i] = slot;
        }
        return new TriangleMesh(Arrays.copyOf(meshPositions, 3 * slots), triangles, Arrays.copyOf(meshNormals, 3 * slots));
    }
}
