package renderer;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import jdk.jfr.DataAmount;
import jdk.jfr.Description;
import jdk.jfr.Label;
import jdk.jfr.Name;

/**
 * A JDK Flight Recorder event for each PNG an {@link ImageWriter} writes, beside the
 * {@link RenderEvent render's}: on a timeline, the write (PNG encoding and the move into place)
 * shows apart from the render it follows, and the first write of a JVM, which starts AWT and
 * ImageIO, shows as the long one. Made, as the render's event, only once the flight recorder is
 * initialised ({@link ImageEvent}); a failed write commits none.
 */
@Name(ImageWriteEvent.NAME)
@Label("Image Write")
@Description("One PNG written by an ImageWriter: encoding and the atomic move into place")
final class ImageWriteEvent extends ImageEvent {
    /** The event's name in a recording (for {@code jfr print --events}). */
    static final String NAME = "raytracer.ImageWrite";

    @Label("Image")
    @Description("The image writer's name, or for a writer made without one the file's name without .png")
    String image;

    @Label("File")
    @Description("The PNG's absolute path")
    String file;

    @Label("Size")
    @Description("The PNG file's size; -1 when it could not be read back")
    @DataAmount(DataAmount.BYTES)
    long bytes;

    /**
     * Ends the event once the PNG is in place, fills it in and commits it, if a recording asks for it.
     *
     * @param writerName the writer's name; null for a writer made without one (the file's stem is used)
     */
    void commit(String writerName, Path file, int width, int height) {
        if (!ended()) return;
        String fileName = file.getFileName().toString();
        this.image = writerName != null ? writerName
                : fileName.endsWith(".png") ? fileName.substring(0, fileName.length() - ".png".length()) : fileName;
        this.file = file.toString();
        this.width = width;
        this.height = height;
        try {
            this.bytes = Files.size(file);
        } catch (IOException e) {
            this.bytes = -1; // the PNG is written; a size the event cannot read must not fail the write
        }
        commit();
    }
}
