package scene.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Where {@link XmlSceneReader} gets the bytes of the files it reads: the scene file and every OBJ
 * mesh it references. {@link #DISK} reads the file system; a cluster's executor reads the copies
 * its driver sent, so that it parses exactly what the driver validated, with the same paths in
 * its messages.
 */
@FunctionalInterface
public interface FileSource {
    /** The file system, as the paths say. */
    FileSource DISK = Files::readAllBytes;

    /**
     * @param file the file as the reader resolved it (relative to the working directory unless
     *             absolute)
     * @return the whole content of {@code file}
     * @throws IOException when it cannot be read ({@link java.nio.file.NoSuchFileException} when
     *                     there is no such file)
     */
    byte[] readAllBytes(Path file) throws IOException;
}
