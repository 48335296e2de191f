package app.spark;

/**
 * A Spark render that failed on the cluster: a task failed more often than Spark retries it, or
 * the job was cancelled. No image of the failed job's unfinished frames was written. The message
 * is one line (Spark's own messages carry an executor's stack trace; the cause keeps it).
 */
public final class SparkRenderException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * @param message one line saying what failed
     * @param cause   Spark's exception, with the executor's stack trace
     */
    public SparkRenderException(String message, Throwable cause) {
        super(message, cause);
    }
}
