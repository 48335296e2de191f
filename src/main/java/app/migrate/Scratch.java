package app.migrate;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/** A scratch folder for the compile checks, deleted afterwards. */
final class Scratch implements AutoCloseable {
    /** Its name's start, then the process's id: a folder of a process that is gone (killed) is stale. */
    private static final String SCRATCH = "raytracer-migrate-";
    private static final Pattern STALE = Pattern.compile(Pattern.quote(SCRATCH) + "(\\d+)-.*");
    final Path dir;

    Scratch() throws MigrationException {
        try {
            deleteStaleScratch();
            dir = Files.createTempDirectory(SCRATCH + ProcessHandle.current().pid() + "-");
        } catch (IOException e) {
            throw new MigrationException("cannot make a scratch folder: " + e.getMessage(), e);
        }
    }

    /** The scratch folders of earlier runs that were killed (their process is gone): removed. */
    private static void deleteStaleScratch() {
        try (Stream<Path> in = Files.list(Path.of(System.getProperty("java.io.tmpdir")))) {
            for (Path p : in.toList()) {
                Matcher m = STALE.matcher(p.getFileName().toString());
                if (m.matches() && Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)
                        && ProcessHandle.of(Long.parseLong(m.group(1))).isEmpty())
                    Javac.deleteTree(p);
            }
        } catch (IOException | NumberFormatException e) {
            // another user's folder, or a name too long for a process id: left to the system
        }
    }

    @Override
    public void close() {
        try {
            Javac.deleteTree(dir);
        } catch (IOException e) {
            // a scratch folder in the temporary folder: the system cleans it
        }
    }
}
