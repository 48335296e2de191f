package app.migrate;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.stream.Stream;

/**
 * Every change a migration makes, written down before it is made, so that a run stopped anywhere
 * (a failure, Ctrl-C, a kill) can be taken back whole by {@code migrate --undo}, and an undo
 * stopped anywhere finished by running it again: a folder made, a class moved into
 * {@code course-backup/}, a file rewritten (its original kept in {@code course-backup/originals/}),
 * a file created (the pom). Kept as {@code course-backup/migrate-manifest.tsv}: a header, the
 * state ({@link State}), then one change a line, paths relative to the project with {@code /}
 * and the SHA-256 of what the change leaves ({@code link:TARGET} for a link).
 *
 * <p>Each change is appended and forced to disk before it is made, and each is made so that it
 * is either done or not (a rename; a copy or a write into a new file renamed into place). Only
 * the newest change can therefore be half-way; reading the files tells how far it got
 * ({@link #status}). An undo takes the changes back newest first and rewrites the manifest after
 * each one, so that what it lists is always what is left to take back.
 */
final class Manifest {
    static final String FILE = Layout.BACKUP + "/migrate-manifest.tsv";
    private static final String HEADER = "# raytracer migrate: what changed (raytracer migrate --undo DIR takes it back)";
    private static final String TEMPORARY = ".migrate-tmp";

    /** How far the changes got; the manifest's second line. */
    enum State {
        /** A migration under way, or stopped part-way: its lines are what it did, the last one perhaps half. */
        APPLYING("# state: applying (a migration that did not end; raytracer migrate --undo DIR takes back what it did)"),
        /** A migration that ended. */
        DONE("# state: done"),
        /** An undo under way, or stopped part-way: its lines are what is left to take back. */
        UNDOING("# state: undoing (an undo that did not end; raytracer migrate --undo DIR finishes it)");

        final String line;

        State(String line) {
            this.line = line;
        }
    }

    /** One change: a kind, paths relative to the project, and the fingerprint of what it left. */
    record Entry(String kind, String path, String to, String backup, String sha) {
        static final String MKDIR = "mkdir", MOVE = "move", REPLACE = "replace", CREATE = "create";

        String line() {
            return String.join("\t", kind, path, to, backup, sha);
        }

