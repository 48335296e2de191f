package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link TestMethods#without}: a student's test file with only its failing methods taken out,
 * found by javac's parser, the rest of the text byte for byte; and every case where the whole file
 * must be left out instead ({@code null}).
 */
class TestMethodsTest {
    private static final String REASON = "Vector.rotate(int) is your own method";

    /** The 1-based lines holding {@code fragments}, each its first occurrence (a missing one fails the test). */
    private static List<Long> lines(String text, String... fragments) {
        List<Long> found = new ArrayList<>();
        for (String fragment : fragments) {
            int at = text.indexOf(fragment);
            assertThat(at).as("the sample holds %s", fragment).isNotNegative();
            found.add(text.substring(0, at).chars().filter(c -> c == '\n').count() + 1);
        }
        return found;
    }

    private static TestMethods.Trimmed without(String text, String... errorFragments) throws MigrationException {
        return TestMethods.without(text, "VectorTest.java", lines(text, errorFragments), REASON);
    }

    /** The trimmed text still parses, and trimming it again with no error changes nothing. */
    private static void assertParses(String text) throws MigrationException {
        TestMethods.Trimmed again = TestMethods.without(text, "VectorTest.java", List.of(), REASON);
        assertThat(again).as("the result parses and keeps a test").isNotNull();
        assertThat(again.text()).isEqualTo(text);
        assertThat(again.removed()).isEmpty();
    }

    private static final String VECTOR_TEST = """
            package primitives;

            import static org.junit.jupiter.api.Assertions.assertEquals;

            import org.junit.jupiter.api.Test;

            class VectorTest {
                @Test
                void add() {
                    assertEquals(new Vector(2, 3, 4), new Vector(1, 2, 3).add(new Vector(1, 1, 1)));
                }

                @Test
                void rotate() {
                    assertEquals(new Vector(0, 1, 0), new Vector(1, 0, 0).rotate(90));
                }

                @Test
                void scale() {
                    assertEquals(new Vector(2, 4, 6), new Vector(1, 2, 3).scale(2));
                }
            }
            """;

    private static final String VECTOR_TEST_WITHOUT_ROTATE = """
            package primitives;

            import static org.junit.jupiter.api.Assertions.assertEquals;

            import org.junit.jupiter.api.Test;

            class VectorTest {
                @Test
                void add() {
                    assertEquals(new Vector(2, 3, 4), new Vector(1, 2, 3).add(new Vector(1, 1, 1)));
                }

                // raytracer migrate: rotate() left out: Vector.rotate(int) is your own method

                @Test
                void scale() {
                    assertEquals(new Vector(2, 4, 6), new Vector(1, 2, 3).scale(2));
                }
            }
            """;

    @Nested
    @DisplayName("takes out the failing test methods")
    class TakesOut {
        @Test
        @DisplayName("one failing method of three: replaced by one comment line, the rest byte for byte")
        void oneOfThree() throws MigrationException {
            TestMethods.Trimmed trimmed = without(VECTOR_TEST, ".rotate(90)");

            assertThat(trimmed.text()).isEqualTo(VECTOR_TEST_WITHOUT_ROTATE);
            assertThat(trimmed.removed()).containsExactly("rotate");
            assertParses(trimmed.text());
        }

        @ParameterizedTest(name = "an error on the line of {0}")
        @ValueSource(strings = { "@Test\n    void rotate", "void rotate()", "new Vector(1, 0, 0).rotate", "}\n\n    @Test\n    void scale" })
        @DisplayName("whichever line of the method javac names: its annotation, its header, its body, its closing brace")
        void anyLineOfTheMethod(String fragment) throws MigrationException {
            assertThat(without(VECTOR_TEST, fragment).text()).isEqualTo(VECTOR_TEST_WITHOUT_ROTATE);
        }

        @Test
        @DisplayName("two failing methods, several errors each, named in file order")
        void twoInFileOrder() throws MigrationException {
            TestMethods.Trimmed trimmed = without(VECTOR_TEST, ".scale(2)", "void scale", ".rotate(90)", "void rotate");

            assertThat(trimmed.removed()).containsExactly("rotate", "scale");
            assertParses(trimmed.text());
        }

        @Test
        @DisplayName("a test named as a method the remaining tests call (add() and v.add(...))")
        void testNamedAsCalledMethod() throws MigrationException {
            String text = VECTOR_TEST.replace("new Vector(1, 2, 3).scale(2)", "new Vector(1, 2, 3).add(new Vector(1, 2, 3))");

            assertThat(without(text, "void add").removed()).containsExactly("add");
        }

