package scene.io;

import java.util.StringJoiner;

import primitives.Color;

/**
 * The grid drawn over the image.
 *
 * @param interval a line every this many pixels (0: none)
 * @param color    the lines' colour
 * @hidden a part of the specification
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
