package scene.io;

import java.io.IOException;

/**
 * A Wavefront OBJ file that {@link ObjReader} cannot turn into a mesh. The message reads
 * {@code source:line: what is wrong}, like a compiler's; the parts are also available apart.
 * An {@link IOException}, so that one {@code catch} covers a missing file and a bad one.
 */
public class ObjFormatException extends IOException {
    /** The file name or resource the text came from, as the caller named it. */
    private final String source;
    /** The 1-based number of the line at fault. */
    private final int line;
    /** What is wrong, naming the bad value, without the source and line. */
    private final String problem;

    /**
     * @param source  the file name or resource the text came from
     * @param line    the 1-based line number of the offending line
     * @param problem what is wrong, naming the bad value
     */
    ObjFormatException(String source, int line, String problem) {
        super(source + ":" + line + ": " + problem);
        this.source = source;
        this.line = line;
        this.problem = problem;
    }

    /** @return the file name or resource the text came from */
    public String getSource() {
        return source;
    }

    /** @return the 1-based number of the line at fault */
    public int getLine() {
        return line;
    }

    /** @return what is wrong, without the source and line */
    public String getProblem() {
        return problem;
    }
}
