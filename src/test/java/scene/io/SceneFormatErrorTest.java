package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every kind of bad scene file gives one {@link SceneFormatException} whose message is
 * {@code FILE:LINE:COLUMN: what (expected …)}, pointing at the offending element or attribute.
 * Positions are counted by hand from the inline files (columns are 1-based).
 */
class SceneFormatErrorTest {
    @TempDir
    Path dir;

    /** Three lines: the bad element is always on line 3, indented by 4 (its '<' at column 5). */
    private static String inGeometries(String element) {
        return "<scene>\n  <geometries>\n    " + element + "\n  </geometries>\n</scene>\n";
    }

    private static String inScene(String element) {
        return "<scene>\n  " + element + "\n</scene>\n";
    }

    static Stream<Arguments> badFiles() {
        return Stream.of(
                // name, file, line, column, part of the message
                Arguments.of("malformed XML: unclosed element",
                        inGeometries("<sphere center=\"0 0 -100\" radius=\"5\">"), 4, 5,
                        "malformed XML: The element type \"sphere\" must be terminated by the matching end-tag"),
                Arguments.of("malformed XML: empty file", "", 1, 1, "malformed XML: Premature end of file"),
                Arguments.of("malformed XML: unquoted attribute", inScene("<image width=5/>"), 2, 16,
                        "malformed XML: Open quote is expected for attribute \"width\""),
                Arguments.of("DOCTYPE with an external entity (XXE)",
                        "<?xml version=\"1.0\"?>\n<!DOCTYPE scene [<!ENTITY x SYSTEM \"file:///etc/passwd\">]>\n<scene name=\"&x;\"/>\n",
                        2, 10, "a DOCTYPE declaration (expected a scene file without DTD or entities"),
                Arguments.of("wrong root element", "<scenes/>\n", 1, 1, "the root element is <scenes> (expected <scene>)"),
                Arguments.of("unknown element", inGeometries("<spher center=\"0 0 -100\" radius=\"5\"/>"), 3, 5,
                        "unknown element <spher> in <geometries> (expected one of: sphere, plane, polygon, triangle, tube, cylinder, mesh)"),
                Arguments.of("unknown child of a geometry",
                        inGeometries("<sphere center=\"0 0 0\" radius=\"5\"> <materials/> </sphere>"), 3, 40,
                        "unknown element <materials> in <sphere> (expected one of: material)"),
                Arguments.of("unknown attribute", inGeometries("<sphere center=\"0 0 -100\" radius=\"5\" colour=\"1 2 3\"/>"),
                        3, 42, "unknown attribute 'colour' on <sphere> (expected one of: center, radius, emission)"),
                Arguments.of("second <camera>", "<scene>\n  <camera/>\n  <camera/>\n</scene>", 3, 3,
                        "a second <camera> in <scene> (expected at most one, the first is at line 2)"),
                Arguments.of("text where only elements belong", inGeometries("<sphere center=\"0 0 0\" radius=\"5\"/> hello"),
                        3, 41, "unexpected text \"hello\" in <geometries> (expected only elements"),
                Arguments.of("missing required attribute", inGeometries("<sphere center=\"0 0 -100\"/>"), 3, 5,
                        "<sphere> is missing attribute 'radius' (expected a positive number)"),
                Arguments.of("malformed number", inGeometries("<sphere center=\"0 0 -100\" radius=\"abc\"/>"), 3, 31,
                        "<sphere radius=\"abc\">: 'abc' is not a number (expected a positive number)"),
                Arguments.of("decimal comma", inGeometries("<sphere center=\"0 0 -100\" radius=\"2,5\"/>"), 3, 31,
                        "'2,5' is not a number"),
                Arguments.of("NaN", inGeometries("<sphere center=\"0 0 -100\" radius=\"NaN\"/>"), 3, 31,
                        "'NaN' is not a finite number (expected a positive number)"),
                Arguments.of("Infinity in a triple", inGeometries("<sphere center=\"0 -Infinity 0\" radius=\"1\"/>"), 3, 13,
                        "<sphere center=\"0 -Infinity 0\">: '-Infinity' is not a finite number (expected a point \"x y z\")"),
                Arguments.of("a number too large to be finite", inGeometries("<sphere center=\"0 0 0\" radius=\"1e999\"/>"), 3, 28,
                        "'1e999' is not a finite number (too large)"),
                Arguments.of("a triple with two numbers", inGeometries("<sphere center=\"0 0\" radius=\"1\"/>"), 3, 13,
                        "<sphere center=\"0 0\">: found 2 values where 3 are needed (expected a point \"x y z\")"),
                Arguments.of("a negative radius", inGeometries("<sphere center=\"0 0 0\" radius=\"-5\"/>"), 3, 28,
                        "-5 is not positive (expected a positive number)"),
                Arguments.of("a negative colour", inGeometries("<sphere center=\"0 0 0\" radius=\"5\" emission=\"10 -1 0\"/>"),
                        3, 39, "colour component -1 is negative (expected a colour \"r g b\""),
                Arguments.of("collinear triangle points (the library's message)",
                        inGeometries("<triangle p0=\"0 0 0\" p1=\"1 1 1\" p2=\"2 2 2\"/>"), 3, 5,
                        "invalid <triangle>: polygon points must not be collinear, got (0.0,0.0,0.0), (1.0,1.0,1.0), (2.0,2.0,2.0)"
                                + " (expected three distinct points not on one line)"),
                Arguments.of("concave polygon",
                        inGeometries("<polygon p0=\"0 0 0\" p1=\"4 0 0\" p2=\"1 1 0\" p3=\"0 4 0\"/>"), 3, 5,
                        "invalid <polygon>: polygon must be convex with vertices in order"),
                Arguments.of("polygon with a gap in its vertices",
                        inGeometries("<polygon p0=\"0 0 0\" p1=\"4 0 0\" p2=\"4 4 0\" p4=\"0 4 0\"/>"), 3, 47,
                        "unknown attribute 'p4' on <polygon> (expected one of: p0, p1, p2, p3, emission)"),
                Arguments.of("a zero normal", inGeometries("<plane point=\"0 0 0\" normal=\"0 0 0\"/>"), 3, 26,
                        "the zero vector has no direction (expected a non-zero vector \"x y z\")"),
                Arguments.of("a plane given both ways", inGeometries("<plane p0=\"0 0 0\" point=\"0 0 0\" normal=\"0 0 1\"/>"),
                        3, 12, "<plane> takes either p0, p1, p2 or point and normal, not both"),
                Arguments.of("kt above 1 (the library's message)",
                        inGeometries("<sphere center=\"0 0 0\" radius=\"5\"><material kt=\"1.5\"/></sphere>"), 3, 49,
                        "<material kt=\"1.5\">: kT components must be in [0, 1]"),
                Arguments.of("index of refraction 0",
                        inGeometries("<sphere center=\"0 0 0\" radius=\"5\"><material ior=\"0\"/></sphere>"), 3, 49,
                        "0 is not positive (expected a positive number)"),
                Arguments.of("infinite index of refraction",
                        inGeometries("<sphere center=\"0 0 0\" radius=\"5\"><material ior=\"Infinity\"/></sphere>"), 3, 49,
                        "(expected a positive number)"),
                Arguments.of("fractional shininess",
                        inGeometries("<sphere center=\"0 0 0\" radius=\"5\"><material shininess=\"2.5\"/></sphere>"), 3, 49,
                        "'2.5' is not an integer (expected an integer ≥ 0)"),
                Arguments.of("negative light attenuation",
                        "<scene>\n  <lights>\n    <point-light color=\"1 1 1\" position=\"0 0 0\" kq=\"-1\"/>\n  </lights>\n</scene>",
                        3, 49, "-1 is negative (expected a number ≥ 0)"),
                Arguments.of("unknown anti-aliasing mode", inScene("<render><anti-aliasing mode=\"fast\"/></render>"), 2, 26,
                        "'fast' is not a known value (expected one of: none, random, corners, adaptive)"),
                Arguments.of("a boolean that is not one", inScene("<render bvh=\"yes\"/>"), 2, 11,
                        "'yes' is not a boolean (expected true or false)"),
                Arguments.of("thread count -3 (the library's message)", inScene("<render threads=\"-3\"/>"), 2, 11,
                        "thread count must be 0 (calling thread), a positive number, or -1 or -2 (all cores), got -3 (expected 0 (the"
                                + " calling thread), a number of threads up to 8 per core, or -1 or -2 (all cores))"),
                Arguments.of("adaptive depth 7 (the library's message)",
                        inScene("<render><anti-aliasing mode=\"adaptive\" depth=\"7\"/></render>"), 2, 42,
                        "adaptive depth must be in 1..6, got 7 (expected an integer from 1 to 6)"),
                Arguments.of("a zero image width", inScene("<image width=\"0\"/>"), 2, 10,
                        "0 is less than 1 (expected an integer ≥ 1)"),
                // 50000 × 50000 = 2,500,000,000 > 2^31 - 9 = 2,147,483,639 pixels (one int array).
                Arguments.of("an image of too many pixels, before a camera: at <image width>, not at <camera>",
                        inScene("<image width=\"50000\" height=\"50000\"/>\n  <camera location=\"0 0 0\" target=\"0 0 -1\""
                                + " vp-size=\"1\" vp-distance=\"1\"/>"), 2, 10,
                        "<image width=\"50000\">: image size 50000x50000 is 2500000000 pixels, more than an image can hold"
                                + " (2147483639) (expected width × height at most 2147483639 pixels)"),
                Arguments.of("an image of too many pixels by its height alone (width 500 by default): at height",
                        inScene("<image height=\"5000000\"/>"), 2, 10,
                        "<image height=\"5000000\">: image size 500x5000000 is 2500000000 pixels"),
                Arguments.of("camera without a direction",
                        inScene("<camera location=\"0 0 0\" vp-size=\"1\" vp-distance=\"1\"/>"), 2, 3,
                        "<camera> is missing its view direction (expected attributes direction and up, or target)"),
                Arguments.of("camera up not orthogonal to the direction",
                        inScene("<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 1\" vp-size=\"1\" vp-distance=\"1\"/>"),
                        2, 47, "must be orthogonal (expected an up vector orthogonal to the direction)"),
                Arguments.of("camera target at its location",
                        inScene("<camera location=\"1 2 3\" target=\"1 2 3\" vp-size=\"1\" vp-distance=\"1\"/>"), 2, 3,
                        "invalid <camera>: camera target (1.0,2.0,3.0) is the camera location"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badFiles")
    @DisplayName("one message with file, line, column, what was wrong and what was expected")
    void badFile(String name, String xml, int line, int column, String message) throws IOException {
        Path file = dir.resolve("bad.xml");
        Files.writeString(file, xml);
        SceneFormatException e = catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(file));
        assertThat(e).as("reading must fail").isNotNull();
        assertThat(e.getReason()).contains(message).contains("(expected ");
        assertThat(new int[] { e.getLine(), e.getColumn() }).as("line and column").containsExactly(line, column);
        assertThat(e.getMessage()).isEqualTo(file + ":" + line + ":" + column + ": " + e.getReason())
                .doesNotContain("\n");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "up not orthogonal to the direction | location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 1\"",
            "target at the location             | location=\"1 2 3\" target=\"1 2 3\"" })
    @DisplayName("a camera the library refuses: the library's exception is the cause, its message in the reason")
    void cameraCause(String name, String view) throws IOException {
        Path file = dir.resolve("camera.xml");
        Files.writeString(file, inScene("<camera " + view + " vp-size=\"1\" vp-distance=\"1\"/>"));
        SceneFormatException e = catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(file));
        assertThat(e.getCause()).isInstanceOf(IllegalArgumentException.class);
        assertThat(e.getReason()).contains(e.getCause().getMessage());
    }

