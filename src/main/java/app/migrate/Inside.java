package app.migrate;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;

/**
 * The rule that keeps a migration and its undo inside the project: every path they change is a
 * plain relative path ({@code src/primitives/Point.java}: no {@code ..}, not absolute), and the
 * folder it lies in is, once links are followed, inside the project's real folder. A link in
 * the way ({@code .idea -> ../elsewhere}, a crafted manifest line) is refused, not followed; the
 * last name of a path may itself be a link, which a move or a restore handles as the link.
 */
final class Inside {
    private Inside() {
    }

    /**
     * Whether {@code relative} is a plain path inside a folder, by its form alone.
     *
     * @return null when it is; else why not, in words
     */
    static String formProblem(String relative) {
        if (relative.isEmpty()) return "an empty path";
        if (relative.startsWith("/") || relative.indexOf('\\') >= 0 || relative.indexOf(':') >= 0 || relative.indexOf('\0') >= 0)
            return "not a relative path with /";
        // the manifest is one change a line, its fields between tabs
        if (relative.indexOf('\t') >= 0 || relative.indexOf('\n') >= 0 || relative.indexOf('\r') >= 0)
            return "a path with a tab or a line break in a name";
        for (String part : relative.split("/", -1))
            if (part.isEmpty() || part.equals(".") || part.equals("..")) return "a path with an empty, . or .. part";
        return null;
    }

    /**
     * {@code dir}'s file at {@code relative}, after checking that it lies inside {@code dir}: by
     * its form, and by where its nearest existing folder really is.
     *
     * @throws IOException naming the path and the project when it does not
     */
    static Path resolve(Path dir, String relative) throws IOException {
        String problem = formProblem(relative);
        if (problem != null) throw new IOException(relative + " is " + problem + ": raytracer migrate changes files inside " + dir + " only");
        Path file = dir.resolve(relative);
        Path existing = file.getParent();
        while (existing != null && !Files.exists(existing, LinkOption.NOFOLLOW_LINKS)) existing = existing.getParent();
        if (existing == null || !existing.toRealPath().startsWith(dir.toRealPath()))
            throw new IOException(relative + " lies outside " + dir + " (its folder " + dir.relativize(existing == null ? dir : existing)
                    + " is a link to " + (existing == null ? "nowhere" : existing.toRealPath()) + "): raytracer migrate changes files"
                    + " inside the project only");
        return file;
    }

    /** Whether a folder, links followed, lies inside the project's real folder. */
    static boolean contains(Path dir, Path folder) throws IOException {
        return folder.toAbsolutePath().normalize().startsWith(dir) && (!Files.exists(folder) || folder.toRealPath().startsWith(dir.toRealPath()));
    }
}