        @Test
        @DisplayName("its Javadoc and the comment lines directly above go with it; a comment after a blank line stays")
        void withItsJavadoc() throws MigrationException {
            String text = """
                    class VectorTest {
                        @Test
                        void add() {
                            assertEquals(1, 1);
                        } // add: done

                        // ---- rotation ----

                        /**
                         * A right angle.
                         */
                        // Javadoc is not enough
                        @Test
                        void rotate() {
                            new Vector(1, 0, 0).rotate(90);
                        }
                    }
                    """;
            TestMethods.Trimmed trimmed = without(text, ".rotate(90)");

            assertThat(trimmed.text()).isEqualTo("""
                    class VectorTest {
                        @Test
                        void add() {
                            assertEquals(1, 1);
                        } // add: done

                        // ---- rotation ----

                        // raytracer migrate: rotate() left out: Vector.rotate(int) is your own method
                    }
                    """);
            assertParses(trimmed.text());
        }

        @Test
        @DisplayName("its Javadoc even across a blank line (javac gives it to the method all the same)")
        void javadocAcrossBlankLine() throws MigrationException {
            String text = """
                    class VectorTest {
                        @Test
                        void add() {
                        }

                        /** A right angle. */

                        @Test
                        void rotate() { new Vector(1, 0, 0).rotate(90); } // a trailing comment goes too
                    }
                    """;

            assertThat(without(text, ".rotate(90)").text()).isEqualTo("""
                    class VectorTest {
                        @Test
                        void add() {
                        }

                        // raytracer migrate: rotate() left out: Vector.rotate(int) is your own method
                    }
                    """);
        }

        @Test
        @DisplayName("a method of a @Nested class, indented as it was")
        void nestedClass() throws MigrationException {
            String text = """
                    class CameraTest {
                        @Test
                        void builds() {
                            new Camera();
                        }

                        @Nested
                        class Rotation {
                            @Test
                            void turns() {
                                new Camera().rotate(90);
                            }

                            @Test
                            void keeps() {
                                new Camera();
                            }
                        }
                    }
                    """;
            TestMethods.Trimmed trimmed = without(text, ".rotate(90)");

            assertThat(trimmed.text()).isEqualTo("""
                    class CameraTest {
                        @Test
                        void builds() {
                            new Camera();
                        }

                        @Nested
                        class Rotation {
                            // raytracer migrate: turns() left out: Vector.rotate(int) is your own method

                            @Test
                            void keeps() {
                                new Camera();
                            }
                        }
                    }
                    """);
            assertThat(trimmed.removed()).containsExactly("turns");
        }

        @Test
        @DisplayName("a CRLF file keeps CRLF, in the comment line too")
        void crlf() throws MigrationException {
            String text = VECTOR_TEST.replace("\n", "\r\n");
            TestMethods.Trimmed trimmed = without(text, ".rotate(90)");

            assertThat(trimmed.text()).isEqualTo(VECTOR_TEST_WITHOUT_ROTATE.replace("\n", "\r\n"));
            assertParses(trimmed.text());
        }

        @Test
        @DisplayName("a file with a byte order mark, tabs and Hebrew comments")
        void bomTabsHebrew() throws MigrationException {
            String text = "\uFEFF" + VECTOR_TEST.replace("    ", "\t")
                    .replace("\t@Test\n\tvoid rotate", "\t// בדיקת סיבוב בזווית ישרה\n\t@Test\n\tvoid rotate")
                    .replace("class VectorTest {", "class VectorTest { // וקטורים");
            String expected = "\uFEFF" + VECTOR_TEST_WITHOUT_ROTATE.replace("    ", "\t")
                    .replace("class VectorTest {", "class VectorTest { // וקטורים");

            TestMethods.Trimmed trimmed = without(text, ".rotate(90)");

            assertThat(trimmed.text()).isEqualTo(expected);
            assertParses(trimmed.text());
        }

