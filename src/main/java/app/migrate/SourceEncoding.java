package app.migrate;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.Charset;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.IllegalCharsetNameException;
import java.nio.charset.StandardCharsets;
import java.nio.charset.UnsupportedCharsetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The character encoding of a project's {@code .java} files, and where it was learnt: given on the
 * command line, stated by the project (its pom's {@code project.build.sourceEncoding}, IntelliJ's
 * {@code .idea/encodings.xml}, Eclipse's {@code .settings/org.eclipse.core.resources.prefs}), or
 * read off the files. Course projects written on a Hebrew Windows keep their comments in
 * windows-1255 unless IntelliJ was told otherwise; read as UTF-8 they do not compile, which is not
 * the JDK's fault. The migration reads, compiles and rewrites in this encoding and writes it into
 * the pom, so {@code mvn test} reads the files as the IDE did.
 *
 * @param charset the encoding
 * @param from    where it was learnt, for the summary ({@code "detected"}, {@code ".idea/encodings.xml"})
 */
record SourceEncoding(Charset charset, String from) {
    /** IntelliJ's project-wide entry ({@code url="PROJECT"}), else its first per-folder one. */
    private static final Pattern IDEA_PROJECT = Pattern.compile("<file\\s+url=\"PROJECT\"\\s+charset=\"([^\"]+)\"");
    private static final Pattern IDEA_ANY = Pattern.compile("<file\\s+url=\"[^\"]*\"\\s+charset=\"([^\"]+)\"");
    private static final Pattern POM = Pattern.compile("<project\\.build\\.sourceEncoding>\\s*([^<\\s]+)\\s*<");
    private static final Pattern ECLIPSE = Pattern.compile("(?m)^encoding/<project>=(\\S+)");
    /** Hebrew letters in windows-1255 (0xE0-0xFA): what a high byte of a course project's comment mostly is. */
    private static final Charset HEBREW = Charset.forName("windows-1255");
    private static final Charset WESTERN = Charset.forName("windows-1252");

    /**
     * @param dir   the project's folder
     * @param given the encoding named on the command line, or null
     * @param files the project's {@code .java} files, for detection when nothing states it
     * @throws MigrationException when the given or stated name is not an encoding this Java knows
     */
    static SourceEncoding of(Path dir, String given, List<Path> files) throws MigrationException {
        if (given != null) return new SourceEncoding(named(given, "--encoding"), "--encoding");
        String stated = stated(dir.resolve("pom.xml"), POM);
        if (stated != null) return new SourceEncoding(named(stated, "pom.xml"), "pom.xml");
        Path idea = dir.resolve(".idea/encodings.xml");
        stated = stated(idea, IDEA_PROJECT);
        if (stated == null) stated = stated(idea, IDEA_ANY);
        if (stated != null) return new SourceEncoding(named(stated, ".idea/encodings.xml"), ".idea/encodings.xml");
        Path eclipse = dir.resolve(".settings/org.eclipse.core.resources.prefs");
        stated = stated(eclipse, ECLIPSE);
        if (stated != null) return new SourceEncoding(named(stated, ".settings/org.eclipse.core.resources.prefs"), "Eclipse settings");
        return detect(files);
    }

    /**
     * UTF-8 when every file decodes as UTF-8 (ASCII included); else windows-1255 when the bytes
     * outside ASCII are mostly its Hebrew letters, windows-1252 otherwise (Latin-1's superset).
     */
    static SourceEncoding detect(List<Path> files) throws MigrationException {
        long hebrew = 0, high = 0;
        for (Path f : files) {
            byte[] bytes;
            try {
                bytes = Files.readAllBytes(f);
            } catch (IOException e) {
                throw new MigrationException("cannot read " + f + ": " + e.getMessage(), e);
            }
            if (isUtf8(bytes)) continue;
            for (byte b : bytes) {
                int u = b & 0xFF;
                if (u >= 0x80) high++;
                if (u >= 0xE0 && u <= 0xFA) hebrew++;
            }
        }
        if (high == 0) return new SourceEncoding(StandardCharsets.UTF_8, "detected");
        return new SourceEncoding(hebrew * 2 > high ? HEBREW : WESTERN, "detected: not UTF-8");
    }

    static boolean isUtf8(byte[] bytes) {
        try {
            StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes));
            return true;
        } catch (CharacterCodingException e) {
            return false;
        }
    }

    /** The summary's words: {@code windows-1255 (from .idea/encodings.xml)}. */
    String describe() {
        return charset.name() + " (" + from + ")";
    }

    private static String stated(Path file, Pattern p) throws MigrationException {
        if (!Files.isRegularFile(file)) return null;
        try {
            Matcher m = p.matcher(Files.readString(file, StandardCharsets.ISO_8859_1));
            return m.find() && !m.group(1).contains("${") ? m.group(1) : null;
        } catch (IOException e) {
            throw new MigrationException("cannot read " + file + ": " + e.getMessage(), e);
        }
    }

    private static Charset named(String name, String where) throws MigrationException {
        try {
            return Charset.forName(name);
        } catch (IllegalCharsetNameException | UnsupportedCharsetException e) {
            throw new MigrationException(where + " names the encoding \"" + name + "\", which this Java does not know"
                    + " (UTF-8, windows-1255 and ISO-8859-1 are; nothing was changed)", e);
        }
    }
}
