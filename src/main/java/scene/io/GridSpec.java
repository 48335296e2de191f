package scene.io;

import java.util.StringJoiner;

import primitives.Color;

/**
 * The grid drawn over the image.
 *
 * <p>A part of {@link RenderSettings}: a component is null where it states nothing.
 *
 * @param interval a line every this many pixels (0: none)
 * @param color    the lines' colour
 * @serial exclude
 */
public record GridSpec(Integer interval, Color color) implements java.io.Serializable {
    static final GridSpec NONE = new GridSpec(null, null);

    GridSpec then(GridSpec later) {
        return new GridSpec(Stated.or(later.interval, interval), Stated.or(later.color, color));
    }

    void describe(StringJoiner out) {
        Stated.add(out, "gridInterval", interval);
        Stated.add(out, "gridColor", color);
    }
}
