package app.migrate;

import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;

/**
 * The test methods of a JUnit test file that javac rejects, taken out of its text one by one, so
 * that the file's other tests still build and run. Only javac's parser reads the file ({@link
 * Parsed}: no class path, nothing written); methods, calls and annotations are known from its tree
 * ({@link MethodSpans}), never from the text, so a string literal or a comment that looks like code
 * changes nothing.
 *
 * <p>A file the parser does not read whole is left as it is (the whole file left out): after a
 * syntax error javac patches the tree up, and a method bound taken from a patched tree could cut
 * the file mid-statement; the compile names that error to the student anyway.
 */
final class TestMethods {
    /** A test file with some of its methods taken out. */
    record Trimmed(String text, List<String> removed) {
        Trimmed {
            Objects.requireNonNull(text, "text");
            removed = List.copyOf(removed);
        }
    }

    private static final String BOM = "\uFEFF";

    private TestMethods() {
    }

    /**
     * @param text          the test file's source
     * @param name          the file's name, for a message should javac fail
     * @param errorLines    the 1-based lines javac reported errors on
     * @param reasonComment why, said in each left-out method's place (line breaks become spaces)
     * @return the text without each method (of any top-level or nested class) whose span holds an
     *         error line, each replaced by one comment line; {@code null} when any error line lies
     *         outside a method that can be removed (an import, a field, a class header, an
     *         initializer, a constructor, a lifecycle method or an override), when a remaining part
     *         of the file calls a removed method or names it in {@code @MethodSource}, when the file
     *         does not parse whole, or when it would keep no test method
     * @throws MigrationException when this Java has no compiler (a JRE), or javac fails on the text in memory
     */
    static Trimmed without(String text, String name, Collection<Long> errorLines, String reasonComment) throws MigrationException {
        Objects.requireNonNull(text, "text");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(errorLines, "errorLines");
        Objects.requireNonNull(reasonComment, "reasonComment");
        // javac rejects a byte order mark as an illegal character; a space of the same length keeps every offset.
        String source = text.startsWith(BOM) ? " " + text.substring(1) : text;
        Parsed parsed = Parsed.of(source, name);
        if (!parsed.whole()) return null;

        MethodSpans spans = new MethodSpans(parsed, source);
        List<MethodSpan> methods = spans.all();
        // No method, no test to keep; and javac's line map of an empty file has no line 1 to look up.
        if (methods.isEmpty()) return null;
        Set<MethodSpan> hit = new HashSet<>();
        for (Long line : errorLines) {
            Objects.requireNonNull(line, "an error line is null");
            MethodSpan owner = spans.owner(line, methods);
            if (owner == null || !owner.removable()) return null;
            hit.add(owner);
        }
        List<MethodSpan> removed = methods.stream().filter(hit::contains).toList();
        List<MethodSpan> kept = methods.stream().filter(m -> !hit.contains(m)).toList();
        if (kept.stream().noneMatch(MethodSpan::test)) return null;
        if (spans.stillUsed(removed, kept)) return null;

        String reason = oneLine(reasonComment);
        StringBuilder out = new StringBuilder(text.length());
        int from = 0;
        for (MethodSpan m : removed) {
            out.append(text, from, m.start()).append(m.indent()).append("// raytracer migrate: ").append(m.name())
                    .append("() left out: ").append(reason).append(m.lineBreak());
            from = m.end();
        }
        out.append(text, from, text.length());
        return new Trimmed(out.toString(), removed.stream().map(MethodSpan::name).toList());
    }

    /**
     * The reason as one comment line: no line break, and no backslash that javac would read as the
     * start of a Unicode escape (javac reads escapes before comments: a backslash and a {@code u}
     * in a Windows folder name is an illegal escape even in a comment, and the escape of a line
     * feed would end the comment).
     */
    private static String oneLine(String reason) {
        String flat = reason.replace("\r\n", " ").replace('\r', ' ').replace('\n', ' ');
        StringBuilder out = new StringBuilder(flat.length());
        int backslashes = 0;
        for (int i = 0; i < flat.length(); i++) {
            char c = flat.charAt(i);
            // A run of backslashes before 'u' starts an escape when its length is odd: one more makes it even.
            if (c == 'u' && backslashes % 2 == 1) out.append('\\');
            backslashes = c == '\\' ? backslashes + 1 : 0;
            out.append(c);
        }
        return out.toString();
    }
}
