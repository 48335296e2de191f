package app.migrate;

import java.nio.file.Path;

/**
 * A file that stays, with its text after the 2025–26 packages are folded ({@link SourceRewrite}),
 * and where it goes.
 */
record Kept(SourceFile file, String text, Path target) {
    boolean changed() {
        return !text.equals(file.text()) || !target.equals(file.path());
    }
}
