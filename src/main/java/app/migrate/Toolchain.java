package app.migrate;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemNotFoundException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * What a migration compiles with and writes down: the library (the classes this command runs
 * with, so the check is made against exactly the library that ships with it), JUnit 5's API for
 * the tests, the local Maven repository the IDE and Maven read, the coordinates a pom names, and
 * the newest Java release this JDK compiles for.
 *
 * @param library         the library's classes: a jar or a folder
 * @param junit           JUnit 5's API jars (jupiter api and params, platform commons, opentest4j,
 *                        apiguardian); empty when the project's own {@code lib/} must do
 * @param mavenRepository the local Maven repository ({@code ~/.m2/repository})
 * @param coordinates     {@code group:artifact:version} of the library
 * @param junitVersion    the JUnit BOM version a new pom imports
 * @param jdk             the newest release this JDK compiles for
 * @param maven           the Maven command that fetches a library missing from the repository
 *                        ({@code mvn dependency:get}), or null: nothing is fetched
 */
record Toolchain(Path library, List<Path> junit, Path mavenRepository, String coordinates, String junitVersion, int jdk,
        String maven) {
    /** The JUnit artifacts a course test compiles against, as {@code group path/artifact}. */
    private static final List<String> JUNIT_ARTIFACTS = List.of("org/junit/jupiter/junit-jupiter-api",
            "org/junit/jupiter/junit-jupiter-params", "org/junit/platform/junit-platform-commons",
            "org/opentest4j/opentest4j", "org/apiguardian/apiguardian-api");

    /**
     * The toolchain of this process: the library it runs with, JUnit from the local repository.
     *
     * @throws MigrationException when the library's own build facts ({@code library.properties}) cannot be read
     */
    static Toolchain ofThisProcess() throws MigrationException {
        Path library = location(Catalog.class);
        Properties p = new Properties();
        try (InputStream in = Toolchain.class.getResourceAsStream("library.properties")) {
            if (in != null) p.load(in);
        } catch (IOException | IllegalArgumentException e) {
            throw new MigrationException("cannot read library.properties in " + library + " (the library's coordinates): "
                    + e.getMessage() + " (nothing was changed)", e);
        }
        String coordinates = p.getProperty("groupId", "io.github.raytracer") + ":" + p.getProperty("artifactId", "raytracer")
                + ":" + p.getProperty("version", "1.0.0-SNAPSHOT");
        String junit = p.getProperty("junit", "5.11.3");
        Path repo = defaultMavenRepository();
        String mvn = System.getProperty("os.name", "").startsWith("Windows") ? "mvn.cmd" : "mvn";
        return new Toolchain(library, junitJars(repo, junit), repo, coordinates, junit, Javac.newestRelease(), mvn);
    }

    /** The jar of {@code group:artifact:version} in the repository, fetched there first when missing. */
    Optional<Path> fetchIfMissing(String coordinates) {
        Path jar = jarOf(coordinates);
        return Files.isRegularFile(jar) ? Optional.of(jar) : fetch(coordinates);
    }

    /**
     * JUnit 5's API jars a course test compiles against, fetched into the repository first when
     * some are missing: the library's first build ({@code mvn package -DskipTests}) resolves
     * JUnit's API but not its parameterized tests, which most course projects use.
     *
     * @return the jars found, all of them unless there was no Maven to ask or it could not fetch
     *         them (offline): the caller says what is missing
     */
    List<Path> junitFetchedIfMissing() {
        if (junit.size() == JUNIT_ARTIFACTS.size()) return junit;
        // the parameterized-tests artifact brings the API, platform commons, opentest4j and apiguardian with it
        if (fetch("org.junit.jupiter:junit-jupiter-params:" + junitVersion, true).isEmpty()) return junit;
        return junitJars(mavenRepository, junitVersion);
    }

    /**
     * Fetches {@code group:artifact:version} into the repository with Maven, which a migrated
     * project needs anyway for {@code mvn test} (and which would fetch it then).
     *
     * @return the jar, or empty when there is no Maven to ask or it could not fetch it (offline,
     *         no such artifact): the caller names the library as missing
     */
    Optional<Path> fetch(String coordinates) {
        return fetch(coordinates, false);
    }

    /** {@link #fetch(String)}, with the artifact's own dependencies when {@code transitive}. */
    private Optional<Path> fetch(String coordinates, boolean transitive) {
        Path jar = jarOf(coordinates);
        if (maven == null) return Optional.empty();
        try {
            Process p = new ProcessBuilder(maven, "-q", "-B", "dependency:get", "-Dartifact=" + coordinates, "-Dtransitive=" + transitive,
                    "-Dmaven.repo.local=" + mavenRepository).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .start();
            p.getOutputStream().close();
            if (!p.waitFor(180, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return Optional.empty();
            }
        } catch (IOException e) {
            return Optional.empty(); // no Maven on the PATH: the library is reported missing, with the files that use it
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return Optional.empty();
        }
        return Files.isRegularFile(jar) ? Optional.of(jar) : Optional.empty();
    }

    private Path jarOf(String coordinates) {
        String[] c = coordinates.split(":");
        return repositoryJar(mavenRepository, c[0], c[1], c[2]);
    }

    /** Where Maven keeps {@code group:artifact:version}'s jar in a local repository. */
    static Path repositoryJar(Path repository, String group, String artifact, String version) {
        return repository.resolve(group.replace('.', '/')).resolve(artifact).resolve(version).resolve(artifact + "-" + version + ".jar");
    }

    /**
     * The library's clone, when this process runs from one (its {@code target/classes} or
     * {@code target/raytracer.jar}, beside its pom): where {@code mvn install} puts it into the
     * local repository.
     */
    Optional<Path> libraryClone() {
        Path target = library.toAbsolutePath().getParent();
        if (target == null || !target.getFileName().toString().equals("target")) return Optional.empty();
        return Optional.ofNullable(target.getParent()).filter(c -> Files.isRegularFile(c.resolve("pom.xml")));
    }

    /** Where the library's jar lies in the local repository (it may not be installed yet). */
    Path installedJar() {
        return jarOf(coordinates);
    }

    /** {@code -Dmaven.repo.local}, else {@code localRepository} of {@code ~/.m2/settings.xml}, else {@code ~/.m2/repository}. */
    static Path defaultMavenRepository() {
        String set = System.getProperty("maven.repo.local");
        if (set != null && !set.isBlank()) return Path.of(set);
        Path m2 = Path.of(System.getProperty("user.home"), ".m2");
        Path settings = m2.resolve("settings.xml");
        if (Files.isRegularFile(settings)) {
            try {
                Matcher m = Pattern.compile("<localRepository>\\s*([^<]+?)\\s*</localRepository>")
                        .matcher(Files.readString(settings, StandardCharsets.UTF_8));
                if (m.find() && !m.group(1).contains("${")) return Path.of(m.group(1));
            } catch (IOException e) {
                // an unreadable settings file: Maven would fail on it too; the default stands
            }
        }
        return m2.resolve("repository");
    }

    /** JUnit's API jars in the repository: the BOM's version of each where present, else the newest. */
    static List<Path> junitJars(Path repo, String jupiterVersion) {
        List<Path> jars = new ArrayList<>();
        for (String artifact : JUNIT_ARTIFACTS) {
            Path dir = repo.resolve(artifact);
            if (!Files.isDirectory(dir)) continue;
            String name = artifact.substring(artifact.lastIndexOf('/') + 1);
            try (Stream<Path> versions = Files.list(dir)) {
                versions.filter(v -> Files.isRegularFile(v.resolve(name + "-" + v.getFileName() + ".jar")))
                        .max(Comparator.comparing((Path v) -> v.getFileName().toString().equals(jupiterVersion))
                                .thenComparing((a, b) -> PomFile.compareVersions(a.getFileName().toString(),
                                        b.getFileName().toString())))
                        .ifPresent(v -> jars.add(v.resolve(name + "-" + v.getFileName() + ".jar")));
            } catch (IOException e) {
                // an unreadable folder of the repository: that jar is missing, which is reported
            }
        }
        return jars;
    }

    /**
     * @throws MigrationException when the class has no location to name (loaded from memory, or a
     *                            location that is not a file)
     */
    static Path location(Class<?> c) throws MigrationException {
        CodeSource source = c.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null)
            throw new MigrationException("cannot tell where the library's classes are loaded from (" + c.getName()
                    + " has no code source): run migrate from the raytracer jar or its clone (nothing was changed)");
        try {
            return Path.of(source.getLocation().toURI());
        } catch (URISyntaxException | IllegalArgumentException | FileSystemNotFoundException e) {
            throw new MigrationException("cannot tell where the library's classes are loaded from (" + source.getLocation()
                    + " is not a file: " + e.getMessage() + "); run migrate from the raytracer jar or its clone (nothing was changed)", e);
        }
    }
}
