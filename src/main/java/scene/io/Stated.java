package scene.io;

import java.util.StringJoiner;

/** What the parts of {@link RenderSettings} share: a value is stated, or null. */
final class Stated {
    private Stated() {
    }

    /** @return {@code stated} when it is stated, else {@code otherwise} */
    static <T> T or(T stated, T otherwise) {
        return stated != null ? stated : otherwise;
    }

    /** Adds {@code name=value} to a description when the value is stated. */
    static void add(StringJoiner out, String name, Object value) {
        if (value != null) out.add(name + "=" + value);
    }
}
