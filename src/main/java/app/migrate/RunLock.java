package app.migrate;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * One {@code raytracer migrate} (or {@code --undo}) at a time on a project: an operating-system
 * lock on a file named after the project's real path, in the temporary folder (not in the
 * project, where it would show in {@code git status} and in the clean-tree check). The system
 * releases it when the process ends however it ends, so a killed run leaves no stale lock; the
 * file itself is left for the next run to lock again.
 */
final class RunLock implements AutoCloseable {
    private final FileChannel channel;
    private final FileLock lock;

    private RunLock(FileChannel channel, FileLock lock) {
        this.channel = channel;
        this.lock = lock;
    }

    /**
     * Takes the lock of {@code dir}.
     *
     * @throws MigrationException when another run holds it, or no lock file can be made
     */
    static RunLock take(Path dir) throws MigrationException {
        Path file;
        try {
            file = Path.of(System.getProperty("java.io.tmpdir"), "raytracer-migrate-" + key(dir.toRealPath()) + ".lock");
        } catch (IOException e) {
            throw new MigrationException("cannot read " + dir + ": " + e.getMessage(), e);
        }
        FileChannel channel = null;
        try {
            channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            FileLock lock = channel.tryLock();
            if (lock != null) return new RunLock(channel, lock);
        } catch (OverlappingFileLockException e) {
            // held by this very process (another thread's run)
        } catch (IOException e) {
            close(channel);
            throw new MigrationException("cannot take the lock " + file + " of " + dir + ": " + e.getMessage(), e);
        }
        close(channel);
        throw new MigrationException("another raytracer migrate is running on " + dir + " (it holds " + file
                + "): wait for it to end, then run this again (nothing was changed)");
    }

    private static void close(FileChannel channel) {
        if (channel == null) return;
        try {
            channel.close();
        } catch (IOException e) {
            // closing a lock file that was never locked: nothing to release
        }
    }

    private static String key(Path real) {
        try {
            byte[] sha = MessageDigest.getInstance("SHA-256").digest(real.toString().getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(sha, 0, 12);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }

    @Override
    public void close() {
        try {
            lock.release();
        } catch (IOException e) {
            // the channel's close below releases it too
        }
        close(channel);
    }
}
