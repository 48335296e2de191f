package scene.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.ByteArrayInputStream;
import java.io.Reader;
import java.nio.charset.StandardCharsets;

import com.code_intelligence.jazzer.junit.FuzzTest;

import geometries.TriangleMesh;

/**
 * OBJ text from the fuzzer: every input either becomes a mesh or ends in one
 * {@link ObjFormatException} naming the source and line. Anything else (another exception, an
 * error, a hang) is a finding.
 *
 * <p>Without {@code JAZZER_FUZZ=1} this replays {@code ObjReaderFuzzTestInputs/read/}: the seed
 * corpus and every input a fuzzing run found (see docs/fuzzing.md).
 */
class ObjReaderFuzzTest {
    /** A closed cube, smooth-shaded: eight vertices, six normals, twelve triangles. */
    static final String CUBE = """
            # unit cube
            o cube
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0
            v 0 0 1
            v 1 0 1
            v 1 1 1
            v 0 1 1
            vt 0 0
            vn 0 0 -1
            vn 0 0 1
            vn 0 -1 0
            vn 0 1 0
            vn -1 0 0
            vn 1 0 0
            f 1//1 4//1 3//1 2//1
            f 5/1/2 6/1/2 7/1/2 8/1/2
            f 1//3 2//3 6//3 5//3
            f -5//4 -6//4 -2//4 -1//4
            f 1//5 5//5 8//5 4//5
            f 2//6 3//6 7//6 6//6
            """;

    @FuzzTest
    void read(byte[] content) throws IOException {
        try (Reader reader = new InputStreamReader(new ByteArrayInputStream(content), StandardCharsets.UTF_8)) {
            TriangleMesh mesh = ObjReader.read(reader, "fuzz.obj");
            assertThat(mesh).isNotNull();
        } catch (ObjFormatException e) {
            assertThat(e.getMessage()).startsWith("fuzz.obj:" + e.getLine() + ": ").doesNotContain("\n");
        }
    }
}
