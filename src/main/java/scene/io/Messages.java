package scene.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

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
}
