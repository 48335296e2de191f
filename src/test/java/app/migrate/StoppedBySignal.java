package app.migrate;

import java.io.ByteArrayOutputStream;
import java.nio.file.Path;

/**
 * A JVM that migrates the project in {@code args[0]} and ends at step {@code args[1]} as Ctrl-C
 * ends it: {@code System.exit(130)}, which runs the shutdown hooks as SIGINT does (and leaves
 * the files as they are at that step). Run by {@link CrashTest}.
 */
final class StoppedBySignal {
    private StoppedBySignal() {
    }

    public static void main(String[] args) throws Exception {
        Path dir = Path.of(args[0]);
        int at = Integer.parseInt(args[1]);
        int[] reached = {0};
        Faults ctrlC = step -> {
            if (reached[0]++ == at) System.exit(130);
        };
        // the migration's progress stream is the command line's standard error, as in raytracer migrate
        Migration m = CourseProjects.migration(dir, new ByteArrayOutputStream(), System.err, ctrlC);
        m.migrate(dir, true, false);
    }
}
