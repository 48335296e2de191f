package scene.io;

import java.util.Objects;

/**
 * A scene file that cannot be read as a scene: malformed XML, an unknown element or attribute,
 * a missing or malformed value, an unreadable mesh, or a geometry the library rejects. The
 * message is one line in the compiler style {@code FILE:LINE:COLUMN: what was wrong (expected …)},
 * so editors and terminals can jump to the place.
 */
public class SceneFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    /** The file as the user named it. */
    private final String file;
    /** 1-based line, 0 when the problem concerns the whole file. */
    private final int line;
    /** 1-based column (in characters), 0 when unknown. */
    private final int column;
    /** What was wrong and what was expected, one line, without the position. */
    private final String reason;

    /**
     * @param file   the file as the user named it
     * @param line   1-based line, 0 when the problem concerns the whole file
     * @param column 1-based column (in characters), 0 when unknown
     * @param reason what was wrong and what was expected, one line
     */
    public SceneFormatException(String file, int line, int column, String reason) {
        this(file, line, column, reason, null);
    }

    /**
     * @param file   the file as the user named it
     * @param line   1-based line, 0 when the problem concerns the whole file
     * @param column 1-based column (in characters), 0 when unknown
     * @param reason what was wrong and what was expected; line breaks are folded into one line
     * @param cause  the library's exception behind it (a rejected geometry, an unreadable mesh), or null
     */
    public SceneFormatException(String file, int line, int column, String reason, Throwable cause) {
        super(format(file, line, column, reason), cause);
        this.file = Objects.requireNonNull(file, "file");
        this.line = line;
        this.column = column;
        this.reason = Objects.requireNonNull(reason, "reason");
    }

    private static String format(String file, int line, int column, String reason) {
        String where = Messages.visible(line > 0 ? file + ":" + line + ":" + column : file);
        // One line, whatever a wrapped library message contained, and no character a terminal
        // would obey (a C1 control from a hostile OBJ line) or hide (a direction override).
        return where + ": " + Messages.visible(reason.replaceAll("\\s*\\R\\s*", " "));
    }

    /** @return the file as the user named it */
    public String getFile() {
        return file;
    }

    /** @return the 1-based line, 0 when the problem concerns the whole file */
    public int getLine() {
        return line;
    }

    /** @return the 1-based column in characters, 0 when unknown */
    public int getColumn() {
        return column;
    }

    /** @return the message without the position prefix */
    public String getReason() {
        return reason;
    }
}
