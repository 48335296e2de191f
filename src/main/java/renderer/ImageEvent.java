package renderer;

import jdk.jfr.Category;
import jdk.jfr.Description;
import jdk.jfr.Event;
import jdk.jfr.FlightRecorder;
import jdk.jfr.Label;

/**
 * What the library's flight-recorder events share ({@link RenderEvent}, {@link ImageWriteEvent}):
 * their category, the image's size, and the rule that one is made only once the flight recorder is
 * initialised in this JVM: the first JFR event class a JVM initialises sets up JFR's machinery,
 * hundreds of classes and longer than a small render, and that must not fall on every first
 * render. With the recorder initialised but no recording asking for an event, it is not filled in.
 */
@Category("Ray Tracer")
abstract class ImageEvent extends Event {
    @Label("Width")
    @Description("Pixels across")
    int width;

    @Label("Height")
    @Description("Pixels down")
    int height;

    /** Begins the event: made just before what it times. */
    ImageEvent() {
        begin();
    }

    /** @return whether an event is to be made now: the flight recorder is initialised (a recording was started) */
    static boolean recording() {
        return FlightRecorder.isInitialized();
    }

    /**
     * Ends the event.
     *
     * @return whether a recording asks for it: the caller then fills it in and commits it
     */
    final boolean ended() {
        end();
        return shouldCommit();
    }
}
