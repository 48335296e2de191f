package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Set;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/** Where a test names the student's namesake of a library class: names in the code, not words in strings or comments. */
@DisplayName("the lines that name a class")
class JavaNamesTest {
    private static final String TEST = """
            package geometries;

            import org.junit.jupiter.api.Test;

            // BoundingBox: the student's own, see below
            class BoxTests {
                @Test
                void message() {
                    String s = "BoundingBox";
                }

                @Test
                void box() {
                    BoundingBox b = new BoundingBox();
                    Object c = geometries
                            .BoundingBox.class;
                }
            }
            """;

    @Test
    @DisplayName("a use as a type, a constructor call and a qualified name count, each on its own line")
    void names() throws Exception {
        assertThat(JavaNames.lines(TEST, "BoxTests.java", Set.of("BoundingBox"))).containsExactly(14L, 16L);
        assertThat(JavaNames.firstLine(TEST, "BoxTests.java", "BoundingBox")).isEqualTo(14);
    }

    @Test
    @DisplayName("a string literal or a comment that spells the name does not count")
    void notWords() throws Exception {
        String words = "class Notes {\n    // BoundingBox\n    String s = \"BoundingBox\";\n}\n";
        assertThat(JavaNames.lines(words, "Notes.java", Set.of("BoundingBox"))).isEmpty();
        assertThat(JavaNames.firstLine(words, "Notes.java", "BoundingBox")).isZero();
    }
}
