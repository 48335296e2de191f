package app.migrate;

import static app.migrate.TextLines.lineBreaks;
import static app.migrate.TextLines.lineEnd;
import static app.migrate.TextLines.lineStart;

import java.util.ArrayList;
import java.util.List;

/**
 * The text between the end of the tree before a method and the method: code that has no tree of
 * its own ({@code {}, {@code ;}, {@code class Name}), blanks and comments. It holds no literal
 * (every literal is a tree), so here a {@code //} or a {@code /*} always starts a comment.
 *
 * @param comments [start, end) of each comment, in order
 * @param lastCode the end of the last code character (the gap's start if it has none)
 */
record CommentGap(List<int[]> comments, int lastCode) {
    static CommentGap lex(String source, int from, int to) {
        List<int[]> comments = new ArrayList<>();
        int lastCode = from;
        int i = from;
        while (i < to) {
            char c = source.charAt(i);
            if (source.startsWith("//", i)) {
                int end = Math.min(lineEnd(source, i), to);
                comments.add(new int[] { i, end });
                i = end;
            } else if (source.startsWith("/*", i)) {
                int close = source.indexOf("*/", i + 2);
                if (close < 0 || close + 2 > to)
                    throw new IllegalStateException("a comment at offset " + i + " runs into the method at " + to);
                comments.add(new int[] { i, close + 2 });
                i = close + 2;
            } else {
                if (!Character.isWhitespace(c)) lastCode = i + 1;
                i++;
            }
        }
        return new CommentGap(comments, lastCode);
    }

    /**
     * Where the comments directly above the method's line begin (its Javadoc, {@code //} lines):
     * each on lines of its own, without a blank line between them, except that blank lines
     * between the method and its Javadoc do not detach it (javac gives it to the method all the
     * same). The method's line start when there are none; -1 when a comment that ends on the
     * method's line began after code (the line's start then belongs to that code).
     */
    int commentsAbove(String source, int methodLine) {
        int start = methodLine;
        for (int k = comments.size() - 1; k >= 0; k--) {
            int[] comment = comments.get(k);
            if (comment[0] < lastCode) break;
            if (comment[0] >= start) continue; // on a line already taken, before what follows it there
            int line = lineStart(source, comment[0]);
            if (comment[1] > start) {
                // Begun above and ending on a line already taken: it cannot be cut in two.
                if (line < lastCode) return -1;
                start = line;
                continue;
            }
            boolean javadoc = source.startsWith("/**", comment[0]) && !source.startsWith("/**/", comment[0]);
            int breaks = lineBreaks(source.substring(comment[1], start));
            if (breaks > 1 && !(javadoc && start == methodLine)) break;
            if (line < lastCode) break; // after code on its first line: a comment on that code
            start = line;
        }
        return start;
    }
}
