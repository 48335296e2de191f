package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class LineReaderTest {
    private static List<String> lines(Reader in, int maxLine, long maxChars) throws IOException {
        LineReader reader = new LineReader(in, maxLine, maxChars);
        List<String> lines = new ArrayList<>();
        for (String line = reader.readLine(); line != null; line = reader.readLine()) lines.add(line);
        return lines;
    }

    @ParameterizedTest(name = "{index}")
    @ValueSource(strings = { "a\nbb\n\nc", "a\r\nbb\r\n\r\nc", "a\rbb\r\rc", "a\nbb\r\n\rc\n" })
    @DisplayName("lines end at \\n, \\r\\n or \\r, as BufferedReader's; the last needs no end")
    void lineEnds(String text) throws IOException {
        assertThat(lines(new StringReader(text), 10, 100)).containsExactly("a", "bb", "", "c");
    }

    @Test
    @DisplayName("lines across buffer fills, and a \\r\\n split between two fills, read whole")
    void acrossFills() throws IOException {
        String longLine = "x".repeat(70_000);
        String text = longLine + "\r\n" + "y".repeat((1 << 16) - 1) + "\r\nz";
        assertThat(lines(new StringReader(text), 100_000, 1_000_000)).containsExactly(longLine, "y".repeat((1 << 16) - 1), "z");
        // One char per read: every split a Reader may make.
        Reader trickle = new Reader() {
            private final StringReader in = new StringReader("ab\r\ncd\r\n");

            @Override
            public int read(char[] buffer, int offset, int length) throws IOException {
                return in.read(buffer, offset, Math.min(1, length));
            }

            @Override
            public void close() {
                in.close();
            }
        };
        assertThat(lines(trickle, 10, 100)).containsExactly("ab", "cd");
    }

    @Test
    @DisplayName("a line over the limit: refused without reading on")
    void longLine() throws IOException {
        assertThatThrownBy(() -> lines(new StringReader("ok\n" + "x".repeat(11)), 10, 100))
                .isInstanceOf(LineReader.LimitExceededException.class).hasMessage("a line longer than 10 characters (the limit)");
        assertThat(lines(new StringReader("x".repeat(10)), 10, 100)).containsExactly("x".repeat(10));
    }

    @Test
    @DisplayName("a text over the limit: refused once the limit is passed, whatever the lines")
    void longText() {
        assertThatThrownBy(() -> lines(new StringReader("a\n".repeat(60)), 10, 100))
                .isInstanceOf(LineReader.LimitExceededException.class).hasMessage("more than 100 characters (the limit)");
    }
}
