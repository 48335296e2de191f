package scene.io;

import java.io.IOException;
import java.io.Reader;

/**
 * Lines of a text stream, read through a fixed buffer with a limit on the length of a line and on
 * the whole text, so that a line without end (such as the content of {@code /dev/zero}) or an
 * endless stream is refused after a bounded amount of memory and work instead of exhausting both.
 * Lines end at {@code \n}, {@code \r\n} or {@code \r}, as for {@link java.io.BufferedReader}.
 */
final class LineReader {
    /** A limit of this reader was exceeded; the message says which, in the reader's words. */
    static final class LimitExceededException extends IOException {
        private static final long serialVersionUID = 1L;

        LimitExceededException(String message) {
            super(message);
        }
    }

    private final Reader in;
    private final int maxLineLength;
    private final long maxChars;
    private final char[] buffer = new char[1 << 16];
    private int position;
    private int limit;
    private long consumed;
    /** The part of a line that began in an earlier buffer fill. */
    private final StringBuilder pending = new StringBuilder();
    /** A '\r' ended the last line: a '\n' right after it belongs to that line end. */
    private boolean afterCarriageReturn;

    /**
     * @param in            the text; not closed here
     * @param maxLineLength the longest line, in characters, without its terminator
     * @param maxChars      the most characters of the whole text, terminators included
     */
    LineReader(Reader in, int maxLineLength, long maxChars) {
        this.in = in;
        this.maxLineLength = maxLineLength;
        this.maxChars = maxChars;
    }

    /**
     * @return the next line without its terminator, or null at the end of the text
     * @throws LimitExceededException when the line is longer than the limit, or the text longer
     */
    String readLine() throws IOException {
        pending.setLength(0);
        boolean any = false;
        while (true) {
            if (position == limit && !fill()) return any ? pending.toString() : null; // the last line has no end
            if (afterCarriageReturn) {
                afterCarriageReturn = false;
                if (buffer[position] == '\n') {
                    ++position;
                    continue;
                }
            }
            any = true;
            int start = position;
            int end = start;
            while (end < limit && buffer[end] != '\n' && buffer[end] != '\r') ++end;
            if (pending.length() + (end - start) > maxLineLength)
                throw new LimitExceededException("a line longer than " + maxLineLength + " characters (the limit)");
            if (end < limit) {
                afterCarriageReturn = buffer[end] == '\r';
                position = end + 1;
                if (pending.length() == 0) return new String(buffer, start, end - start);
                pending.append(buffer, start, end - start);
                return pending.toString();
            }
            pending.append(buffer, start, end - start);
            position = end;
        }
    }

    private boolean fill() throws IOException {
        int n;
        do {
            n = in.read(buffer, 0, buffer.length);
        } while (n == 0);
        if (n < 0) return false;
        consumed += n;
        if (consumed > maxChars)
            throw new LimitExceededException("more than " + maxChars + " characters (the limit)");
        position = 0;
        limit = n;
        return true;
    }
}
