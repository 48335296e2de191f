package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.BufferedReader;
import java.io.FileNotFoundException;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.TriangleMesh;
import primitives.Point;
import primitives.Vector;

@DisplayName("ObjReader")
class ObjReaderTest {
    /** Four vertices of the unit square in z = 0: lines 1 to 4 of most texts below. */
    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";

    private static TriangleMesh read(String text) throws IOException {
        return ObjReader.read(new StringReader(text), "test.obj");
    }

    private static List<int[]> triangles(TriangleMesh mesh) {
        List<int[]> result = new ArrayList<>();
        for (int k = 0; k < mesh.triangleCount(); ++k) result.add(mesh.getTriangleIndices(k));
        return result;
    }

    @Nested
    @DisplayName("the bundled teapot")
    class Teapot {
        @Test
        @DisplayName("has 530 vertices and 992 triangles, flat-shaded")
        void counts() throws IOException {
            TriangleMesh teapot = ObjReader.readResource("/models/teapot.obj");
            assertThat(teapot.vertexCount()).isEqualTo(530);
            assertThat(teapot.triangleCount()).isEqualTo(992);
            assertThat(teapot.hasVertexNormals()).isFalse();
        }

        @Test
        @DisplayName("holds exactly the file's vertices and faces, as a split-and-parseDouble reading gives them")
        void matchesIndependentReading() throws IOException {
            List<double[]> vertices = new ArrayList<>();
            List<int[]> faces = new ArrayList<>();
            try (BufferedReader in = new BufferedReader(new InputStreamReader(
                    ObjReaderTest.class.getResourceAsStream("/models/teapot.obj"), StandardCharsets.UTF_8))) {
                for (String line = in.readLine(); line != null; line = in.readLine()) {
                    String[] f = line.trim().split("\\s+");
                    if (f[0].equals("v"))
                        vertices.add(new double[] { Double.parseDouble(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3]) });
                    else if (f[0].equals("f"))
                        faces.add(new int[] { Integer.parseInt(f[1]) - 1, Integer.parseInt(f[2]) - 1, Integer.parseInt(f[3]) - 1 });
                }
            }
            TriangleMesh teapot = ObjReader.readResource("/models/teapot.obj");
            for (int i = 0; i < vertices.size(); ++i) {
                Point v = teapot.getVertex(i);
                assertThat(new double[] { v.getX(), v.getY(), v.getZ() }).as("vertex %d", i).containsExactly(vertices.get(i));
            }
            assertThat(triangles(teapot)).containsExactlyElementsOf(faces);
        }