    /** Writes {@code content} into {@code file} and reads it, which must fail. */
    private static SceneFormatException readFails(Path file, String content) throws IOException {
        Files.writeString(file, content);
        return catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(file));
    }

    @Test
    @DisplayName("a mesh file that does not exist: reported at the file attribute, with the resolved path")
    void missingMesh() throws IOException {
        Path file = dir.resolve("mesh.xml");
        SceneFormatException e = readFails(file, inGeometries("<mesh file=\"models/absent.obj\"/>"));
        assertThat(e.getMessage()).isEqualTo(file + ":3:11: <mesh file=\"models/absent.obj\">: cannot read "
                + dir.resolve("models/absent.obj") + ": no such file"
                + " (expected an OBJ file; a relative path starts at the scene file's folder)");
    }

    @Test
    @DisplayName("a malformed mesh file: the OBJ reader's message with the OBJ line")
    void malformedMesh() throws IOException {
        Path file = dir.resolve("mesh.xml");
        Files.writeString(dir.resolve("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 one 0\nf 1 2 3\n");
        Files.writeString(file, inGeometries("<mesh file=\"bad.obj\"/>"));
        SceneFormatException e = catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(file));
        assertThat(e.getMessage()).startsWith(file + ":3:11: <mesh file=\"bad.obj\">: " + dir.resolve("bad.obj") + ":3: ")
                .endsWith("(expected an OBJ file; a relative path starts at the scene file's folder)");
    }

    @Test
    @DisplayName("a hostile mesh line: its C1 control and direction override escaped in the message, never sent raw to a terminal")
    void hostileMeshLine() throws IOException {
        Path file = dir.resolve("hostile.xml");
        Files.writeString(dir.resolve("hostile.obj"), "v 0 0 0\nv 1 0 0\nv 0 \u009B31m\u202E 0\nf 1 2 3\n");
        Files.writeString(file, inGeometries("<mesh file=\"hostile.obj\"/>"));
        SceneFormatException e = catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(file));
        assertThat(e.getMessage()).contains("'\\u009B31m\\u202E'").doesNotContain("\u009B", "\u202E");
        assertThat(e.getMessage().codePoints().filter(cp -> Messages.hidden(cp) != null)).isEmpty();
    }

    @Test
    @DisplayName("bytes that are not UTF-8")
    void notUtf8() throws IOException {
        Path file = dir.resolve("latin1.xml");
        // The byte E9 alone (an ISO-8859-1 'é') is not UTF-8; it follows '<image name="é' (a
        // UTF-8 'é', 2 bytes but one column) on line 2: column 15.
        byte[] head = "<scene>\n<image name=\"é".getBytes(StandardCharsets.UTF_8);
        byte[] bytes = Arrays.copyOf(head, head.length + 4);
        bytes[head.length] = (byte) 0xE9;
        bytes[head.length + 1] = '"';
        bytes[head.length + 2] = '/';
        bytes[head.length + 3] = '>';
        Files.write(file, bytes);
        SceneFormatException e = catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(file));
        assertThat(e.getMessage()).isEqualTo(file + ":2:15: bytes that are not UTF-8 (expected an XML scene file encoded in UTF-8)");
    }

    @Test
    @DisplayName("a scene without a camera cannot be rendered: the error points at <scene>")
    void noCamera() throws Exception {
        Path file = dir.resolve("nocamera.xml");
        Files.writeString(file, "<?xml version=\"1.0\"?>\n  <scene/>");
        LoadedScene loaded = XmlSceneReader.read(file);
        SceneFormatException e = catchThrowableOfType(SceneFormatException.class, loaded::requireCamera);
        assertThat(e.getMessage()).isEqualTo(file + ":2:3: the scene has no <camera> (expected a <camera> element inside <scene> to render it)");
    }

    @Test
    @DisplayName("CRLF line ends count as one line break")
    void crlf() throws IOException {
        Path file = dir.resolve("crlf.xml");
        Files.writeString(file, "<scene>\r\n\r\n  <geometries>\r\n    <sphere center=\"0 0 0\" radius=\"x\"/>\r\n  </geometries>\r\n</scene>");
        SceneFormatException e = catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(file));
        assertThat(new int[] { e.getLine(), e.getColumn() }).containsExactly(4, 28);
    }

    @Test
    @DisplayName("a missing file is an IOException, not a format error")
    void missingFile() {
        Path file = dir.resolve("absent.xml");
        assertThat(catchThrowableOfType(IOException.class, () -> XmlSceneReader.read(file))).isNotNull();
    }

    @Test
    @DisplayName("an image name with a right-to-left override: refused, the message quoting it escaped, on one line")
    void invisibleCharacterQuoted() throws IOException {
        Path file = dir.resolve("rlo.xml");
        assertThat(readFails(file, inScene("<image name=\"abc\u202Egnp&#10;x\"/>")).getMessage())
                .startsWith(file + ":2:10: <image name=\"abc\\u202Egnp\\u000Ax\">: the image name contains U+202E, an"
                        + " invisible or direction-changing character").doesNotContain("\u202E", "\n");
    }

    @Nested
    @DisplayName("mesh files: OBJ files inside the scene file's folder only, refused unread otherwise")
    class MeshFiles {
        private static final String QUAD = "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n";

        private SceneFormatException refused(Path scene, String mesh) throws IOException {
            return readFails(scene, inGeometries("<mesh file=\"" + mesh + "\"/>"));
        }

        private String allowed() throws IOException {
            return " (expected an OBJ file inside " + dir.toAbsolutePath().normalize()
                    + "; the command line's --mesh-root DIR allows another folder)";
        }

        @ParameterizedTest(name = "{0}")
        @CsvSource({ "/etc/passwd", "/proc/self/status", "cube.txt", "models" })
        @DisplayName("not an OBJ file by its name: refused before it is opened")
        void notObj(String mesh) throws IOException {
            Path scene = dir.resolve("scene.xml");
            SceneFormatException e = refused(scene, mesh);
            Path resolved = scene.resolveSibling(mesh);
            assertThat(e.getMessage()).isEqualTo(scene + ":3:11: <mesh file=\"" + mesh + "\">: " + resolved
                    + " is not an OBJ file (its name does not end in .obj)" + allowed());
        }

        @ParameterizedTest(name = "{0}")
        @CsvSource({ "../outside.obj", "/tmp/outside.obj", "sub/../../outside.obj" })
        @DisplayName("outside the scene's folder by its path: refused")
        void outside(String mesh) throws IOException {
            Files.writeString(dir.getParent().resolve("outside.obj"), QUAD);
            Path scene = dir.resolve("scene.xml");
            SceneFormatException e = refused(scene, mesh);
            assertThat(e.getMessage()).isEqualTo(scene + ":3:11: <mesh file=\"" + mesh + "\">: " + scene.resolveSibling(mesh)
                    + " is outside the folder meshes are read from" + allowed());
        }

        @Test
        @DisplayName("a link inside the folder that leads out: refused")
        void link() throws IOException {
            Path target = Files.writeString(Files.createTempFile("outside", ".obj"), QUAD);
            try {
                Files.createSymbolicLink(dir.resolve("link.obj"), target);
                Path scene = dir.resolve("scene.xml");
                assertThat(refused(scene, "link.obj").getMessage()).isEqualTo(scene + ":3:11: <mesh file=\"link.obj\">: "
                        + dir.resolve("link.obj") + " leads outside the folder meshes are read from (through a link)" + allowed());
            } finally {
                Files.delete(target);
            }
        }

        @Test
        @DisplayName("a sub-folder is inside; another root allows a file beside the scene's folder")
        void inside() throws Exception {
            Files.createDirectories(dir.resolve("models"));
            Files.writeString(dir.resolve("models/quad.OBJ"), QUAD);
            Path scene = dir.resolve("scenes/scene.xml");
            Files.createDirectories(scene.getParent());
            Files.writeString(scene, inGeometries("<mesh file=\"../models/quad.OBJ\"/>"));
            assertThat(catchThrowableOfType(SceneFormatException.class, () -> XmlSceneReader.read(scene)).getMessage())
                    .contains("is outside the folder meshes are read from");
            assertThat(XmlSceneReader.read(scene, FileSource.DISK, dir).scene().geometries.getItems()).hasSize(1);
        }
    }
}