        @Test
        @DisplayName("a string literal and comments that look like code do not move the spans")
        void literalsAndComments() throws MigrationException {
            String text = """
                    class ParserTest {
                        @Test
                        void parses() {
                            String s = "@Test void x() {"; /* } } */
                            assertEquals(16, s.length()); // }
                        }

                        /* { a comment with braces { */
                        @Test
                        void fails() {
                            new Parser().parse("} @Test void y() {");
                        }

                        @Test
                        void last() {
                            char c = '}';
                        }
                    }
                    """;
            TestMethods.Trimmed first = without(text, "@Test void x");
            TestMethods.Trimmed second = without(text, "new Parser()");

            assertThat(first.text()).isEqualTo(text.replace("""
                        @Test
                        void parses() {
                            String s = "@Test void x() {"; /* } } */
                            assertEquals(16, s.length()); // }
                        }
                    """, "    // raytracer migrate: parses() left out: " + REASON + "\n"));
            assertThat(first.removed()).containsExactly("parses");
            assertThat(second.text()).isEqualTo(text.replace("""
                        /* { a comment with braces { */
                        @Test
                        void fails() {
                            new Parser().parse("} @Test void y() {");
                        }
                    """, "    // raytracer migrate: fails() left out: " + REASON + "\n"));
            assertThat(second.removed()).containsExactly("fails");
        }

        @Test
        @DisplayName("a JUnit 4 test (org.junit.Test, also written in full) is a test method")
        void junit4() throws MigrationException {
            String text = """
                    import static org.junit.Assert.assertEquals;

                    import org.junit.Test;

                    public class PointTest {
                        @Test
                        public void distance() {
                            assertEquals(5, new Point(0, 0, 0).distanceTo(new Point(3, 4, 0)), 1e-9);
                        }

                        @org.junit.Test
                        public void add() {
                            assertEquals(new Point(1, 1, 1), Point.ZERO.add(new Vector(1, 1, 1)));
                        }
                    }
                    """;

            assertThat(without(text, "distanceTo").removed()).containsExactly("distance");
            assertThat(without(text, "Point.ZERO").removed()).containsExactly("add");
            assertThat(without(text, "distanceTo", "Point.ZERO")).as("no test would be left").isNull();
        }

        @Test
        @DisplayName("no error line: the text as it is")
        void noError() throws MigrationException {
            TestMethods.Trimmed trimmed = TestMethods.without(VECTOR_TEST, "VectorTest.java", List.of(), REASON);

            assertThat(trimmed.text()).isEqualTo(VECTOR_TEST);
            assertThat(trimmed.removed()).isEmpty();
        }

        @Test
        @DisplayName("the reason on one line, with no backslash javac would read as a Unicode escape")
        void reasonOnOneLine() throws MigrationException {
            TestMethods.Trimmed trimmed = TestMethods.without(VECTOR_TEST, "VectorTest.java", lines(VECTOR_TEST, ".rotate(90)"),
                    "first\r\nsecond\nthird\rin C:\\users\\u000a");

            assertThat(trimmed.text()).contains("    // raytracer migrate: rotate() left out: first second third in C:\\\\users\\\\u000a\n\n");
            assertParses(trimmed.text());
        }

        @Test
        @DisplayName("a method sharing its closing line with code: the code starts the next line")
        void codeAfterClosingBrace() throws MigrationException {
            String text = """
                    class VectorTest {
                        @Test
                        void add() {
                        }
                        @Test
                        void rotate() {
                            new Vector(1, 0, 0).rotate(90);
                        } }
                    """;

            assertThat(without(text, ".rotate(90)").text()).isEqualTo("""
                    class VectorTest {
                        @Test
                        void add() {
                        }
                        // raytracer migrate: rotate() left out: Vector.rotate(int) is your own method
                     }
                    """);
        }
    }

    @Nested
    @DisplayName("takes out a helper method with an error")
    class Helpers {
        private static final String TEXT = """
                class VectorTest {
                    @Test
                    void add() {
                        assertEquals(new Vector(2, 2, 2), new Vector(1, 1, 1).scale(2));
                    }

                    @Test
                    void rotate() {
                        assertEquals(new Vector(0, 1, 0), turned());
                    }

                    private Vector turned() {
                        return new Vector(1, 0, 0).rotate(90);
                    }
                }
                """;

        @Test
        @DisplayName("when no remaining method calls it")
        void unused() throws MigrationException {
            TestMethods.Trimmed trimmed = without(TEXT.replace("turned());", "new Vector(0, 1, 0));"), ".rotate(90)");

            assertThat(trimmed.text()).endsWith("""
                        }

                        // raytracer migrate: turned() left out: Vector.rotate(int) is your own method
                    }
                    """);
            assertThat(trimmed.removed()).containsExactly("turned");
        }

        @Test
        @DisplayName("with the failing tests that call it")
        void withItsCallers() throws MigrationException {
            TestMethods.Trimmed trimmed = without(TEXT, ".rotate(90)", "turned());");

            assertThat(trimmed.removed()).containsExactly("rotate", "turned");
            assertParses(trimmed.text());
        }

