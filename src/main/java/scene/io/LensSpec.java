package scene.io;

import java.util.StringJoiner;

import renderer.Camera;

/**
 * The thin lens and its samples per pixel.
 *
 * <p>A part of {@link RenderSettings}: a component is null where it states nothing.
 *
 * @param focalDistance the sharp plane's distance, stated with the aperture; 0: the pinhole
 *                      camera, whatever the aperture
 * @param aperture      the lens radius
 * @param samples       lens samples per pixel
 * @serial exclude
 */
public record LensSpec(Double focalDistance, Double aperture, Integer samples) implements java.io.Serializable {
    static final LensSpec NONE = new LensSpec(null, null, null);

    LensSpec then(LensSpec later) {
        return new LensSpec(later.focalDistance != null ? later.focalDistance : focalDistance,
                later.focalDistance != null ? later.aperture : aperture, Stated.or(later.samples, samples));
    }

    /** Replays the stated values onto {@code camera}, each through its own setter. */
    void applyTo(Camera.Builder camera) {
        // A stated pinhole undoes a lens set on the builder before.
        if (focalDistance != null) {
            if (focalDistance == 0) camera.setPinhole();
            else camera.setDepthOfField(focalDistance, aperture);
        }
        if (samples != null) camera.setDepthOfFieldSamples(samples);
    }

    void describe(StringJoiner out) {
        Stated.add(out, "depthOfField", focalDistance == null ? null : "focal " + focalDistance + " aperture " + aperture);
        Stated.add(out, "lensSamples", samples);
    }
}
