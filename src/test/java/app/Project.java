package app;

import java.nio.file.Path;

/**
 * The project's own files (README, pom, scenes, docs, sources) for tests that read them. Maven
 * runs the tests in {@code target/test-run}, so that what they write (images/, the CLI's
 * outputs) stays out of the clone; Surefire names the project folder in the property
 * {@code basedir}. An IDE that runs a test in the project folder without it gets that folder.
 */
public final class Project {
    private Project() {
    }

    /**
     * @param first the path below the project folder, such as {@code "README.md"} or {@code "scenes"}
     * @param more  further names
     * @return that file or folder of the project
     */
    public static Path file(String first, String... more) {
        return Path.of(System.getProperty("basedir", ""), first).resolve(Path.of("", more));
    }
}
