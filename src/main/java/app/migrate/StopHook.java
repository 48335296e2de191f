package app.migrate;

import java.io.PrintStream;

/**
 * Says in one line what to run when the JVM is stopped (Ctrl-C, a kill that lets it end) while
 * the files change; the manifest, written before each change, makes that possible.
 */
final class StopHook implements AutoCloseable {
    private final Thread hook;

    StopHook(PrintStream progress, String line) {
        hook = new Thread(() -> progress.println("raytracer migrate: " + line), "raytracer migrate: stopped");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    @Override
    public void close() {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // the JVM is ending: the hook runs, and its line is what the user needs
        }
    }
}
