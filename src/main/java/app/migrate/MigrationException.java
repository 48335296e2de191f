package app.migrate;

/**
 * A migration refused before anything changed (bad input: not a course project, a folder that
 * cannot be written, an earlier run's backup in the way), or one taken back after a failure. Its
 * message is the one line the command prints.
 */
public final class MigrationException extends Exception {
    private static final long serialVersionUID = 1L;
    /** Whether files had started to change (and were taken back), rather than a refusal up front. */
    private final boolean partWay;

    MigrationException(String message) {
        this(message, null, false);
    }

    MigrationException(String message, Throwable cause) {
        this(message, cause, false);
    }

    MigrationException(String message, Throwable cause, boolean partWay) {
        super(message, cause);
        this.partWay = partWay;
    }

    /** @return true when it failed while changing files (what changed was taken back), false when refused up front */
    public boolean partWay() {
        return partWay;
    }
}
