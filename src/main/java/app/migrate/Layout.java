package app.migrate;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Where a course project keeps its sources and tests, read from what it has: an IntelliJ module
 * ({@code *.iml}: its source and test folders), a Maven {@code pom.xml}, an Eclipse
 * {@code .classpath}, or plain folders ({@code src/} and {@code unittests/}, {@code test/} or
 * {@code tests/}). Folders a module names but that do not exist are ignored (course templates name
 * {@code UnitTests} where the tests sit in {@code src/unittests}).
 *
 * @param dir       the project's folder (absolute, normalized)
 * @param kind      what the layout was read from
 * @param mainRoots the source folders, as the project's build declares them
 * @param testRoots the test folders (may be empty, or nested in a source folder)
 * @param iml       the IntelliJ module file, or null
 * @param pom       the Maven pom, or null
 * @param jars      jars the project's module lists (its {@code lib/} JUnit, say): on the class path
 *                  of the compile checks, so that a test compiles as it did in the IDE
 */
record Layout(Path dir, Kind kind, List<Path> mainRoots, List<Path> testRoots, Path iml, Path pom, List<Path> jars) {
    /** What the layout was read from. */
    enum Kind {
        INTELLIJ("IntelliJ module"), MAVEN("Maven project"), ECLIPSE("Eclipse project"), PLAIN("plain folders");

        final String label;

        Kind(String label) {
            this.label = label;
        }
    }

    /** The backup folder's name: never a source folder, never walked. */
    static final String BACKUP = "course-backup";
    /** Folders that hold build output or tool state, never sources of the project. */
    private static final Set<String> SKIPPED = Set.of(BACKUP, "out", "target", "bin", "build", ".git", ".idea",
            ".gradle", "node_modules");

    private static final Pattern IML_FOLDER = Pattern.compile("<sourceFolder\\s+url=\"file://\\$MODULE_DIR\\$/?([^\"]*)\"([^>]*)/?>");
    private static final Pattern IML_JAR = Pattern.compile("jar://(\\$[A-Z_]+\\$)/([^\"!]+\\.jar)!/");
    private static final Pattern IML_LIBRARY = Pattern.compile("<orderEntry\\s+type=\"library\"[^>]*?name=\"([^\"]+)\"");
    private static final Pattern MODULES_XML = Pattern.compile("filepath=\"\\$PROJECT_DIR\\$/([^\"]+\\.iml)\"");
    private static final Pattern ECLIPSE_ENTRY = Pattern.compile("<classpathentry\\s+[^>]*?kind=\"(src|lib)\"[^>]*?path=\"([^\"]+)\"");
    /** A test annotated; with a JUnit import ({@link SourceFile#JUNIT}), a JUnit test file. */
    private static final Pattern TEST_ANNOTATION = Pattern.compile("@(?:Test|ParameterizedTest)\\b");
    private static final Pattern POM_SOURCE = Pattern.compile("<sourceDirectory>\\s*([^<]+?)\\s*</sourceDirectory>");
    private static final Pattern POM_TEST = Pattern.compile("<testSourceDirectory>\\s*([^<]+?)\\s*</testSourceDirectory>");

    /**
     * @throws MigrationException when {@code dir} is not a folder or holds no Java sources
     */
    static Layout read(Path dir, Path mavenRepository) throws MigrationException {
        Path d = dir.toAbsolutePath().normalize();
        if (!Files.isDirectory(d)) throw new MigrationException(d + " is not a folder");
        try {
            Layout layout = readKind(d, mavenRepository);
            if (layout.javaFiles().isEmpty())
                throw new MigrationException(d + " is not a course project: no .java file in "
                        + (layout.mainRoots.isEmpty() ? "src/" : names(d, layout.mainRoots)) + " or its test folders");
            return layout;
        } catch (IOException e) {
            throw new MigrationException("cannot read " + d + ": " + e, e);
        }
    }

    /**
     * This layout with more test folders: those {@link #strayTestRoots} found, whose tests would
     * otherwise be silently missing from {@code mvn test} (a plain project's {@code unittest/}, a
     * module's forgotten folder).
     */
    Layout withTests(List<Path> strays) {
        if (strays.isEmpty()) return this;
        List<Path> tests = new ArrayList<>(testRoots);
        tests.addAll(strays);
        return new Layout(dir, kind, mainRoots, List.copyOf(tests), iml, pom, jars);
    }