        static Entry parse(String line) throws MigrationException {
            String[] f = line.split("\t", -1);
            if (f.length != 5 || !List.of(MKDIR, MOVE, REPLACE, CREATE).contains(f[0]))
                throw new MigrationException(FILE + " is damaged (a line reads \"" + line + "\"): undo by hand or with git");
            // Every path a line names is one --undo may move, write or delete: a plain path inside
            // the project, whoever wrote the file (nothing is changed when one is not).
            for (int i = 1; i <= 3; i++) {
                boolean required = i == 1 || (i == 2 && (f[0].equals(MOVE) || f[0].equals(REPLACE))) || (i == 3 && f[0].equals(REPLACE));
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

    /** How far one change got, read from the files. */
    private enum Status {
        /** Made whole: to be taken back. */
        DONE,
        /** Not made (only written down): nothing to take back. */
        NOT_DONE,
        /** A rewrite of which only the original's copy was made: the copy goes. */
        ONLY_KEPT
    }

    private final Path dir;
    private final Faults faults;
    private final List<Entry> entries = new ArrayList<>();
    private State state;

    private Manifest(Path dir, Faults faults, State state) {
        this.dir = dir;
        this.faults = faults;
        this.state = state;
    }

    List<Entry> entries() {
        return List.copyOf(entries);
    }

    State state() {
        return state;
    }

    /**
     * Starts the manifest of a migration of {@code dir}: {@code course-backup/} made (or taken
     * empty, as a run stopped at once left it) and the manifest written, in state applying,
     * before any change.
     */
    static Manifest begin(Path dir, Faults faults) throws IOException {
        Manifest m = new Manifest(dir, faults, State.APPLYING);
        faults.reach("begin " + FILE);
        Files.createDirectories(Inside.resolve(dir, FILE).getParent());
        m.rewrite();
        return m;
    }

    /** Makes the folders {@code folder} needs, each written down first, so that an undo removes them again. */
    private void makeFolders(Path folder) throws IOException {
        List<Path> missing = new ArrayList<>();
        for (Path f = folder; f != null && !f.equals(dir) && !Files.exists(f, LinkOption.NOFOLLOW_LINKS); f = f.getParent())
            missing.add(0, f);
        for (Path f : missing) {
            journal(new Entry(Entry.MKDIR, relative(f), "", "", ""));
            faults.reach("mkdir " + relative(f));
            Files.createDirectory(f);
        }
    }

    /** Moves a file (a rename: done or not), making the folders it needs. */
    void move(String from, String to) throws IOException {
        Path source = Inside.resolve(dir, from), target = Inside.resolve(dir, to);
        makeFolders(target.getParent());
        journal(new Entry(Entry.MOVE, from, to, "", fingerprint(source)));
        faults.reach("move " + from);
        Files.move(source, target);
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
        makeFolders(kept.getParent());
        makeFolders(target.getParent());
        journal(new Entry(Entry.REPLACE, path, to, backup, sha(content)));
        faults.reach("keep " + path);
        copy(original, kept, faults);
        faults.reach("write " + to);
        write(target, content, original, faults);
        if (!target.equals(original)) {
            faults.reach("delete " + path);
            Files.delete(original);
        }
    }

    /** Creates a file that was not there. */
    void create(String path, String content) throws IOException {
        Path target = Inside.resolve(dir, path);
        if (Files.exists(target, LinkOption.NOFOLLOW_LINKS)) throw new IOException(path + " exists");
        byte[] bytes = content.getBytes(StandardCharsets.UTF_8);
        makeFolders(target.getParent());
        journal(new Entry(Entry.CREATE, path, "", "", sha(bytes)));
        faults.reach("write " + path);
        write(target, bytes, target, faults);
    }

    /** Marks the migration ended: from now on every change it lists must be as it left it. */
    void finish() throws IOException {
        state = State.DONE;
        rewrite();
    }

    /**
     * Reads the manifest of an earlier migration of {@code dir}. A line cut short at the end of a
     * manifest that was being written (a kill while a change was written down, before it was
     * made) is dropped.
     */
    static Manifest load(Path dir, Faults faults) throws MigrationException {
        String text;
        try {
            text = Files.readString(Inside.resolve(dir, FILE), StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new MigrationException(dir + " has no " + FILE + ": nothing of raytracer migrate to undo");
        } catch (IOException e) {
            throw new MigrationException("cannot read " + dir.resolve(FILE) + ": " + e.getMessage(), e);
        }
        List<String> lines = new ArrayList<>(text.lines().toList());
        State state = State.DONE; // a manifest of before the state line: written whole, after the last change
        for (State s : State.values())
            if (lines.size() > 1 && lines.get(1).equals(s.line)) state = s;
        if (state != State.DONE && !text.endsWith("\n") && !lines.isEmpty()) lines.remove(lines.size() - 1);
        Manifest m = new Manifest(dir, faults, state);
        for (String line : lines)
            if (!line.isBlank() && !line.startsWith("#")) m.entries.add(Entry.parse(line));
        return m;
    }

    /** The state of {@code dir}'s manifest, or null when it has none. */
    static State stateOf(Path dir) throws MigrationException {
        return Files.isRegularFile(dir.resolve(FILE)) ? load(dir, Faults.NONE).state : null;
    }

    /**
     * The changes that block an undo, one line each: a file changed since the migration, gone, or
     * put back in the way, or a change not made that should have been. Only the newest change may
     * be half-way (a run stopped there); every other one must be as it was left. Empty when every
     * change can be taken back.
     */
    List<String> conflicts() throws IOException {
        List<String> found = new ArrayList<>();
        for (int i = 0; i < entries.size(); i++) {
            Entry e = entries.get(i);
            Object status = status(e);
            if (status instanceof String conflict) found.add(conflict);
            else if (status != Status.DONE && i < entries.size() - 1)
                found.add(e.path() + " is not as the migration left it (" + e.kind() + " not made)");
        }
        return found;
    }

    /**
     * Takes every change back, newest first, rewriting the manifest after each: stopped anywhere,
     * it lists what is left, and running it again finishes. Call {@link #conflicts()} first.
     */
    void undoAll() throws IOException {
        state = State.UNDOING;
        rewrite();
        while (!entries.isEmpty()) {
            Entry e = entries.get(entries.size() - 1);
            Object status = status(e);
            if (status instanceof String conflict) throw new IOException(conflict);
            reverse(e, (Status) status);
            entries.remove(entries.size() - 1);
            rewrite();
        }
    }

    /** How far {@code e} got: a {@link Status}, or why it cannot be taken back (a String). */
    private Object status(Entry e) throws IOException {
        switch (e.kind()) {
            case Entry.MKDIR -> {
                return Files.isDirectory(Inside.resolve(dir, e.path()), LinkOption.NOFOLLOW_LINKS) ? Status.DONE : Status.NOT_DONE;
            }
            case Entry.CREATE -> {
                Path file = Inside.resolve(dir, e.path());
                if (!Files.exists(file, LinkOption.NOFOLLOW_LINKS)) return Status.NOT_DONE;
                return fingerprint(file).equals(e.sha()) ? Status.DONE : e.path() + " changed since the migration";
            }
            case Entry.MOVE -> {
                Path from = Inside.resolve(dir, e.path()), to = Inside.resolve(dir, e.to());
                boolean there = Files.exists(to, LinkOption.NOFOLLOW_LINKS), back = Files.exists(from, LinkOption.NOFOLLOW_LINKS);
                if (there && back) return e.path() + " is there again";
                if (back) return Status.NOT_DONE;
                if (!there) return e.to() + " is gone since the migration";
                return fingerprint(to).equals(e.sha()) ? Status.DONE : e.to() + " changed since the migration";
            }
            default -> {
                Path original = Inside.resolve(dir, e.path()), target = Inside.resolve(dir, e.to()), kept = Inside.resolve(dir, e.backup());
                boolean targetNew = Files.exists(target, LinkOption.NOFOLLOW_LINKS) && fingerprint(target).equals(e.sha());
                if (!Files.exists(kept, LinkOption.NOFOLLOW_LINKS)) // the original is copied before anything is written
                    return targetNew ? e.backup() + " (the original of " + e.path() + ") is gone" : Status.NOT_DONE;
                String keptPrint = fingerprint(kept);
                boolean originalThere = Files.exists(original, LinkOption.NOFOLLOW_LINKS);
                boolean originalAsKept = originalThere && fingerprint(original).equals(keptPrint);
                if (target.equals(original)) {
                    if (targetNew) return Status.DONE;
                    if (originalAsKept) return Status.ONLY_KEPT;
                    return e.path() + (originalThere ? " changed since the migration" : " is gone since the migration");
                }
                if (Files.exists(target, LinkOption.NOFOLLOW_LINKS)) {
                    if (!targetNew) return e.to() + " changed since the migration";
                    return !originalThere || originalAsKept ? Status.DONE : e.path() + " is there again";
                }
                if (originalAsKept) return Status.ONLY_KEPT;
                return e.to() + " is gone since the migration";
            }
        }
    }

    private void reverse(Entry e, Status status) throws IOException {
        if (status == Status.NOT_DONE) {
            deleteTemporaries(e);
            return;
        }
        switch (e.kind()) {
            case Entry.MKDIR -> {
                Path folder = Inside.resolve(dir, e.path());
                try (Stream<Path> in = Files.list(folder)) {
                    if (in.findAny().isPresent()) return; // a file of the user's since: the folder stays with it
                }
                faults.reach("rmdir " + e.path());
                Files.delete(folder);
            }
            case Entry.CREATE -> {
                faults.reach("delete " + e.path());
                Files.delete(Inside.resolve(dir, e.path()));
            }
            case Entry.MOVE -> {
                Path back = Inside.resolve(dir, e.path());
                Files.createDirectories(back.getParent()); // a package folder the migration emptied went with its classes
                faults.reach("move back " + e.to());
                Files.move(Inside.resolve(dir, e.to()), back);
            }
            default -> {
                Path original = Inside.resolve(dir, e.path()), kept = Inside.resolve(dir, e.backup());
                if (status == Status.DONE) {
                    Files.createDirectories(original.getParent());
                    faults.reach("restore " + e.path());
                    copy(kept, original, faults); // as it was: its mode, and a link as the link
                    if (!e.to().equals(e.path())) {
                        faults.reach("delete " + e.to());
                        Files.deleteIfExists(Inside.resolve(dir, e.to()));
                    }
                }
                faults.reach("delete " + e.backup());
                Files.delete(kept);
            }
        }
        deleteTemporaries(e);
    }

    /** The temporary files a write stopped part-way left beside the entry's files. */
    private void deleteTemporaries(Entry e) throws IOException {
        for (String p : List.of(e.path(), e.to(), e.backup())) {
            if (p.isEmpty()) continue;
            Path file = Inside.resolve(dir, p);
            Path folder = file.getParent();
            if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) continue;
            String prefix = "." + file.getFileName();
            try (Stream<Path> in = Files.list(folder)) {
                for (Path t : in.filter(t -> t.getFileName().toString().startsWith(prefix)
                        && t.getFileName().toString().endsWith(TEMPORARY)).toList())
                    Files.deleteIfExists(t);
            }
        }
    }

    /** Writes a change down, at the end of the manifest, forced to disk, before it is made. */
    private void journal(Entry e) throws IOException {
        faults.reach("journal " + e.kind() + " " + e.path());
        try (FileChannel out = FileChannel.open(Inside.resolve(dir, FILE), StandardOpenOption.WRITE, StandardOpenOption.APPEND,
                LinkOption.NOFOLLOW_LINKS)) {
            ByteBuffer line = ByteBuffer.wrap((e.line() + "\n").getBytes(StandardCharsets.UTF_8));
            while (line.hasRemaining()) out.write(line);
            out.force(false);
        }
        entries.add(e);
    }

    /** Writes the manifest whole, as it stands (atomically: the old one or the new one, never half). */
    private void rewrite() throws IOException {
        faults.reach("manifest " + state.name().toLowerCase(java.util.Locale.ROOT));
        StringBuilder text = new StringBuilder(HEADER).append('\n').append(state.line).append('\n');
        for (Entry e : entries) text.append(e.line()).append('\n');
        write(Inside.resolve(dir, FILE), text.toString().getBytes(StandardCharsets.UTF_8), Inside.resolve(dir, FILE), faults);
    }

    private String relative(Path p) {
        return dir.relativize(p).toString().replace('\\', '/');
    }

    /**
     * Copies {@code from} to {@code to} as it is (mode, and a link as the link) through a new
     * temporary file renamed into place: {@code to} is the old file or the whole copy, never half.
     */
    private static void copy(Path from, Path to, Faults faults) throws IOException {
        Path temp = Files.createTempFile(to.getParent(), "." + to.getFileName(), TEMPORARY);
        try {
            Files.copy(from, temp, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.COPY_ATTRIBUTES, LinkOption.NOFOLLOW_LINKS);
            faults.reach("rename into " + to.getFileName());
            Files.move(temp, to, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** Writes through a temporary file beside the target, so no half-written file is ever left. */
    static void write(Path target, String content) throws IOException {
        write(target, content.getBytes(StandardCharsets.UTF_8), target, Faults.NONE);
    }

    /**
     * Writes {@code content} into a temporary file of its own beside {@code target} (made new,
     * with a name no one could have planted a link under), then renames it over the target: a
     * link at the target is replaced, never written through. The file gets the mode of
     * {@code modeOf} where that is a regular file (the original of a rewritten file), else
     * {@code rw-r--r--}.
     */
    static void write(Path target, byte[] content, Path modeOf, Faults faults) throws IOException {
        Files.createDirectories(target.getParent());
        Path temp = Files.createTempFile(target.getParent(), "." + target.getFileName(), TEMPORARY);
        try {
            Files.write(temp, content);
            if (Files.getFileStore(temp).supportsFileAttributeView(PosixFileAttributeView.class))
                Files.setPosixFilePermissions(temp, Files.isRegularFile(modeOf, LinkOption.NOFOLLOW_LINKS)
                        ? Files.getPosixFilePermissions(modeOf, LinkOption.NOFOLLOW_LINKS) : PosixFilePermissions.fromString("rw-r--r--"));
            try (FileChannel c = FileChannel.open(temp, StandardOpenOption.WRITE)) {
                c.force(true); // on disk before the rename makes it the file
            }
            faults.reach("rename into " + target.getFileName());
            Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /**
     * Deletes the temporary files a run stopped part-way left in {@code course-backup/} (of the
     * manifest itself, the report, a kept original), so that the folder empties when the undo
     * has taken everything back. The migration's own folder: nothing else in it is touched.
     */
    static void deleteTemporariesInBackup(Path dir) throws IOException {
        Path backup = Inside.resolve(dir, FILE).getParent();
        if (!Files.isDirectory(backup, LinkOption.NOFOLLOW_LINKS)) return;
        try (Stream<Path> walk = Files.walk(backup)) {
            for (Path t : walk.filter(t -> t.getFileName().toString().startsWith(".") && t.getFileName().toString().endsWith(TEMPORARY)
                    && Files.isRegularFile(t, LinkOption.NOFOLLOW_LINKS)).toList())
                Files.deleteIfExists(t);
        }
    }

    /** What a file holds: the SHA-256 of its bytes, or {@code link:TARGET} for a link (which may point nowhere from where it is). */
    static String fingerprint(Path file) throws IOException {
        if (Files.isSymbolicLink(file)) return "link:" + Files.readSymbolicLink(file);
        return sha(Files.readAllBytes(file));
    }

    static String sha(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}