        @ParameterizedTest(name = "called as {0}")
        @ValueSource(strings = { "turned()", "this.turned()", "Optional.of(this).map(VectorTest::turned).get()" })
        @DisplayName("not when a remaining method still calls it: the whole file is left out")
        void stillCalled(String call) throws MigrationException {
            String text = TEXT.replace("new Vector(1, 1, 1).scale(2)", call);

            assertThat(without(text, ".rotate(90)")).isNull();
        }

        @Test
        @DisplayName("not when a remaining field calls it")
        void calledByField() throws MigrationException {
            String text = TEXT.replace("class VectorTest {\n", "class VectorTest {\n    private final Vector v = turned();\n");

            assertThat(without(text, ".rotate(90)")).isNull();
        }

        @Test
        @DisplayName("not when it is the @MethodSource of a remaining test")
        void methodSource() throws MigrationException {
            String text = TEXT.replace("    @Test\n    void add() {", "    @ParameterizedTest\n    @MethodSource(\"turned\")\n    void add(Vector v) {");

            assertThat(without(text, ".rotate(90)")).isNull();
        }
    }

    @Nested
    @DisplayName("leaves the whole file out (null)")
    class WholeFile {
        private static final String TEXT = """
                package primitives;

                import static org.junit.jupiter.api.Assertions.assertEquals;

                import org.junit.jupiter.api.BeforeEach;
                import org.junit.jupiter.api.Test;

                /** Vectors. */
                class VectorTest {
                    private final double limit = Vector.LIMIT;
                    private Vector v;

                    static {
                        Vector.warmUp();
                    }

                    VectorTest() {
                        Vector.count();
                    }

                    @BeforeEach
                    void setUp() {
                        v = new Vector(1, 2, 3);
                    }

                    @Override
                    public String toString() {
                        return v.describe();
                    }

                    @Test
                    void add() {
                        assertEquals(new Vector(2, 3, 4), v.add(new Vector(1, 1, 1)));
                    }

                    @Test
                    void rotate() {
                        assertEquals(new Vector(0, 1, 0), new Vector(1, 0, 0).rotate(90));
                    }
                } // end
                """;

        @ParameterizedTest(name = "an error on the line of {0}")
        @ValueSource(strings = { "package primitives", "import static", "import org.junit.jupiter.api.Test",
                "/** Vectors. */", "class VectorTest", "Vector.LIMIT", "private Vector v;", "static {", "Vector.warmUp",
                "VectorTest() {", "Vector.count", "new Vector(1, 2, 3);", "@Override", "v.describe()", "} // end" })
        @DisplayName("an error outside a method that can go: import, field, class header, initializer, constructor, @BeforeEach, override")
        void outsideRemovableMethod(String fragment) throws MigrationException {
            assertThat(without(TEXT, ".rotate(90)", fragment)).isNull();
        }

        @Test
        @DisplayName("the sample itself trims (the nulls above come from the named line)")
        void sampleTrims() throws MigrationException {
            assertThat(without(TEXT, ".rotate(90)").removed()).containsExactly("rotate");
        }

        @Test
        @DisplayName("every test method fails")
        void allTestsFail() throws MigrationException {
            assertThat(without(VECTOR_TEST, "void add", ".rotate(90)", ".scale(2)")).isNull();
        }

        @ParameterizedTest(name = "the file \"{0}\"")
        @ValueSource(strings = { "", "class VectorTest {}", "class VectorTest { void helper() { } }" })
        @DisplayName("a file with no test method, even without an error")
        void noTestMethod(String text) throws MigrationException {
            assertThat(TestMethods.without(text, "VectorTest.java", List.of(), REASON)).isNull();
        }

        @Test
        @DisplayName("the file does not parse")
        void doesNotParse() throws MigrationException {
            String text = VECTOR_TEST.replace("void scale() {", "void scale() {{");

            assertThat(without(text, ".rotate(90)")).isNull();
        }

        @ParameterizedTest(name = "line {0}")
        @ValueSource(longs = { 0, -1, 23, 1000 })
        @DisplayName("an error line the file does not have")
        void noSuchLine(long line) throws MigrationException {
            Collection<Long> errors = List.of(line);

            assertThat(TestMethods.without(VECTOR_TEST, "VectorTest.java", errors, REASON)).isNull();
        }

        @Test
        @DisplayName("an error on a line shared by two methods")
        void sharedLine() throws MigrationException {
            String text = VECTOR_TEST.replace("    }\n\n    @Test\n    void scale() {", "    } @Test void scale() {");

            assertThat(without(text, "void scale")).isNull();
        }
    }
}
