package lighting;

import java.util.Objects;

import primitives.Color;
import primitives.CourseClassGuard;

/** The part every light shares: its intensity. */
abstract class Light {
    /** The emitted intensity, on the colour scale (0..255 per channel is "full"). */
    protected final Color intensity;

    protected Light(Color intensity) {
        CourseClassGuard.check();
        this.intensity = Objects.requireNonNull(intensity, "light intensity");
    }

    /** @return the emitted intensity, before any attenuation by distance or beam shape */
    public Color getIntensity() {
        return intensity;
    }
}
