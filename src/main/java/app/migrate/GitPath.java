package app.migrate;

import java.nio.charset.StandardCharsets;

/**
 * A path as git writes it in a diff's headers, so that {@code git apply} reads back the same path.
 * git leaves a path as it is unless it holds a double quote, a backslash, a control character or a
 * non-ASCII character; then the whole name, {@code a/} or {@code b/} included, goes in double quotes
 * with C escapes ({@code \"}, {@code \\}, {@code \t}, {@code \n}, …) and every byte of its UTF-8
 * above 127 as three octal digits ({@code é} is {@code \303\251}), as git's default
 * {@code core.quotePath} does. A space is not quoted: instead the {@code ---} and {@code +++} lines
 * end the name with a tab, which is how {@code git apply} knows where a name with a space ends.
 */
final class GitPath {
    private GitPath() {
    }

    /** {@code name} as git writes it: as it is, or quoted (see above). */
    static String quoted(String name) {
        byte[] bytes = name.getBytes(StandardCharsets.UTF_8);
        boolean plain = true;
        for (byte b : bytes) plain &= !needsEscape(b & 0xff);
        if (plain) return name;
        StringBuilder out = new StringBuilder(bytes.length + 8).append('"');
        for (byte signed : bytes) {
            int b = signed & 0xff;
            if (!needsEscape(b)) {
                out.append((char) b);
                continue;
            }
            out.append('\\');
            switch (b) {
                case 0x07 -> out.append('a');
                case '\b' -> out.append('b');
                case '\t' -> out.append('t');
                case '\n' -> out.append('n');
                case 0x0b -> out.append('v');
                case '\f' -> out.append('f');
                case '\r' -> out.append('r');
                case '"', '\\' -> out.append((char) b);
                default -> out.append((char) ('0' + (b >> 6))).append((char) ('0' + ((b >> 3) & 7))).append((char) ('0' + (b & 7)));
            }
        }
        return out.append('"').toString();
    }

    /**
     * A {@code ---} or {@code +++} line: {@code marker}, the name ({@code a/} or {@code b/} and the
     * path, quoted as git quotes it), and a tab after a name with a space in it.
     */
    static String fileLine(String marker, String name) {
        String q = quoted(name);
        return marker + " " + q + (q.indexOf(' ') >= 0 ? "\t" : "") + "\n";
    }

    private static boolean needsEscape(int b) {
        return b < 0x20 || b == '"' || b == '\\' || b >= 0x7f;
    }
}
