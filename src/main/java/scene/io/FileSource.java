package scene.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * Where {@link XmlSceneReader} gets the bytes of the files it reads: the scene file and every OBJ
 * mesh it references. {@link #DISK} reads the file system; a cluster's executor reads the copies
 * its driver sent, so that it parses exactly what the driver validated, with the same paths in
 * its messages. Every source holds the files to the reader's size limit.
 */
@FunctionalInterface
public interface FileSource {
    /**
     * The file system, as the paths say. A device or a pipe ({@code /dev/zero} never ends), a
     * folder, and a file beyond the limit are refused before their content is read; the read is
     * bounded as well, should the file grow meanwhile.
     */
    FileSource DISK = FileSource::readRegularFile;

    /**
     * @param file     the file as the reader resolved it (relative to the working directory
     *                 unless absolute)
     * @param maxBytes the most bytes the reader accepts for this file (a {@link Limits} value)
     * @return the whole content of {@code file}
     * @throws RefusedFileException when the file is not a regular file or has more than
     *                              {@code maxBytes} bytes
     * @throws IOException          when it cannot be read ({@link NoSuchFileException} when there
     *                              is no such file)
     */
    byte[] readAllBytes(Path file, long maxBytes) throws IOException;

    /** A file the reader will not take: its kind or its size is outside the limits. */
    final class RefusedFileException extends IOException {
        private static final long serialVersionUID = 1L;

        /** Why, without the file's name. */
        private final String reason;

        /**
         * @param file   the refused file
         * @param reason why, without the file's name
         */
        public RefusedFileException(Path file, String reason) {
            super(file + ": " + reason);
            this.reason = reason;
        }

        /** @return why the file was refused, without its name */
        public String reason() {
            return reason;
        }
    }

    private static byte[] readRegularFile(Path file, long maxBytes) throws IOException {
        if (!Files.isRegularFile(file)) {
            if (!Files.exists(file)) throw new NoSuchFileException(file.toString());
            throw new RefusedFileException(file, "not a regular file (a device, a pipe or a folder)");
        }
        long size = Files.size(file);
        if (size > maxBytes)
            throw new RefusedFileException(file, "the file has " + size + " bytes, more than the limit of " + maxBytes + " bytes");
        try (InputStream in = Files.newInputStream(file)) {
            byte[] bytes = in.readNBytes((int) Math.min(maxBytes + 1, Integer.MAX_VALUE - 8)); // one more: it may grow
            if (bytes.length > maxBytes)
                throw new RefusedFileException(file, "the file grew beyond the limit of " + maxBytes + " bytes while read");
            return bytes;
        }
    }
}
