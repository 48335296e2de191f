package renderer;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.function.BiConsumer;

/**
 * What a camera's renders and writes tell, and to whom: the render listener (told of the writes too
 * when it is a {@link WriteListener}) and, unless silenced, a line on the output stream for each
 * render and each write ({@link CameraReports#renderLine}, {@link CameraReports#writeLine}). It
 * runs the two around the render loop and the image writer, so that {@link Camera} stays the
 * course's facade. A builder replaces one part at a time; a camera keeps the one it was built with.
 *
 * @param summary  whether a render prints its summary line and a write its line
 * @param stream   where those lines go (the progress lines too: the builder gives the same stream)
 * @param listener told of each finished render, on the thread that rendered; by default nobody
 */
record CameraOutput(boolean summary, PrintStream stream, BiConsumer<? super Camera, ? super RenderStats> listener) {
    /** @return the defaults: the lines printed on System.out as it is now, nobody told */
    static CameraOutput standard() {
        return new CameraOutput(true, System.out, (camera, stats) -> {
        });
    }

    CameraOutput withSummary(boolean on) {
        return new CameraOutput(on, stream, listener);
    }

    CameraOutput withStream(PrintStream stream) {
        return new CameraOutput(summary, stream, listener);
    }

    CameraOutput withListener(BiConsumer<? super Camera, ? super RenderStats> listener) {
        return new CameraOutput(summary, stream, listener);
    }

    /**
     * Renders the camera's image through its render loop, then records the JFR event (while a
     * recording runs), tells the listener and prints the summary line, in that order.
     *
     * @return what the render did
     */
    RenderStats render(Camera camera) {
        String name = CameraReports.imageLabel(camera);
        String scene = camera.rayTracer().sceneName();
        ImageWriter image = camera.imageWriter();
        RenderEvent event = ImageEvent.recording() ? new RenderEvent() : null; // see RenderEvent
        RenderStats stats = camera.setup().loop(image).render(name);
        if (event != null) event.commit(name, scene, image, camera.sampling().antiAliasing(), stats);
        listener.accept(camera, stats);
        if (summary) stream.println(CameraReports.renderLine(camera, name, scene, stats));
        return stats;
    }

    /**
     * Writes the camera's image to {@code file} (a JFR event of the image writer's while a
     * recording runs), then tells a {@link WriteListener} and prints the write's line with the
     * time it took.
     */
    void write(Camera camera, Path file) {
        String name = CameraReports.imageLabel(camera);
        Path target = file.toAbsolutePath();
        ImageWriter image = camera.imageWriter();
        long start = System.nanoTime();
        image.writeToImage(target); // the public method: a subclass of ImageWriter may override it
        double seconds = (System.nanoTime() - start) / 1e9;
        if (listener instanceof WriteListener writes) writes.written(camera, target, seconds);
        if (summary) stream.println(CameraReports.writeLine(name, target, seconds, image));
    }
}
