package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/**
 * A kept source is rewritten through javac's parser: names change where they are names (package
 * and import lines, qualified names in the code), never inside a string literal or a comment.
 */
@DisplayName("a kept source pointed at the library")
class SourceRewriteTest {
    private static final Map<String, String> MATERIAL = Map.of("lighting.Material", "primitives.Material");

    @Nested
    @DisplayName("the 2025-26 packages folded")
    class Fold {
        @Test
        @DisplayName("in package and import lines, static ones and wildcards too")
        void lines() throws Exception {
            assertThat(SourceRewrite.fold("package geometries.impl;\nimport geometries.api.Intersectable;\nimport lighting.impl.*;\n"
                    + "import static geometries.api.Intersectable.Intersection;\n"))
                    .isEqualTo("package geometries;\nimport geometries.Intersectable;\nimport lighting.*;\n"
                            + "import static geometries.Intersectable.Intersection;\n");
        }

        @Test
        @DisplayName("in a qualified name in the code, but not in a string literal or a comment that spells it")
        void notInStringsOrComments() throws Exception {
            String text = """
                    package geometries.impl;

                    // moved from geometries.impl.Sphere, see geometries.api.Intersectable
                    class Cube {
                        /* geometries.api.Intersectable is the course's interface */
                        static final String NAME = "geometries.api.Intersectable";
                        geometries.api.Intersectable shape = null;
                        Object o = geometries . api . Intersectable.class;
                        String s = "lighting.impl." + geometries.impl.Cube.class.getName();
                    }
                    """;
            assertThat(SourceRewrite.fold(text)).isEqualTo("""
                    package geometries;

                    // moved from geometries.impl.Sphere, see geometries.api.Intersectable
                    class Cube {
                        /* geometries.api.Intersectable is the course's interface */
                        static final String NAME = "geometries.api.Intersectable";
                        geometries.Intersectable shape = null;
                        Object o = geometries . Intersectable.class;
                        String s = "lighting.impl." + geometries.Cube.class.getName();
                    }
                    """);
        }

        @Test
        @DisplayName("a file with none of them is left byte for byte, its line breaks and encoding-free text included")
        void untouched() throws Exception {
            String text = "package renderer;\r\n\r\nclass A { String s = \"שלום geometries.api\"; }";
            assertThat(SourceRewrite.fold(text)).isEqualTo(text);
        }
    }

    @Nested
    @DisplayName("a file javac cannot parse whole")
    class ParseErrors {
        @Test
        @DisplayName("is rewritten where it parses; the broken part stays as written, for the compile to name")
        void broken() throws Exception {
            String text = "package geometries.impl;\nimport geometries.api.Intersectable;\nimport ;\n"
                    + "class A {\n    void f() { int = geometries.api.Intersectable.class; }\n}\n";
            assertThat(SourceRewrite.rewrite(text, "A.java", MATERIAL)).startsWith("package geometries;\nimport geometries.Intersectable;\n"
                    + "import ;\nclass A {\n    void f() { int = ");
        }
    }

    @Nested
    @DisplayName("a relocated course class (lighting.Material as the library's primitives.Material)")
    class Relocate {
        @Test
        @DisplayName("its import and qualified uses name the library's class; strings and comments keep the old name")
        void imported() throws Exception {
            String text = """
                    package renderer;

                    import lighting.Material;

                    class Use {
                        // lighting.Material had kD
                        String note = "lighting.Material";
                        Material m = new lighting.Material();
                    }
                    """;
            assertThat(SourceRewrite.rewrite(text, "Use.java", MATERIAL)).isEqualTo("""
                    package renderer;

                    import primitives.Material;

                    class Use {
                        // lighting.Material had kD
                        String note = "lighting.Material";
                        Material m = new primitives.Material();
                    }
                    """);
        }

        @Test
        @DisplayName("a file of its old package that names it unqualified gets the library's import after its package line")
        void samePackage() throws Exception {
            String text = "package lighting;\n\nclass MaterialTests {\n    Object m = new Material();\n}\n";
            assertThat(SourceRewrite.rewrite(text, "MaterialTests.java", MATERIAL))
                    .isEqualTo("package lighting;\nimport primitives.Material;\n\nclass MaterialTests {\n    Object m = new Material();\n}\n");
        }

        @Test
        @DisplayName("a file that only mentions it in a string or a comment gets no import")
        void onlyMentioned() throws Exception {
            String text = "package lighting;\n\n// Material moved\nclass Notes {\n    String s = \"Material\";\n}\n";
            assertThat(SourceRewrite.rewrite(text, "Notes.java", MATERIAL)).isEqualTo(text);
        }
    }
}
