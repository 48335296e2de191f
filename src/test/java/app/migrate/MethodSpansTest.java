package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/**
 * {@link MethodSpans} and {@link TestMethods#without}: test methods, their bounds and their
 * annotations come from javac's tree, so text in string literals, text blocks, character literals
 * and comments that looks like a test, a method or a brace neither makes one nor moves one.
 */
class MethodSpansTest {
    private static final String REASON = "Vector.rotate(int) is your own method";

    /** The 1-based line holding {@code fragment}'s first occurrence (a missing one fails the test). */
    private static long line(String text, String fragment) {
        int at = text.indexOf(fragment);
        assertThat(at).as("the sample holds %s", fragment).isNotNegative();
        return text.substring(0, at).chars().filter(c -> c == '\n').count() + 1;
    }

    private static List<MethodSpan> spans(String text) throws MigrationException {
        return new MethodSpans(Parsed.of(text, "Sample.java"), text).all();
    }

    private static String removedText(String text, MethodSpan span) {
        return text.substring(span.start(), span.end());
    }

    @Nested
    @DisplayName("text that only looks like a test is no test")
    class LooksLikeCode {
        private static final String TEXT = """
                class ParserTest {
                    @Test
                    @DisplayName("@Test void ghost() { }")
                    void parses() {
                        String s = "@Test void inString() { }";
                        String block = \"""
                                @ParameterizedTest
                                void inTextBlock() {
                                \""";
                        assertEquals(s, block); // @RepeatedTest void inLineComment() {
                    }

                    /* @TestFactory
                       void inBlockComment() { } */

                    @Test
                    void rotates() {
                        new Vector(1, 0, 0).rotate(90);
                    }
                }
                """;

        @Test
        @DisplayName("only the two methods javac parses are found, both tests, named as declared")
        void onlyRealMethods() throws MigrationException {
            assertThat(spans(TEXT)).extracting(MethodSpan::name).containsExactly("parses", "rotates");
            assertThat(spans(TEXT)).allMatch(MethodSpan::test);
        }

        @Test
        @DisplayName("an error on a line of a string, a text block or a comment takes out the method around it, nothing else")
        void errorInsideLiteralLine() throws MigrationException {
            for (String fragment : List.of("void inString", "void inTextBlock", "void inLineComment", "@DisplayName(\"@Test")) {
                TestMethods.Trimmed t = TestMethods.without(TEXT, "VectorTest.java", List.of(line(TEXT, fragment)), REASON);

                assertThat(t.removed()).as(fragment).containsExactly("parses");
                assertThat(t.text()).as(fragment).contains("void rotates() {").contains("/* @TestFactory")
                        .doesNotContain("inString").doesNotContain("inTextBlock").doesNotContain("inLineComment");
            }
        }

        @Test
        @DisplayName("a block comment between methods that holds a method is in no method: the whole file is left out")
        void errorOnCommentedMethod() throws MigrationException {
            assertThat(TestMethods.without(TEXT, "VectorTest.java", List.of(line(TEXT, "void inBlockComment")), REASON)).isNull();
        }

        @Test
        @DisplayName("a test method that only a comment or a string holds keeps no test: the whole file is left out")
        void commentedTestIsNoTestToKeep() throws MigrationException {
            String text = """
                    class ParserTest {
                        // @Test void stillHere() { }
                        String note = "@Test void alsoHere() { }";

                        @Test
                        void rotates() {
                            new Vector(1, 0, 0).rotate(90);
                        }
                    }
                    """;

            assertThat(TestMethods.without(text, "VectorTest.java", List.of(line(text, ".rotate(90)")), REASON)).isNull();
        }
    }

    @Nested
    @DisplayName("braces in literals and comments do not move a method's bounds")
    class Braces {
        private static final String BRACY = """
                    @Test
                    void braces() {
                        char open = '{', close = '}', quote = '"';
                        String s = "}}} {";
                        String block = \"""
                                }
                                \""";
                        /* } */ // }
                        assertEquals("{", s.substring(4)); /* { */
                    }
                """;
        private static final String TEXT = "class BraceTest {\n" + BRACY + """

                    @Test
                    void after() {
                        new Vector(1, 0, 0).rotate(90);
                    }
                }
                """;

        @Test
        @DisplayName("the method runs from its annotation to its own closing brace and the line break after it")
        void bounds() throws MigrationException {
            MethodSpan braces = spans(TEXT).get(0);

            assertThat(braces.name()).isEqualTo("braces");
            assertThat(removedText(TEXT, braces)).isEqualTo(BRACY);
        }

        @Test
        @DisplayName("taken out, it leaves the next method byte for byte; kept, it stays byte for byte")
        void takenOutOrKept() throws MigrationException {
            TestMethods.Trimmed first = TestMethods.without(TEXT, "VectorTest.java", List.of(line(TEXT, "/* } */")), REASON);
            TestMethods.Trimmed second = TestMethods.without(TEXT, "VectorTest.java", List.of(line(TEXT, ".rotate(90)")), REASON);

            assertThat(first.text()).isEqualTo(TEXT.replace(BRACY, "    // raytracer migrate: braces() left out: " + REASON + "\n"));
            assertThat(second.text()).startsWith("class BraceTest {\n" + BRACY).contains("// raytracer migrate: after() left out:");
            assertThat(second.removed()).containsExactly("after");
        }
    }

    @Nested
    @DisplayName("a file javac's parser does not read whole is left as it is")
    class DoesNotParseWhole {
        /** A missing semicolon in one test; the error line given lies in another test that parses fine. */
        private static final String TEXT = """
                class VectorTest {
                    @Test
                    void add() {
                        int broken = 1
                    }

                    @Test
                    void rotate() {
                        new Vector(1, 0, 0).rotate(90);
                    }

                    @Test
                    void scale() {
                    }
                }
                """;

        @Test
        @DisplayName("no method is taken out, even one far from the syntax error (a patched-up tree's bounds are a guess)")
        void leftAsIs() throws MigrationException {
            assertThat(TestMethods.without(TEXT, "VectorTest.java", List.of(line(TEXT, ".rotate(90)")), REASON)).isNull();
        }

        @Test
        @DisplayName("Parsed names the line of the syntax error, and MethodSpans refuses it naming that line")
        void namedLine() throws MigrationException {
            Parsed parsed = Parsed.of(TEXT, "VectorTest.java");

            assertThat(parsed.whole()).isFalse();
            assertThat(parsed.errorLines()).containsExactly(line(TEXT, "int broken"));
            assertThatThrownBy(() -> new MethodSpans(parsed, TEXT)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("lines [4]");
        }
    }
}
