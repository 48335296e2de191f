package app.migrate;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;

/**
 * Every change a migration made, in order, so that {@code migrate --undo} takes each back exactly
 * and refuses when a file changed since (its SHA-256 differs): a class moved into
 * {@code course-backup/}, a file rewritten (its original kept in {@code course-backup/originals/}),
 * a file created (the pom). Kept as {@code course-backup/migrate-manifest.tsv}, one change a line,
 * paths relative to the project with {@code /}.
 *
 * <p>Changes are applied one by one; when one fails, those already made are taken back in reverse
 * order, so that a migration either happens whole or leaves the folder as it was.
 */
final class Manifest {
    static final String FILE = Layout.BACKUP + "/migrate-manifest.tsv";
    private static final String HEADER = "# raytracer migrate: what changed (raytracer migrate --undo DIR takes it back)";

    /** One change: a kind, paths relative to the project, and the SHA-256 of what it left. */
    record Entry(String kind, String path, String to, String backup, String sha) {
        static final String MOVE = "move", REPLACE = "replace", CREATE = "create";

        String line() {
            return String.join("\t", kind, path, to, backup, sha);
        }

        static Entry parse(String line) throws MigrationException {
            String[] f = line.split("\t", -1);
            if (f.length != 5 || !List.of(MOVE, REPLACE, CREATE).contains(f[0]))
                throw new MigrationException(FILE + " is damaged (a line reads \"" + line + "\"): undo by hand or with git");
            return new Entry(f[0], f[1], f[2], f[3], f[4]);
        }
    }

    private final Path dir;
    private final List<Entry> entries = new ArrayList<>();

    Manifest(Path dir) {
        this.dir = dir;
    }

    List<Entry> entries() {
        return List.copyOf(entries);
    }

    /** Moves a file, making the folders it needs. */
    void move(String from, String to) throws IOException {
        Path target = dir.resolve(to);
        Files.createDirectories(target.getParent());
        Files.move(dir.resolve(from), target);
        entries.add(new Entry(Entry.MOVE, from, to, "", sha(target)));
    }

    /**
     * Writes new content for a file, keeping its original at {@code backup}; the new content goes
     * to {@code to}, which may differ from {@code path} (a class whose package line changed moves
     * to its package's folder).
     */
    void replace(String path, String to, String backup, String content) throws IOException {
        replace(path, to, backup, content.getBytes(StandardCharsets.UTF_8));
    }

    /** As {@link #replace(String, String, String, String)}, with the new content as bytes (a source in its own encoding). */
    void replace(String path, String to, String backup, byte[] content) throws IOException {
        Path original = dir.resolve(path), target = dir.resolve(to), kept = dir.resolve(backup);
        Files.createDirectories(kept.getParent());
        Files.copy(original, kept, StandardCopyOption.REPLACE_EXISTING);
        write(target, content);
        if (!target.equals(original)) Files.delete(original);
        entries.add(new Entry(Entry.REPLACE, path, to, backup, sha(target)));
    }

    /** Creates a file that was not there. */
    void create(String path, String content) throws IOException {
        Path target = dir.resolve(path);
        if (Files.exists(target)) throw new IOException(path + " exists");
        write(target, content);
        entries.add(new Entry(Entry.CREATE, path, "", "", sha(target)));
    }

    /** Takes back, newest first, every change made so far (after a failure part-way). */
    void rollBack() throws IOException {
        for (int i = entries.size() - 1; i >= 0; i--) reverse(entries.get(i));
        entries.clear();
    }

    /** Writes the manifest itself into the backup folder. */
    void save() throws IOException {
        StringBuilder text = new StringBuilder(HEADER).append('\n');
        for (Entry e : entries) text.append(e.line()).append('\n');
        write(dir.resolve(FILE), text.toString());
    }

    /** Reads the manifest of an earlier migration of {@code dir}. */
    static Manifest load(Path dir) throws MigrationException {
        Manifest m = new Manifest(dir);
        try {
            for (String line : Files.readAllLines(dir.resolve(FILE), StandardCharsets.UTF_8))
                if (!line.isBlank() && !line.startsWith("#")) m.entries.add(Entry.parse(line));
        } catch (NoSuchFileException e) {
            throw new MigrationException(dir + " has no " + FILE + ": nothing of raytracer migrate to undo");
        } catch (IOException e) {
            throw new MigrationException("cannot read " + dir.resolve(FILE) + ": " + e.getMessage(), e);
        }
        return m;
    }

    /**
     * The changes that block an undo, one line each: a file changed since the migration, gone, or
     * put back in the way. Empty when every change can be taken back as it was made.
     */
    List<String> conflicts() throws IOException {
        List<String> found = new ArrayList<>();
        for (Entry e : entries) {
            String now = e.kind().equals(Entry.MOVE) ? e.to() : e.kind().equals(Entry.REPLACE) ? e.to() : e.path();
            Path file = dir.resolve(now);
            if (!Files.isRegularFile(file)) found.add(now + " is gone since the migration");
            else if (!sha(file).equals(e.sha())) found.add(now + " changed since the migration");
            else if (!e.kind().equals(Entry.CREATE) && !e.path().equals(e.to()) && Files.exists(dir.resolve(e.path())))
                found.add(e.path() + " is there again");
            if (e.kind().equals(Entry.REPLACE) && !Files.isRegularFile(dir.resolve(e.backup())))
                found.add(e.backup() + " (the original of " + e.path() + ") is gone");
        }
        return found;
    }

    /** Takes every change back, newest first. Call {@link #conflicts()} first. */
    void undoAll() throws IOException {
        for (int i = entries.size() - 1; i >= 0; i--) reverse(entries.get(i));
    }

    private void reverse(Entry e) throws IOException {
        switch (e.kind()) {
            case Entry.MOVE -> {
                Path back = dir.resolve(e.path());
                Files.createDirectories(back.getParent());
                Files.move(dir.resolve(e.to()), back);
            }
            case Entry.REPLACE -> {
                Path original = dir.resolve(e.path());
                Files.createDirectories(original.getParent());
                Files.copy(dir.resolve(e.backup()), original, StandardCopyOption.REPLACE_EXISTING);
                if (!e.to().equals(e.path())) Files.deleteIfExists(dir.resolve(e.to()));
                Files.deleteIfExists(dir.resolve(e.backup()));
            }
            default -> Files.deleteIfExists(dir.resolve(e.path()));
        }
    }

    /** Writes through a temporary file beside the target, so no half-written file is ever left. */
    static void write(Path target, String content) throws IOException {
        write(target, content.getBytes(StandardCharsets.UTF_8));
    }

    static void write(Path target, byte[] content) throws IOException {
        Files.createDirectories(target.getParent());
        Path temp = target.resolveSibling(target.getFileName() + ".migrate-tmp");
        Files.write(temp, content);
        Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    static String sha(Path file) throws IOException {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(file)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}
