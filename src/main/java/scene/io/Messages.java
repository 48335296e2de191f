package scene.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;

import renderer.ImageWriters;

/**
 * Wording shared by the scene-file reader and the {@code render} command, so that a file that
 * cannot be read is reported in the same words whether it is a scene or a mesh.
 *
 * @hidden internal: the messages' wording, public for the command line and the Spark driver; a scene reads files through XmlSceneReader
 */
public final class Messages {
    private Messages() {
    }

    /**
     * The one line for a scene file that cannot be read at all (the command line's and the Spark
     * driver's wording).
     *
     * @param scene the scene file as the user named it
     * @param e     why it cannot be read
     * @return {@code SCENE: cannot read the scene file: REASON (expected a readable XML scene file)}
     */
    public static String cannotReadScene(Path scene, IOException e) {
        return scene + ": cannot read the scene file: " + reason(e) + " (expected a readable XML scene file)";
    }

    /**
     * The reason a file could not be read, in a few words for a one-line message: "no such file",
     * "access denied", the file system's own reason, else the exception's message (its class name
     * when the message is missing or blank). The file itself is not named: the caller does that.
     *
     * @param e the failure of reading the file
     * @return the reason, one line, without the file's name
     */
    public static String reason(IOException e) {
        if (e instanceof NoSuchFileException) return "no such file";
        if (e instanceof AccessDeniedException) return "access denied";
        if (e instanceof FileSystemException f && f.getReason() != null) return f.getReason();
        String message = e.getMessage();
        return message == null || message.isBlank() ? e.getClass().getSimpleName() : message;
    }

    /**
     * Why code point {@code cp} may not stand in a name, or null when it may: the rule of image
     * names ({@code ImageWriters.requireFileName}), kept in the renderer's image writer, which
     * names the files.
     *
     * @param cp a Unicode code point
     * @return the kind of character, for a message ("a control character", …), or null
     */
    public static String hidden(int cp) {
        return ImageWriters.hiddenCharacter(cp);
    }

    /**
     * {@code text} with every character that {@link #hidden} names written as a backslash-u escape
     * (a backslash, "u" and four hexadecimal digits; above U+FFFF, "u{E0001}"): a message quoting a file's or a user's
     * text stays one line and displays as the text is, and a terminal receives no control
     * sequence from it.
     *
     * @param text any text, or null
     * @return the text, escaped; null for null
     */
    public static String visible(String text) {
        if (text == null) return null;
        if (text.codePoints().noneMatch(cp -> cp > '~' || cp < ' ')) return text; // printable ASCII: as is
        StringBuilder b = new StringBuilder(text.length() + 16);
        text.codePoints().forEach(cp -> {
            if (hidden(cp) == null) b.appendCodePoint(cp);
            else if (cp <= 0xFFFF) b.append(String.format(Locale.ROOT, "\\u%04X", cp));
            else b.append(String.format(Locale.ROOT, "\\u{%X}", cp));
        });
        return b.toString();
    }
}
