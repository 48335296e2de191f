package app.migrate;

/** Lines of a source text by offset: any of {@code \n}, {@code \r\n}, {@code \r} ends one, as javac reads them. */
final class TextLines {
    private TextLines() {
    }

    static int lineStart(String source, int position) {
        int i = position;
        while (i > 0 && source.charAt(i - 1) != '\n' && source.charAt(i - 1) != '\r') i--;
        return i;
    }

    /** The offset of the line break that ends the line holding {@code position} (the text's length when none). */
    static int lineEnd(String source, int position) {
        int i = position;
        while (i < source.length() && source.charAt(i) != '\n' && source.charAt(i) != '\r') i++;
        return i;
    }

    /** The line break ending the line at {@code lineStart}; the file's first, or {@code \n}, when it has none. */
    static String lineBreakOf(String source, int lineStart) {
        int end = lineEnd(source, lineStart);
        if (end == source.length()) end = lineEnd(source, 0);
        if (end == source.length()) return "\n";
        return source.startsWith("\r\n", end) ? "\r\n" : source.substring(end, end + 1);
    }

    static String leadingBlanks(String source, int lineStart) {
        int i = lineStart;
        while (i < source.length() && (source.charAt(i) == ' ' || source.charAt(i) == '\t')) i++;
        return source.substring(lineStart, i);
    }

    static int lineBreaks(String s) {
        return (int) s.replace("\r\n", "\n").chars().filter(ch -> ch == '\n' || ch == '\r').count();
    }
}
