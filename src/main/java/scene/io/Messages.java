package scene.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Wording shared by the scene-file reader and the {@code render} command, so that a file that
 * cannot be read is reported in the same words whether it is a scene or a mesh.
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
     * Why code point {@code cp} may not stand in a name, or null when it may. The rule, in the
     * order asked: control characters (Unicode Cc: C0, DEL and C1, such as U+009B, which a
     * terminal obeys); format characters (Cf: the bidirectional overrides and isolates, the
     * direction marks, zero-width characters); line and paragraph separators (Zl, Zp); spaces
     * other than U+0020 (Zs: U+00A0, U+3000, …: they look like the plain space and are another
     * character); private-use, unassigned and surrogate code points (Co, Cn, Cs: no agreed glyph);
     * the rest of Unicode's Default_Ignorable_Code_Point (U+034F, the Hangul fillers U+115F,
     * U+1160, U+3164 and U+FFA0, the variation selectors U+FE00–U+FE0F, …: drawn as nothing);
     * and the blank braille pattern U+2800, a letter-like character drawn as a space.
     *
     * @param cp a Unicode code point
     * @return the kind of character, for a message ("a control character", …), or null
     */
    public static String hidden(int cp) {
        return switch (Character.getType(cp)) {
            case Character.CONTROL -> "a control character";
            case Character.FORMAT -> "an invisible or direction-changing character";
            case Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR -> "a line or paragraph separator";
            case Character.SPACE_SEPARATOR -> cp == ' ' ? null : "a space other than U+0020 (it looks like one and is another character)";
            case Character.PRIVATE_USE, Character.UNASSIGNED, Character.SURROGATE -> "a private-use, unassigned or surrogate code point";
            default -> defaultIgnorable(cp) ? "an invisible character (Unicode's Default_Ignorable_Code_Point)"
                    : cp == 0x2800 ? "a blank-looking character (the empty braille pattern)" : null;
        };
    }

    /**
     * Unicode's Default_Ignorable_Code_Point (DerivedCoreProperties, Unicode 15) outside the
     * format category, which {@link #hidden} names first: characters drawn as nothing.
     */
    private static boolean defaultIgnorable(int cp) {
        return cp == 0x034F || cp == 0x115F || cp == 0x1160 || cp == 0x17B4 || cp == 0x17B5
                || (cp >= 0x180B && cp <= 0x180F) || (cp >= 0x2060 && cp <= 0x206F) || cp == 0x3164
                || (cp >= 0xFE00 && cp <= 0xFE0F) || cp == 0xFFA0 || (cp >= 0xFFF0 && cp <= 0xFFF8)
                || (cp >= 0x1BCA0 && cp <= 0x1BCA3) || (cp >= 0x1D173 && cp <= 0x1D17A)
                || (cp >= 0xE0000 && cp <= 0xE0FFF);
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
