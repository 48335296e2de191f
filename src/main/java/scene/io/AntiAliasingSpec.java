package scene.io;

import java.util.StringJoiner;

import renderer.AntiAliasing;
import renderer.Camera;
import renderer.Sampling;

/**
 * The sampling as {@code Camera.Builder}'s setters take it.
 *
 * <p>A part of {@link RenderSettings}: a component is null where it states nothing.
 *
 * @param mode      the mode
 * @param columns   RANDOM's grid columns (stated with the rows)
 * @param rows      RANDOM's grid rows
 * @param depth     ADAPTIVE's depth
 * @param threshold ADAPTIVE's threshold
 * @serial exclude
 */
public record AntiAliasingSpec(AntiAliasing mode, Integer columns, Integer rows, Integer depth, Double threshold)
        implements java.io.Serializable {
    static final AntiAliasingSpec NONE = new AntiAliasingSpec(null, null, null, null, null);

    AntiAliasingSpec then(AntiAliasingSpec later) {
        return new AntiAliasingSpec(Stated.or(later.mode, mode), later.columns != null ? later.columns : columns,
                later.columns != null ? later.rows : rows, Stated.or(later.depth, depth), Stated.or(later.threshold, threshold));
    }

    /** Replays the stated values onto {@code camera}, each through its own setter. */
    void applyTo(Camera.Builder camera) {
        if (mode != null) camera.setAntiAliasing(mode);
        if (columns != null) camera.setAntiAliasingGrid(columns, rows);
        if (depth != null || threshold != null) {
            // The builder takes the two together: a specification stating one gets the library's other.
            Sampling.Adaptive library = Sampling.DEFAULT.adaptive();
            camera.setAdaptive(depth != null ? depth : library.depth(), threshold != null ? threshold : library.threshold());
        }
    }

    void describe(StringJoiner out) {
        Stated.add(out, "antiAliasing", mode);
        Stated.add(out, "grid", columns == null ? null : columns + "x" + rows);
        Stated.add(out, "adaptiveDepth", depth);
        Stated.add(out, "adaptiveThreshold", threshold);
    }
}
