package renderer;

import java.nio.file.Path;

/**
 * Told of each PNG a camera writes ({@link Camera#writeToImage()}, {@link Camera#writeToImage(String)}):
 * a render listener given to {@link Camera.Builder#setRenderListener} that also implements this
 * interface hears of the writes too, so that one listener (such as
 * {@code renderer.junit.RenderReports.to(testReporter)}) reports a test's renders and writes.
 */
public interface WriteListener {
    /**
     * Called on the writing thread once the PNG is in place (not after a failed write).
     *
     * @param camera  the camera that wrote
     * @param file    the PNG's absolute path
     * @param seconds the write's wall time in seconds: encoding the PNG and moving it into place
     */
    void written(Camera camera, Path file, double seconds);
}
