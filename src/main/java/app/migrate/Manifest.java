package app.migrate;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
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
            // Every path a line names is one --undo may move, write or delete: a plain path inside
            // the project, whoever wrote the file (nothing is changed when one is not).
            for (int i = 1; i <= 3; i++) {
                boolean required = i == 1 || (i == 2 && !f[0].equals(CREATE)) || (i == 3 && f[0].equals(REPLACE));
                if (!required && f[i].isEmpty()) continue;
                String problem = Inside.formProblem(f[i]);
                if (problem != null)
                    throw new MigrationException(FILE + " names " + (f[i].isEmpty() ? "no path" : f[i]) + ", " + problem
                            + ": --undo changes files inside the project only, and this manifest is not one raytracer migrate wrote"
                            + " (nothing was changed; undo by hand or with git)");
            }
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
        Path target = Inside.resolve(dir, to);
        Files.createDirectories(target.getParent());
        Files.move(Inside.resolve(dir, from), target);
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
        Path original = Inside.resolve(dir, path), target = Inside.resolve(dir, to), kept = Inside.resolve(dir, backup);
        Files.createDirectories(kept.getParent());
        // the original as it is, mode and all; a link stays a link (kept as the link, not what it points to)
        Files.copy(original, kept, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.COPY_ATTRIBUTES, LinkOption.NOFOLLOW_LINKS);
        write(target, content, original);
        if (!target.equals(original)) Files.delete(original);
        entries.add(new Entry(Entry.REPLACE, path, to, backup, sha(target)));
    }

    /** Creates a file that was not there. */
    void create(String path, String content) throws IOException {
        Path target = Inside.resolve(dir, path);
        if (Files.exists(target, LinkOption.NOFOLLOW_LINKS)) throw new IOException(path + " exists");
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
        write(Inside.resolve(dir, FILE), text.toString());
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
            // the original may be a link, kept as the link (whose target, relative, need not resolve from there)
            if (e.kind().equals(Entry.REPLACE) && !Files.exists(dir.resolve(e.backup()), LinkOption.NOFOLLOW_LINKS))
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
                Path back = Inside.resolve(dir, e.path());
                Files.createDirectories(back.getParent());
                Files.move(Inside.resolve(dir, e.to()), back);
            }
            case Entry.REPLACE -> {
                Path original = Inside.resolve(dir, e.path());
                Files.createDirectories(original.getParent());
                // as it was: its mode, and a link as the link; what is in the way is replaced, not written through
                Files.copy(Inside.resolve(dir, e.backup()), original, StandardCopyOption.REPLACE_EXISTING,
                        StandardCopyOption.COPY_ATTRIBUTES, LinkOption.NOFOLLOW_LINKS);
                if (!e.to().equals(e.path())) Files.deleteIfExists(Inside.resolve(dir, e.to()));
                Files.deleteIfExists(Inside.resolve(dir, e.backup()));
            }
            default -> Files.deleteIfExists(Inside.resolve(dir, e.path()));
        }
    }

    /** Writes through a temporary file beside the target, so no half-written file is ever left. */
    static void write(Path target, String content) throws IOException {
        write(target, content.getBytes(StandardCharsets.UTF_8), target);
    }

    /**
     * Writes {@code content} into a temporary file of its own beside {@code target} (made new,
     * with a name no one could have planted a link under), then renames it over the target: a
     * link at the target is replaced, never written through. The file gets the mode of
     * {@code modeOf} where that is a regular file (the original of a rewritten file), else
     * {@code rw-r--r--}.
     */
    static void write(Path target, byte[] content, Path modeOf) throws IOException {
        Files.createDirectories(target.getParent());
        Path temp = Files.createTempFile(target.getParent(), "." + target.getFileName(), ".migrate-tmp");
        try {
            Files.write(temp, content);
            if (Files.getFileStore(temp).supportsFileAttributeView(PosixFileAttributeView.class))
                Files.setPosixFilePermissions(temp, Files.isRegularFile(modeOf, LinkOption.NOFOLLOW_LINKS)
                        ? Files.getPosixFilePermissions(modeOf, LinkOption.NOFOLLOW_LINKS) : PosixFilePermissions.fromString("rw-r--r--"));
            Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    static String sha(Path file) throws IOException {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(file)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}
