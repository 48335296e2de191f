package app.migrate;

import java.io.IOException;

/**
 * The points where a migration or an undo changes the disk, one by one (journal a change, move a
 * file, keep an original, write a file, rewrite the manifest), named as they are reached. The
 * tests stop a run at each of them, with a failure or as a kill would, and check that what is
 * left can be taken back whole; a real run passes {@link #NONE}.
 */
@FunctionalInterface
interface Faults {
    /** A run that no one stops. */
    Faults NONE = step -> {
    };

    /**
     * Called before each step.
     *
     * @param step what is about to change, e.g. {@code "move src/primitives/Point.java"}
     * @throws IOException to fail the step, as a full disk would
     */
    void reach(String step) throws IOException;
}
