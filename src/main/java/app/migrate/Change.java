package app.migrate;

import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;

/**
 * One file a migration changes, with the exact text it leaves: the plan holds every one before
 * anything is written, {@link Apply} writes only these texts, and {@code --dry-run} prints them as
 * a diff ({@link UnifiedDiff}). Paths are relative to the project, with {@code /}.
 *
 * @param kind    what happens to the file
 * @param path    the file as it is (for {@link Kind#CREATE}, the file made)
 * @param to      where its new text goes (the same as {@code path} unless it moves)
 * @param before  its text now ({@code null} for {@link Kind#CREATE})
 * @param after   its text after the migration
 * @param charset the encoding {@code after} is in (a source's own; UTF-8 for the build files)
 */
record Change(Kind kind, String path, String to, String before, String after, Charset charset) {
    /** Where a rewritten file's original is kept, under its own path. */
    static final String ORIGINALS = Layout.BACKUP + "/originals/";

    /** What a change does to its file. */
    enum Kind {
        /** Moved whole (a course class into {@code course-backup/}): its bytes are not read or written. */
        MOVE,
        /** Rewritten, perhaps at a new path; the original kept under {@link #ORIGINALS}. */
        REPLACE,
        /** Made where there was no file. */
        CREATE
    }

    static Change move(String from, String to, String text, Charset charset) {
        return new Change(Kind.MOVE, from, to, text, text, charset);
    }

    static Change replace(String path, String to, String before, String after, Charset charset) {
        return new Change(Kind.REPLACE, path, to, before, after, charset);
    }

    static Change create(String path, String text) {
        return new Change(Kind.CREATE, path, path, null, text, StandardCharsets.UTF_8);
    }

    /** Where a {@link Kind#REPLACE} keeps the original. */
    String backup() {
        return ORIGINALS + path;
    }

    /** The bytes written. */
    byte[] bytes() {
        return after.getBytes(charset);
    }
}
