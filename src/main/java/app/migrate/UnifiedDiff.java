package app.migrate;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * The changes of a plan as a unified diff with git's headers ({@code diff --git}, {@code rename
 * from}, {@code copy from}, {@code new file mode}): what {@code --dry-run} prints, and what
 * {@code git apply} turns the project into exactly what a real run leaves (the manifest aside).
 * A moved file is a rename; a rewritten file's original kept under {@code originals/} is a copy,
 * then the rewrite (a rename with changes where its package folder changed too).
 */
final class UnifiedDiff {
    /** Lines of unchanged text around each change, as {@code diff -u} and git print them. */
    private static final int CONTEXT = 3;
    private static final String NO_NEWLINE = "\\ No newline at end of file\n";

    private UnifiedDiff() {
    }

    /** The diff of every change, in the order they are made, as text (a test's view; what is printed is {@link #bytes}). */
    static String of(List<Change> changes) {
        StringBuilder out = new StringBuilder();
        for (Change c : changes) out.append(header(c)).append(hunks(c));
        return out.toString();
    }

    /**
     * The diff as {@code git apply} takes it: git's headers in UTF-8, each file's lines in that
     * file's own encoding (a windows-1255 source's Hebrew comments as their bytes on disk), so that
     * the context lines match the files byte for byte.
     */
    static byte[] bytes(List<Change> changes) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (Change c : changes) {
            out.writeBytes(header(c).getBytes(StandardCharsets.UTF_8));
            out.writeBytes(hunks(c).getBytes(c.charset()));
        }
        return out.toByteArray();
    }

    /** The lines before a change's hunks: what happens to the file, and its paths (each as git quotes it: {@link GitPath}). */
    private static String header(Change c) {
        StringBuilder out = new StringBuilder();
        switch (c.kind()) {
            case MOVE -> out.append(diffGit(c.path(), c.to())).append("similarity index 100%\n")
                    .append(named("rename from", c.path())).append(named("rename to", c.to()));
            case CREATE -> {
                out.append(diffGit(c.path(), c.path())).append("new file mode 100644\n");
                if (!c.after().isEmpty()) out.append("--- /dev/null\n").append(GitPath.fileLine("+++", "b/" + c.path()));
            }
            case REPLACE -> {
                out.append(diffGit(c.path(), c.backup())).append("similarity index 100%\n")
                        .append(named("copy from", c.path())).append(named("copy to", c.backup()));
                out.append(diffGit(c.path(), c.to()));
                if (!c.to().equals(c.path())) out.append(named("rename from", c.path())).append(named("rename to", c.to()));
                if (!c.before().equals(c.after()))
                    out.append(GitPath.fileLine("---", "a/" + c.path())).append(GitPath.fileLine("+++", "b/" + c.to()));
            }
        }
        return out.toString();
    }

    private static String diffGit(String from, String to) {
        return "diff --git " + GitPath.quoted("a/" + from) + " " + GitPath.quoted("b/" + to) + "\n";
    }

    /** A {@code rename from}, {@code copy to}, … line: git quotes the bare path there, with no {@code a/} or {@code b/}. */
    private static String named(String what, String path) {
        return what + " " + GitPath.quoted(path) + "\n";
    }

    /** A change's hunks: none for a move or an unchanged text. */
    private static String hunks(Change c) {
        return switch (c.kind()) {
            case MOVE -> "";
            case CREATE -> hunks("", c.after());
            case REPLACE -> c.before().equals(c.after()) ? "" : hunks(c.before(), c.after());
        };
    }

    /** One line of an edit script: {@code ' '} kept, {@code '-'} removed, {@code '+'} added, with its line numbers. */
    private record Edit(char op, String line, int oldLine, int newLine) {
    }

    /** The {@code @@} hunks that turn {@code before} into {@code after}. */
    static String hunks(String before, String after) {
        List<Edit> script = script(lines(before), lines(after));
        StringBuilder out = new StringBuilder();
        int i = 0;
        while (i < script.size()) {
            if (script.get(i).op() == ' ') {
                i++;
                continue;
            }
            // A hunk: from CONTEXT kept lines before this change to CONTEXT after the last change
            // that lies within 2 * CONTEXT kept lines of the one before it.
            int start = Math.max(0, i - CONTEXT);
            while (start < i && script.get(start).op() != ' ') start++;
            int end = i;
            int lastChange = i;
            for (int j = i; j < script.size(); j++) {
                if (script.get(j).op() != ' ') lastChange = j;
                else if (j - lastChange > 2 * CONTEXT) break;
            }
            end = Math.min(script.size(), lastChange + CONTEXT + 1);
            int oldStart = 0, newStart = 0, oldCount = 0, newCount = 0;
            for (int j = start; j < end; j++) {
                Edit e = script.get(j);
                if (e.op() != '+') {
                    if (oldCount++ == 0) oldStart = e.oldLine();
                }
                if (e.op() != '-') {
                    if (newCount++ == 0) newStart = e.newLine();
                }
            }
            // An empty side is numbered by the line before it, as diff does (0 at the start).
            if (oldCount == 0) oldStart = script.get(start).oldLine() - 1;
            if (newCount == 0) newStart = script.get(start).newLine() - 1;
            out.append("@@ -").append(range(oldStart, oldCount)).append(" +").append(range(newStart, newCount)).append(" @@\n");
            for (int j = start; j < end; j++) {
                Edit e = script.get(j);
                boolean terminated = e.line().endsWith("\n");
                out.append(e.op()).append(e.line());
                if (!terminated) out.append('\n').append(NO_NEWLINE);
            }
            i = end;
        }
        return out.toString();
    }

    private static String range(int start, int count) {
        return count == 1 ? Integer.toString(start) : start + "," + count;
    }

    /** The lines of {@code text}, each with its line break (the last one without, where the text has none). */
    static List<String> lines(String text) {
        List<String> lines = new ArrayList<>();
        int from = 0;
        while (from < text.length()) {
            int nl = text.indexOf('\n', from);
            int to = nl < 0 ? text.length() : nl + 1;
            lines.add(text.substring(from, to));
            from = to;
        }
        return lines;
    }

    /**
     * The shortest edit script from {@code a} to {@code b}, by the longest common subsequence of
     * what lies between their common start and end (migrated files are small: a few hundred lines).
     */
    private static List<Edit> script(List<String> a, List<String> b) {
        int prefix = 0;
        while (prefix < a.size() && prefix < b.size() && a.get(prefix).equals(b.get(prefix))) prefix++;
        int suffix = 0;
        while (suffix < a.size() - prefix && suffix < b.size() - prefix
                && a.get(a.size() - 1 - suffix).equals(b.get(b.size() - 1 - suffix))) suffix++;
        int n = a.size() - prefix - suffix, m = b.size() - prefix - suffix;
        int[][] common = new int[n + 1][m + 1];
        for (int i = n - 1; i >= 0; i--)
            for (int j = m - 1; j >= 0; j--)
                common[i][j] = a.get(prefix + i).equals(b.get(prefix + j)) ? common[i + 1][j + 1] + 1
                        : Math.max(common[i + 1][j], common[i][j + 1]);
        List<Edit> script = new ArrayList<>();
        int oldLine = 1, newLine = 1;
        for (int k = 0; k < prefix; k++) script.add(new Edit(' ', a.get(k), oldLine++, newLine++));
        int i = 0, j = 0;
        while (i < n || j < m) {
            if (i < n && j < m && a.get(prefix + i).equals(b.get(prefix + j))) {
                script.add(new Edit(' ', a.get(prefix + i++), oldLine++, newLine++));
                j++;
            } else if (i < n && (j == m || common[i + 1][j] >= common[i][j + 1])) {
                script.add(new Edit('-', a.get(prefix + i++), oldLine++, newLine));
            } else {
                script.add(new Edit('+', b.get(prefix + j++), oldLine, newLine++));
            }
        }
        for (int k = a.size() - suffix; k < a.size(); k++) script.add(new Edit(' ', a.get(k), oldLine++, newLine++));
        return script;
    }
}