    /**
     * Folders outside the build's own that hold JUnit tests, each the folder their package starts
     * in; a folder whose package does not match its path, or that would hold the project itself,
     * is not taken (its tests are named by the check that no test is missed).
     */
    List<Path> strayTestRoots() throws IOException {
        List<Path> roots = Stream.concat(mainRoots.stream(), testRoots.stream()).toList();
        Set<Path> found = new LinkedHashSet<>();
        try (Stream<Path> walk = Files.walk(dir, 12)) {
            for (Path f : walk.filter(f -> f.toString().endsWith(".java") && Files.isRegularFile(f)).sorted().toList()) {
                if (skipped(dir, f) || roots.stream().anyMatch(f::startsWith)) continue;
                String text = Files.readString(f, StandardCharsets.ISO_8859_1);
                if (!SourceFile.JUNIT.matcher(text).find() || !TEST_ANNOTATION.matcher(text).find()) continue;
                Matcher p = SourceFile.PACKAGE.matcher(text);
                Path root = f.getParent();
                if (p.find()) {
                    Path pkg = Path.of(p.group(1).replace('.', '/'));
                    if (!root.endsWith(pkg)) continue;
                    for (int i = 0; i < pkg.getNameCount(); i++) root = root.getParent();
                }
                if (!root.equals(dir) && root.startsWith(dir)) found.add(root);
            }
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
        return List.copyOf(found);
    }

    private static Layout readKind(Path d, Path repo) throws IOException {
        Path pom = d.resolve("pom.xml");
        Path iml = findIml(d);
        List<Path> jars = new ArrayList<>(libJars(d));
        if (Files.isRegularFile(pom)) {
            String text = Files.readString(pom, StandardCharsets.UTF_8);
            Path main = d.resolve(first(POM_SOURCE, text, "src/main/java")).normalize();
            Path test = d.resolve(first(POM_TEST, text, "src/test/java")).normalize();
            return new Layout(d, Kind.MAVEN, existing(List.of(main)), existing(List.of(test)), iml, pom, jars);
        }
        if (iml != null) {
            String text = Files.readString(iml, StandardCharsets.UTF_8);
            List<Path> main = new ArrayList<>(), test = new ArrayList<>();
            Matcher m = IML_FOLDER.matcher(text);
            while (m.find()) {
                if (m.group(2).contains("java-resource")) continue;
                Path folder = moduleFolder(d, iml, m.group(1));
                (m.group(2).contains("isTestSource=\"true\"") ? test : main).add(folder);
            }
            Matcher j = IML_JAR.matcher(text);
            while (j.find()) jars.add(jar(d, iml, repo, j.group(1), j.group(2)));
            // Project libraries (.idea/libraries/NAME.xml): IntelliJ's JUnit, gson, a lib/ jar.
            var projectLibraries = Libraries.projectLibraries(d);
            Matcher l = IML_LIBRARY.matcher(text);
            while (l.find())
                for (String url : projectLibraries.getOrDefault(l.group(1), List.of())) {
                    Matcher u = Pattern.compile("(\\$[A-Z_]+\\$)/(.+)").matcher(url);
                    if (u.matches()) jars.add(jar(d, iml, repo, u.group(1), u.group(2)));
                }
            if (!existing(main).isEmpty())
                return new Layout(d, Kind.INTELLIJ, existing(main), existing(test), iml, null, distinct(jars));
        }
        Path classpath = d.resolve(".classpath");
        if (Files.isRegularFile(classpath)) {
            List<Path> main = new ArrayList<>();
            Matcher m = ECLIPSE_ENTRY.matcher(Files.readString(classpath, StandardCharsets.UTF_8));
            while (m.find())
                (m.group(1).equals("src") ? main : jars).add(d.resolve(m.group(2)).normalize());
            if (!existing(main).isEmpty())
                return new Layout(d, Kind.ECLIPSE, existing(main), List.of(), iml, null, distinct(jars));
        }
        if (Files.isDirectory(d.resolve("src/main/java")))
            return new Layout(d, Kind.PLAIN, List.of(d.resolve("src/main/java")),
                    existing(List.of(d.resolve("src/test/java"))), iml, null, distinct(jars));
        List<Path> tests = existing(List.of(d.resolve("unittests"), d.resolve("unittest"), d.resolve("test"), d.resolve("tests")));
        return new Layout(d, iml != null ? Kind.INTELLIJ : Kind.PLAIN, existing(List.of(d.resolve("src"))), tests, iml,
                null, distinct(jars));
    }

    /**
     * A folder an .iml names ({@code $MODULE_DIR$/src}): under the module file's folder, or under
     * the project's where a module file kept in {@code .idea/} names folders as if it were at the
     * top (IntelliJ then shows them there).
     */
    private static Path moduleFolder(Path d, Path iml, String relative) {
        Path inModule = iml.getParent().resolve(relative).normalize();
        if (Files.isDirectory(inModule) || iml.getParent().equals(d)) return inModule;
        return d.resolve(relative).normalize();
    }

    /** A jar an .iml or project library names by one of IntelliJ's path variables; unknown variables keep their name. */
    private static Path jar(Path d, Path iml, Path repo, String variable, String path) {
        return switch (variable) {
            case "$MODULE_DIR$" -> moduleFolder(d, iml, path);
            case "$PROJECT_DIR$" -> d.resolve(path).normalize();
            case "$MAVEN_REPOSITORY$" -> repo.resolve(path).normalize();
            // $APPLICATION_HOME_DIR$ (IntelliJ's own lib/, its bundled annotations): not on this
            // machine; kept as a relative name, which Libraries tells by its file name.
            default -> Path.of(variable.replace("$", "")).resolve(path).normalize();
        };
    }

    /**
     * The module file IntelliJ loads: the one {@code .idea/modules.xml} names (a stale copy at the
     * top is not read), else one at the top (the one named after the folder when there are several),
     * else in .idea/.
     */
    private static Path findIml(Path d) throws IOException {
        Path modules = d.resolve(".idea/modules.xml");
        if (Files.isRegularFile(modules)) {
            Matcher m = MODULES_XML.matcher(Files.readString(modules, StandardCharsets.UTF_8));
            while (m.find()) {
                Path named = d.resolve(m.group(1)).normalize();
                if (named.startsWith(d) && Files.isRegularFile(named)) return named;
            }
        }
        for (Path where : List.of(d, d.resolve(".idea"))) {
            if (!Files.isDirectory(where)) continue;
            try (Stream<Path> files = Files.list(where)) {
                List<Path> imls = files.filter(f -> f.getFileName().toString().endsWith(".iml")).sorted().toList();
                if (imls.isEmpty()) continue;
                return imls.stream().filter(f -> f.getFileName().toString().equals(d.getFileName() + ".iml"))
                        .findFirst().orElse(imls.get(0));
            }
        }
        return null;
    }

    private static List<Path> libJars(Path d) throws IOException {
        Path lib = d.resolve("lib");
        if (!Files.isDirectory(lib)) return List.of();
        try (Stream<Path> files = Files.list(lib)) {
            return files.filter(f -> f.getFileName().toString().endsWith(".jar")).sorted().toList();
        }
    }

    private static String first(Pattern p, String text, String fallback) {
        Matcher m = p.matcher(text);
        return m.find() ? m.group(1).replace("${project.basedir}/", "").replace("${basedir}/", "") : fallback;
    }

    private static List<Path> existing(List<Path> folders) {
        return folders.stream().filter(Files::isDirectory).distinct().toList();
    }

    /** The jars as named, each once; some may not be on this machine (another user's Maven repository). */
    private static List<Path> distinct(List<Path> jars) {
        return new ArrayList<>(new LinkedHashSet<>(jars));
    }

    /** {@code p} relative to the project {@code d}, with {@code /}; {@code .} for the project itself. */
    static String relative(Path d, Path p) {
        String r = d.relativize(p).toString().replace('\\', '/');
        return r.isEmpty() ? "." : r;
    }

    static String names(Path dir, List<Path> folders) {
        return String.join(", ", folders.stream().map(f -> dir.relativize(f).toString().replace('\\', '/') + "/").toList());
    }

    /** A source or test folder. */
    private record Root(Path path, boolean test) {
    }

    /** The paths of {@link #sources}: every {@code .java} file, before its encoding is known. */
    List<Path> javaFiles() throws IOException {
        List<Path> files = new ArrayList<>();
        for (Path root : Stream.concat(mainRoots.stream(), testRoots.stream()).toList())
            try (Stream<Path> walk = Files.walk(root)) {
                walk.filter(f -> f.toString().endsWith(".java") && Files.isRegularFile(f) && !skipped(root, f))
                        .sorted().forEach(f -> {
                            if (!files.contains(f)) files.add(f);
                        });
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        return files;
    }

    /**
     * Every {@code .java} file of the project, read in {@code encoding}, each with the deepest
     * folder that holds it (a test folder inside a source folder owns its files); build output and
     * {@code course-backup/} left out.
     */
    List<SourceFile> sources(Charset encoding) throws IOException {
        List<Root> roots = new ArrayList<>();
        mainRoots.forEach(r -> roots.add(new Root(r, false)));
        testRoots.forEach(r -> roots.add(new Root(r, true)));
        roots.sort(Comparator.comparingInt((Root r) -> r.path.getNameCount()).reversed());
        List<SourceFile> found = new ArrayList<>();
        Set<Path> seen = new LinkedHashSet<>();
        for (Root r : roots) {
            try (Stream<Path> walk = Files.walk(r.path)) {
                for (Path f : walk.filter(f -> f.toString().endsWith(".java") && Files.isRegularFile(f)).sorted().toList()) {
                    if (skipped(r.path, f) || !seen.add(f)) continue;
                    found.add(SourceFile.read(f, r.path, r.test, encoding));
                }
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
        }
        return found;
    }

    private static boolean skipped(Path root, Path file) {
        for (Path part : root.relativize(file.getParent() == null ? root : file.getParent()))
            if (SKIPPED.contains(part.toString())) return true;
        return false;
    }
}