        @Test
        @DisplayName("reads the same from a file path")
        void fromPath(@TempDir Path dir) throws IOException {
            Path file = dir.resolve("teapot.obj");
            try (var in = ObjReaderTest.class.getResourceAsStream("/models/teapot.obj")) {
                Files.copy(in, file);
            }
            TriangleMesh fromFile = ObjReader.read(file), bundled = ObjReader.readResource("/models/teapot.obj");
            assertThat(fromFile.vertexCount()).isEqualTo(bundled.vertexCount());
            assertThat(triangles(fromFile)).containsExactlyElementsOf(triangles(bundled));
        }
    }

    @Nested
    @DisplayName("sources")
    class Sources {
        @Test
        @DisplayName("a missing resource is named; a relative resource name is refused")
        void resources() {
            assertThatThrownBy(() -> ObjReader.readResource("/models/nothing.obj")).isInstanceOf(FileNotFoundException.class)
                    .hasMessageContaining("/models/nothing.obj");
            assertThatThrownBy(() -> ObjReader.readResource("models/teapot.obj")).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("'models/teapot.obj'");
        }

        @Test
        @DisplayName("a missing file is an I/O error naming it")
        void missingFile(@TempDir Path dir) {
            Path file = dir.resolve("absent.obj");
            assertThatThrownBy(() -> ObjReader.read(file)).isInstanceOf(NoSuchFileException.class)
                    .hasMessageContaining("absent.obj");
        }

        @Test
        @DisplayName("errors in a file name the file as given")
        void errorNamesFile(@TempDir Path dir) throws IOException {
            Path file = dir.resolve("broken.obj");
            Files.writeString(file, SQUARE + "f 1 2 9\n");
            ObjFormatException e = catchThrowableOfType(ObjFormatException.class, () -> ObjReader.read(file));
            assertThat(e.getSource()).isEqualTo(file.toString());
            assertThat(e).hasMessageStartingWith(file + ":5: ");
        }
    }

    @Nested
    @DisplayName("faces")
    class Faces {
        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = ';', value = {
                "v;           f 1 2 3;             false",
                "v/vt;        f 1/1 2/2 3/3;       false",
                "v//vn;       f 1//1 2//1 3//1;    true",
                "v/vt/vn;     f 1/3/1 2/2/1 3/1/1; true" })
        @DisplayName("every corner form, with normals only when the form has them:")
        void forms(String form, String face, boolean smooth) throws IOException {
            TriangleMesh mesh = read(SQUARE + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 2\n" + face + "\n");
            assertThat(triangles(mesh)).containsExactly(new int[] { 0, 1, 2 });
            assertThat(mesh.hasVertexNormals()).isEqualTo(smooth);
            assertThat(mesh.getVertex(mesh.getTriangleIndices(0)[1])).isEqualTo(new Point(1, 0, 0));
            if (smooth)
                for (int v : mesh.getTriangleIndices(0)) assertThat(mesh.getVertexNormal(v)).isEqualTo(new Vector(0, 0, 1));
        }

        @Test
        @DisplayName("negative indices count back from the last vertex defined before the line")
        void negativeIndices() throws IOException {
            TriangleMesh mesh = read("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf -3 -2 -1\nf 1 -5 -1\n");
            assertThat(triangles(mesh)).containsExactly(new int[] { 0, 1, 2 }, new int[] { 3, 4, 5 }, new int[] { 0, 1, 5 });
        }

        @Test
        @DisplayName("negative normal and texture indices too")
        void negativeNormalIndices() throws IOException {
            TriangleMesh mesh = read(SQUARE + "vt 0 0\nvn 1 0 0\nvn 0 0 1\nf 1/-1/-1 2/-1/-1 3/-1/-1\n");
            for (int v : mesh.getTriangleIndices(0)) assertThat(mesh.getVertexNormal(v)).isEqualTo(new Vector(0, 0, 1));
        }

        @ParameterizedTest(name = "{0} corners: {0} - 2 triangles")
        @ValueSource(ints = { 3, 4, 5, 6, 8, 32 })
        @DisplayName("a convex n-gon is cut into the fan (1, i, i+1):")
        void polygons(int n) throws IOException {
            StringBuilder text = new StringBuilder();
            for (int i = 0; i < n; ++i)
                text.append("v ").append(Math.cos(2 * Math.PI * i / n)).append(' ').append(Math.sin(2 * Math.PI * i / n)).append(" 0\n");
            text.append('f');
            for (int i = 1; i <= n; ++i) text.append(' ').append(i);
            TriangleMesh mesh = read(text.append('\n').toString());
            assertThat(mesh.triangleCount()).isEqualTo(n - 2);
            for (int k = 0; k < n - 2; ++k) assertThat(mesh.getTriangleIndices(k)).containsExactly(0, k + 1, k + 2);
        }
    }

    @Nested
    @DisplayName("normals")
    class Normals {
        @Test
        @DisplayName("one face without normals makes the whole mesh flat, keeping the file's vertices")
        void flatWhenAnyCornerLacksANormal() throws IOException {
            TriangleMesh mesh = read(SQUARE + "vn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n");
            assertThat(mesh.hasVertexNormals()).isFalse();
            assertThat(mesh.vertexCount()).isEqualTo(4);
            assertThat(triangles(mesh)).containsExactly(new int[] { 0, 1, 2 }, new int[] { 1, 3, 2 });
        }

        @Test
        @DisplayName("a vertex with one normal stays one vertex: a smooth quad has 4 vertices")
        void sharedPairs() throws IOException {
            TriangleMesh mesh = read(SQUARE + "vn 0 0 1\nvn 0 0.1 1\nvn 0.1 0 1\nvn 0.1 0.1 1\n"
                    + "f 1//1 2//3 4//4\nf 1//1 4//4 3//2\n");
            assertThat(mesh.hasVertexNormals()).isTrue();
            assertThat(mesh.vertexCount()).isEqualTo(4);
            assertThat(triangles(mesh)).containsExactly(new int[] { 0, 1, 2 }, new int[] { 0, 2, 3 });
        }

        /**
         * Two faces of a folded strip share the edge 2–3, each with its own normal on it: every corner
         * must keep the (position, normal) pair the file gives it.
         */
        @Test
        @DisplayName("each corner keeps its own normal: a vertex with two normals becomes two vertices")
        void perCornerNormals() throws IOException {
            String text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvn 0 0 1\nvn 1 1 -1\n"
                    + "f 1//1 2//1 3//1\nf 2//2 4//2 3//2\nf 3//1 1//1 2//1\n";
            double[][] position = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 1 } };
            double[][] normal = { { 0, 0, 1 }, { 1, 1, -1 } };
            int[][] cornerVertex = { { 0, 1, 2 }, { 1, 3, 2 }, { 2, 0, 1 } };
            int[][] cornerNormal = { { 0, 0, 0 }, { 1, 1, 1 }, { 0, 0, 0 } };
            TriangleMesh mesh = read(text);
            assertThat(mesh.vertexCount()).as("3 + 2 on the shared edge with the second normal + 1").isEqualTo(6);
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c) {
                    int v = mesh.getTriangleIndices(k)[c];
                    double[] p = position[cornerVertex[k][c]], n = normal[cornerNormal[k][c]];
                    assertThat(mesh.getVertex(v)).as("triangle %d corner %d", k, c).isEqualTo(new Point(p[0], p[1], p[2]));
                    assertThat(mesh.getVertexNormal(v)).as("triangle %d corner %d", k, c)
                            .isEqualTo(new Vector(n[0], n[1], n[2]).normalize());
                }
        }
    }

    @Nested
    @DisplayName("tolerates")
    class Tolerance {
        @Test
        @DisplayName("comments, blank lines, tabs, CRLF, and keywords it does not use")
        void ignoredContent() throws IOException {
            String text = "# a comment\r\n\r\nmtllib scene.mtl\r\no object\r\ng group\r\ns 1\r\nusemtl red\r\n"
                    + "  v\t0 0 0   # inline comment\r\nv 1 0 0 1.0\r\nv 0 1 0 0.5 0.5 0.5\r\nvt 0 0\r\nvp 0.5\r\n"
                    + "l 1 2\r\nbogus 1 2 3\r\n\t\r\nf 1 2 3 # the face\r\n";
            TriangleMesh mesh = read(text);
            assertThat(mesh.vertexCount()).isEqualTo(3);
            assertThat(triangles(mesh)).containsExactly(new int[] { 0, 1, 2 });
            assertThat(mesh.getVertex(1)).isEqualTo(new Point(1, 0, 0));
        }

        @ParameterizedTest(name = "''{0}''")
        @ValueSource(strings = { "1", "-2.5", "+3.", ".5", "-.5", "007", "1e3", "1E-3", "2.5e+2", "-0", "0.000",
                "0.1", "0.30000000000000004", "9007199254740993", "123456789012345678901234567890",
                "1.00000000000000000000001", "4.9e-324", "1e-320", "1.7976931348623157e308", "123.456e-30", "1e22", "1e23" })
        @DisplayName("number forms, read exactly as Double.parseDouble reads them:")
        void numberForms(String number) throws IOException {
            TriangleMesh mesh = read("v " + number + " 7 7\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n");
            assertThat(mesh.getVertex(0).getX()).isEqualTo(Double.parseDouble(number));
            assertThat(Double.doubleToRawLongBits(mesh.getVertex(0).getX()))
                    .as("the sign of zero too").isEqualTo(Double.doubleToRawLongBits(Double.parseDouble(number)));
        }

        @Test
        @DisplayName("random numbers in many notations: every one exactly as Double.parseDouble reads it")
        void randomNumbers() throws IOException {
            Random random = new Random(2024);
            List<String> tokens = new ArrayList<>();
            for (int i = 0; i < 3000; ++i) {
                double d = (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(21) - 10);
                tokens.add(switch (i % 5) {
                    case 0 -> Double.toString(d);
                    case 1 -> String.format(Locale.ROOT, "%.6f", d);
                    case 2 -> String.format(Locale.ROOT, "%.17g", d);
                    case 3 -> String.format(Locale.ROOT, "%.3e", d);
                    default -> String.format(Locale.ROOT, "%.20f", d);
                });
            }
            StringBuilder text = new StringBuilder();
            for (int i = 0; i < tokens.size(); i += 3)
                text.append("v ").append(tokens.get(i)).append(' ').append(tokens.get(i + 1)).append(' ')
                        .append(tokens.get(i + 2)).append('\n');
            text.append("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
            TriangleMesh mesh = read(text.toString());
            for (int i = 0; i < tokens.size(); ++i) {
                Point v = mesh.getVertex(i / 3);
                double actual = i % 3 == 0 ? v.getX() : i % 3 == 1 ? v.getY() : v.getZ();
                assertThat(actual).as("'%s'", tokens.get(i)).isEqualTo(Double.parseDouble(tokens.get(i)));
            }
        }

        @Test
        @DisplayName("numbers read the same whatever the default Locale (a German one writes 1,5)")
        void localeIndependent() throws IOException {
            Locale saved = Locale.getDefault();
            try {
                Locale.setDefault(Locale.GERMANY);
                TriangleMesh mesh = read("v 1.5 2.25 -3.125\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
                assertThat(mesh.getVertex(0)).isEqualTo(new Point(1.5, 2.25, -3.125));
            } finally {
                Locale.setDefault(saved);
            }
        }
    }

    @Nested
    @DisplayName("malformed input")
    class Errors {
        static Stream<Arguments> malformed() {
            String fiveVertices = SQUARE + "v 2 0 0\n"; // lines 1-5; vertex 5 is collinear with 1 and 2
            return Stream.of(
                    Arguments.of("a vertex with two coordinates", SQUARE + "v 1 2\n", 5, "a vertex needs x y z (optionally followed by w, or by r g b), got 2 numbers"),
                    Arguments.of("a vertex with five numbers", "v 1 2 3 4 5\n", 1, "got 5 numbers"),
                    Arguments.of("a malformed coordinate", SQUARE + "v 1 2 x\n", 5, "malformed vertex coordinate 'x'"),
                    Arguments.of("a decimal comma", "v 1,5 2 3\n", 1, "malformed vertex coordinate '1,5'"),
                    Arguments.of("two decimal points", "v 1.2.3 2 3\n", 1, "malformed vertex coordinate '1.2.3'"),
                    Arguments.of("an exponent without digits", "v 1e 2 3\n", 1, "malformed vertex coordinate '1e'"),
                    Arguments.of("a Java float suffix", "v 1.0f 2 3\n", 1, "malformed vertex coordinate '1.0f'"),
                    Arguments.of("NaN", SQUARE + "v nan 0 0\n", 5, "vertex coordinate 'nan' is not a finite number"),
                    Arguments.of("infinity", SQUARE + "v 0 -Infinity 0\n", 5, "vertex coordinate '-Infinity' is not a finite number"),
                    Arguments.of("a coordinate beyond the double range", SQUARE + "v 0 0 1e999\n", 5, "vertex coordinate '1e999' is not a finite number (too large)"),
                    Arguments.of("a normal with two numbers", SQUARE + "vn 0 1\n", 5, "a vertex normal needs x y z, got 2 numbers"),
                    Arguments.of("a malformed normal", SQUARE + "vn 0 1 z\n", 5, "malformed normal coordinate 'z'"),
                    Arguments.of("a zero normal", SQUARE + "vn 0 0 0\n", 5, "vertex normal (0.0,0.0,0.0) has zero length"),
                    Arguments.of("a normal too short for the zero tolerance", SQUARE + "vn 1e-13 0 0\n", 5, "vertex normal (1.0E-13,0.0,0.0) has zero length"),
                    Arguments.of("a face with two vertices", SQUARE + "f 1 2\n", 5, "a face needs at least 3 vertices, got 2"),
                    Arguments.of("a face with no vertex", SQUARE + "f\n", 5, "a face needs at least 3 vertices, got 0"),
                    Arguments.of("index 0", SQUARE + "f 0 1 2\n", 5, "vertex index 0 is invalid: OBJ indices start at 1"),
                    Arguments.of("an index past the last vertex", SQUARE + "f 1 2 5\n", 5, "vertex index 5 is out of range: 4 vertices defined before this line"),
                    Arguments.of("a negative index reaching before the first vertex", SQUARE + "f -5 1 2\n", 5, "vertex index -5 is out of range: 4 vertices"),
                    Arguments.of("a face before its vertices", "f 1 2 3\n" + SQUARE, 1, "vertex index 1 is out of range: no vertices defined before this line"),
                    Arguments.of("a malformed index", SQUARE + "f 1 2.5 3\n", 5, "malformed vertex index '2.5' in face vertex '2.5'"),
                    Arguments.of("an index beyond any integer", SQUARE + "f 1 2 99999999999999999999\n", 5, "malformed vertex index '99999999999999999999'"),
                    Arguments.of("a texture index without texture coordinates", SQUARE + "f 1/1 2/1 3/1\n", 5, "texture coordinate index 1 is out of range: no texture coordinates"),
                    Arguments.of("a malformed texture index", SQUARE + "vt 0 0\nf 1/a 2/1 3/1\n", 6, "malformed texture coordinate index 'a' in face vertex '1/a'"),
                    Arguments.of("a normal index past the last normal", SQUARE + "vn 0 0 1\nf 1//1 2//2 3//1\n", 6, "normal index 2 is out of range: 1 normal defined before this line"),
                    Arguments.of("an empty normal index", SQUARE + "f 1// 2// 3//\n", 5, "face vertex '1//' has an empty normal index"),
                    Arguments.of("an empty texture index", SQUARE + "f 1/ 2/ 3/\n", 5, "face vertex '1/' has an empty texture coordinate index"),
                    Arguments.of("an empty vertex index", SQUARE + "f /1 2 3\n", 5, "face vertex '/1' has an empty vertex index"),
                    Arguments.of("four parts in a corner", SQUARE + "vn 0 0 1\nvt 0 0\nf 1/1/1/1 2 3\n", 7, "face vertex '1/1/1/1' has more than three parts"),
                    Arguments.of("a vertex repeated in a face", SQUARE + "f 1 2 2\n", 5, "degenerate face: vertices 1 (0.0,0.0,0.0), 2 (1.0,0.0,0.0), 2 (1.0,0.0,0.0) coincide or are collinear"),
                    Arguments.of("a face of collinear vertices", fiveVertices + "f 1 2 5\n", 6, "degenerate face: vertices 1 (0.0,0.0,0.0), 2 (1.0,0.0,0.0), 5 (2.0,0.0,0.0)"),
                    Arguments.of("a quad whose second fan triangle is degenerate", fiveVertices + "f 2 4 1 5\n", 6, "degenerate triangle (corners 1, 3, 4) of a 4-vertex face"),
                    Arguments.of("no faces", SQUARE, 4, "no faces: an OBJ mesh needs at least one 'f' line"),
                    Arguments.of("nothing at all", "", 0, "no faces"),
                    Arguments.of("an error after comments and blank lines", "# header\n\n" + SQUARE + "\n# more\nv a b c\n", 9, "malformed vertex coordinate 'a'"));
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("malformed")
        @DisplayName("fails naming the source, the line and what is wrong:")
        void reportsLine(String what, String text, int line, String problem) {
            ObjFormatException e = catchThrowableOfType(ObjFormatException.class, () -> read(text));
            assertThat(e).as("exception").isNotNull();
            assertThat(e.getSource()).isEqualTo("test.obj");
            assertThat(e.getLine()).isEqualTo(line);
            assertThat(e.getProblem()).contains(problem);
            assertThat(e).hasMessage("test.obj:" + line + ": " + e.getProblem());
        }
    }

    @Nested
    @DisplayName("a mesh that does not fit the heap: one line")
    class OutOfMemory {
        private static final long MB = 1 << 20;

        @Test
        @DisplayName("names the file, its size, the triangles and vertices read, the limit and -Xmx")
        void midway() {
            assertThat(ObjReader.memoryMessage("meshes/big.obj", 147 * MB + 123, 2_104_533, 1_052_270, false, 900 * MB))
                    .isEqualTo("the OBJ file meshes/big.obj (147 MB) did not fit in memory: 2104533 triangles and 1052270"
                            + " vertices read when Java ran out; Java may use at most 900 MB here (give Java more memory"
                            + " with -Xmx; on Spark's driver, spark-submit --driver-memory)");
        }

        @Test
        @DisplayName("read whole, before any vertex, a small file, an unknown size, no limit; a control character escaped")
        void cases() {
            assertThat(ObjReader.memoryMessage("a.obj", 5_046_994, 178_802, 90_000, true, 32 * MB))
                    .startsWith("the OBJ file a.obj (4.8 MB) did not fit in memory: read whole (178802 triangles, 90000"
                            + " vertices), Java ran out making the mesh; Java may use at most 32 MB here");
            assertThat(ObjReader.memoryMessage("a.obj", 20 * MB, 0, 0, false, 16 * MB))
                    .startsWith("the OBJ file a.obj (20 MB) did not fit in memory: Java ran out before a vertex was read;");
            assertThat(ObjReader.memoryMessage("/models/teapot.obj", -1, 10, 20, false, Long.MAX_VALUE))
                    .isEqualTo("the OBJ file /models/teapot.obj did not fit in memory: 10 triangles and 20 vertices read when"
                            + " Java ran out (give Java more memory with -Xmx; on Spark's driver, spark-submit --driver-memory)");
            assertThat(ObjReader.memoryMessage("a\u009B.obj", 1, 0, 1, false, MB)).startsWith("the OBJ file a\\u009B.obj (0.0 MB)");
        }

        @Test
        @DisplayName("the error made from the JVM's: that message, with the JVM's as its cause")
        void error() {
            OutOfMemoryError jvm = new OutOfMemoryError("Java heap space");
            OutOfMemoryError named = ObjReader.outOfMemory(jvm, "a.obj", 3 * MB, 1, 3, false);
            assertThat(named).hasMessageStartingWith("the OBJ file a.obj (3.0 MB) did not fit in memory: 1 triangles and 3"
                    + " vertices read when Java ran out").hasCause(jvm);
        }
    }
}
