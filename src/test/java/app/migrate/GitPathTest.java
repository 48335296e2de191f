package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@link GitPath}: paths in a diff's headers, written as git 2.39's {@code git diff} writes them. */
class GitPathTest {
    @Nested
    @DisplayName("quoted")
    class Quoted {
        @ParameterizedTest(name = "{0}")
        @CsvSource(delimiter = '|', quoteCharacter = '\'', value = {
                "a/src/primitives/Vector.java | a/src/primitives/Vector.java",
                "a/my dir/x.java              | a/my dir/x.java",
                "a/q\"d/y.java                | \"a/q\\\"d/y.java\"",
                "a/back\\slash.java           | \"a/back\\\\slash.java\"",
                "a/tab\té.java                | \"a/tab\\t\\303\\251.java\"",
                "a/\u05d5\u05e7.java          | \"a/\\327\\225\\327\\247.java\"",
                "a/bell\u0007\u007f.java      | \"a/bell\\a\\177.java\"" })
        @DisplayName("as it is unless it holds a quote, a backslash, a control or a non-ASCII character; a space stays")
        void likeGit(String name, String expected) {
            // CsvSource reads no escapes: the Java string's own escapes above are what is compared.
            assertThat(GitPath.quoted(name)).isEqualTo(expected);
        }
    }

    @Nested
    @DisplayName("fileLine")
    class FileLine {
        @Test
        @DisplayName("a name with a space ends with a tab, as git ends it (git apply reads the name up to the tab)")
        void space() {
            assertThat(GitPath.fileLine("+++", "b/new f.java")).isEqualTo("+++ b/new f.java\t\n");
        }

        @Test
        @DisplayName("a name without one ends the line; a quoted name is quoted whole")
        void noSpace() {
            assertThat(GitPath.fileLine("---", "a/src/Cube.java")).isEqualTo("--- a/src/Cube.java\n");
            assertThat(GitPath.fileLine("---", "a/q\"d/y.java")).isEqualTo("--- \"a/q\\\"d/y.java\"\n");
        }
    }
}
