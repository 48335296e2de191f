package renderer;

import jdk.jfr.Description;
import jdk.jfr.Label;
import jdk.jfr.Name;
import jdk.jfr.Timespan;

/**
 * A JDK Flight Recorder event for each {@link Camera#render()}, so that a recording (or an IDE's
 * profiler, which records with JFR) shows each render on the timeline with what it rendered.
 * Its duration covers the scene's preparation and the render loop, not the PNG write.
 * <p>The camera makes one only once the flight recorder is initialised in this JVM (a recording
 * was started, by {@code -XX:StartFlightRecording}, {@code jcmd}, a profiler or the JFR API), for
 * the reason {@link ImageEvent} gives. The PNG write is an event of its own, {@link ImageWriteEvent}.
 */
@Name(RenderEvent.NAME)
@Label("Render")
@Description("One Camera.render(): the image, its scene, sampling, threads and rays; the duration covers the scene's "
        + "preparation (BVH build) and the render loop, not the PNG write")
final class RenderEvent extends ImageEvent {
    /** The event's name in a recording (for {@code jfr print --events}). */
    static final String NAME = "raytracer.Render";

    @Label("Image")
    @Description("The image's name, or the calling test's for an image named only when written")
    String image;

    @Label("Scene")
    @Description("The name of the scene rendered")
    String scene;

    @Label("Sampling")
    @Description("The anti-aliasing mode: NONE, RANDOM, CORNERS or ADAPTIVE")
    String sampling;

    @Label("Threads")
    @Description("Worker threads; 0: the calling thread")
    int threads;

    @Label("Preparation")
    @Description("Time spent preparing the scene (the BVH build) before the render loop")
    @Timespan(Timespan.NANOSECONDS)
    long preparation;

    @Label("Camera Rays")
    long cameraRays;

    @Label("Shadow Rays")
    long shadowRays;

    @Label("Secondary Rays")
    @Description("Reflected and refracted rays")
    long secondaryRays;

    /** Ends the event, fills in what the render did and commits it, if a recording asks for it. */
    void commit(String image, String scene, ImageWriter writer, AntiAliasing sampling, RenderStats stats) {
        if (!ended()) return;
        this.image = image;
        this.scene = scene;
        this.width = writer.getNx();
        this.height = writer.getNy();
        this.sampling = sampling.name();
        this.threads = stats.threads();
        this.preparation = Math.round(stats.prepareSeconds() * 1e9);
        this.cameraRays = stats.cameraRays();
        this.shadowRays = stats.shadowRays();
        this.secondaryRays = stats.secondaryRays();
        commit();
    }
}
