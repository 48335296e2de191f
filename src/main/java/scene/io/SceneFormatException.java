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

    private final String file;
    private final int line;
    private final int column;
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

    public SceneFormatException(String file, int line, int column, String reason, Throwable cause) {
        super(format(file, line, column, reason), cause);
        this.file = Objects.requireNonNull(file, "file");
        this.line = line;
        this.column = column;
        this.reason = Objects.requireNonNull(reason, "reason");
    }

    private static String format(String file, int line, int column, String reason) {
        String where = line > 0 ? file + ":" + line + ":" + column : file;
        // One line, whatever a wrapped library message contained.
        return where + ": " + reason.replaceAll("\\s*\\R\\s*", " ");
    }

    public String getFile() {
        return file;
    }

    public int getLine() {
        return line;
    }

    public int getColumn() {
        return column;
    }

    /** @return the message without the position prefix */
    public String getReason() {
        return reason;
    }
}
