package scene.io;

import java.util.Arrays;

/**
 * The text of a scene file with its line structure, to turn the parser's (line, column) reports
 * into offsets and back. Lines end at "\n", "\r\n" or a lone "\r", as XML counts them; columns
 * are 1-based and count characters, so they match what an editor shows for ordinary text.
 */
final class SourceText {
    private final String text;
    /** Offset of the first character of each line; lineStarts[0] == 0. */
    private final int[] lineStarts;

    SourceText(String text) {
        this.text = text;
        int[] starts = new int[16];
        int count = 1;
        for (int i = 0; i < text.length(); ++i) {
            char c = text.charAt(i);
            if (c == '\r' && i + 1 < text.length() && text.charAt(i + 1) == '\n') ++i;
            if (c == '\r' || c == '\n') {
                if (count == starts.length) starts = Arrays.copyOf(starts, count * 2);
                starts[count++] = i + 1;
            }
        }
        this.lineStarts = Arrays.copyOf(starts, count);
    }

    String text() {
        return text;
    }

    /** @return the offset of 1-based (line, column), clamped to the text */
    int offset(int line, int column) {
        if (line < 1) return 0;
        if (line > lineStarts.length) return text.length();
        return Math.max(0, Math.min(text.length(), lineStarts[line - 1] + Math.max(column, 1) - 1));
    }

    /** @return the 1-based line of {@code offset} */
    int line(int offset) {
        int i = Arrays.binarySearch(lineStarts, offset);
        return i >= 0 ? i + 1 : -i - 1;
    }

    /** @return the 1-based column of {@code offset} */
    int column(int offset) {
        return offset - lineStarts[line(offset) - 1] + 1;
    }
}
