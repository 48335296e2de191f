package app.migrate;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The libraries a course project uses besides the JDK, the course API and JUnit 5, as its build
 * named them (the IntelliJ module's jars and project libraries, IntelliJ's bundled annotations,
 * an Eclipse {@code .classpath}, {@code lib/*.jar}) or, where the IDE supplied one without naming
 * it in the project, as its imports show ({@code org.jetbrains.annotations}, JUnit 4's
 * {@code org.junit.Test}). Each becomes a dependency of the written pom: Maven coordinates where
 * the jar is a known artifact (so {@code mvn test} fetches it), the project's own jar with
 * {@code system} scope otherwise.
 */
final class Libraries {
    /** One library: coordinates, or a jar of the project's ({@code systemPath}), and where it was found. */
    record Library(String group, String artifact, String version, String systemPath, boolean testOnly, String from) {
        String coordinates() {
            return group + ":" + artifact + ":" + version;
        }

        /** How the summary names it: {@code org.jetbrains:annotations:24.0.0 (from the .iml)}. */
        String describe() {
            return (systemPath != null ? systemPath : coordinates()) + (testOnly ? ", tests" : "") + " (" + from + ")";
        }
    }

    /** A jar's file name as Maven names it: {@code gson-2.10.1.jar}. */
    private static final Pattern JAR_NAME = Pattern.compile("(.+?)-(\\d[\\w.-]*)\\.jar");
    /** {@code group/path/artifact/version/artifact-version.jar} under a Maven repository. */
    private static final Pattern REPOSITORY_PATH = Pattern.compile("(.+)/([^/]+)/([^/]+)/\\2-\\3(?:-[^/]*)?\\.jar");

    /** A jar known by its file name's artifact: its group, a package it holds, whether only tests use it. */
    private record KnownJar(String group, String pkg, boolean testOnly) {
    }

    private static final Map<String, KnownJar> KNOWN_JARS = Map.of(
            "annotations", new KnownJar("org.jetbrains", "org/jetbrains/annotations/", false),
            "gson", new KnownJar("com.google.code.gson", "com/google/gson/", false),
            "json-simple", new KnownJar("com.googlecode.json-simple", "org/json/simple/", false),
            "json", new KnownJar("org.json", "org/json/", false),
            "junit", new KnownJar("junit", "org/junit/", true),
            "hamcrest-core", new KnownJar("org.hamcrest", "org/hamcrest/", true));

    /** A package a student imports, the library that has it, and its version when nothing names one. */
    private record Known(Pattern imported, String group, String artifact, String version, boolean testOnly) {
    }

    private static final List<Known> BY_IMPORT = List.of(
            new Known(Pattern.compile("(?m)^\\s*import\\s+(static\\s+)?org\\.jetbrains\\.annotations\\."), "org.jetbrains",
                    "annotations", "24.1.0", false),
            new Known(Pattern.compile("(?m)^\\s*import\\s+(static\\s+)?com\\.google\\.gson\\."), "com.google.code.gson", "gson",
                    "2.10.1", false),
            new Known(Pattern.compile("(?m)^\\s*import\\s+(static\\s+)?org\\.json\\.simple\\."), "com.googlecode.json-simple",
                    "json-simple", "1.1.1", false),
            new Known(JUnit4.IMPORT, "junit", "junit", JUnit4.VERSION, true));

    /** JUnit 4, which a project's tests may use beside (or instead of) JUnit 5. */
    static final class JUnit4 {
        /** {@code org.junit.Test}, {@code org.junit.Assert.*}: JUnit 4's package, not Jupiter's or the platform's. */
        static final Pattern IMPORT = Pattern.compile("(?m)^\\s*import\\s+(static\\s+)?org\\.junit\\.(?!jupiter\\.|platform\\.)[A-Z\\w]");
        static final String VERSION = "4.13.2";

        private JUnit4() {
        }

        static boolean usedBy(List<SourceFile> files) {
            return files.stream().anyMatch(f -> IMPORT.matcher(f.text()).find());
        }
    }

    private Libraries() {
    }

    /**
     * @param d     the project's folder
     * @param jars  the jars the project's build names ({@link Layout#jars()}), JUnit 5's among them
     * @param files the project's sources and tests, for the imports nothing names
     * @return each library once, JUnit 5's jars left out (the pom's JUnit replaces them)
     */
    static List<Library> of(Path d, Path mavenRepository, List<Path> jars, List<SourceFile> files) {
        Map<String, Library> found = new LinkedHashMap<>();
        for (Path jar : jars) {
            Library l = library(d, mavenRepository, jar);
            if (l != null) found.putIfAbsent(l.group + ":" + l.artifact, l);
        }
        for (Known k : BY_IMPORT) {
            String key = k.group + ":" + k.artifact;
            if (found.containsKey(key) || files.stream().noneMatch(f -> k.imported.matcher(f.text()).find())) continue;
            found.put(key, new Library(k.group, k.artifact, k.version, null, k.testOnly,
                    "your code imports it; your IDE supplied it"));
        }
        return List.copyOf(found.values());
    }

    /** The library a jar is: null for JUnit 5's own jars and for a jar outside the project Maven cannot name. */
    private static Library library(Path d, Path mavenRepository, Path jar) {
        String name = jar.getFileName().toString();
        if (isJUnit5(name)) return null;
        String from = jar.startsWith(d) ? rel(d, jar) : "your IDE's module";
        if (jar.startsWith(mavenRepository)) {
            Matcher m = REPOSITORY_PATH.matcher(mavenRepository.relativize(jar).toString().replace('\\', '/'));
            if (m.matches()) {
                boolean test = KNOWN_JARS.containsKey(m.group(2)) && KNOWN_JARS.get(m.group(2)).testOnly();
                return new Library(m.group(1).replace('/', '.'), m.group(2), m.group(3), null, test, "your IDE's module");
            }
        }
        Matcher m = JAR_NAME.matcher(name);
        if (m.matches() && KNOWN_JARS.containsKey(m.group(1)) && holds(jar, KNOWN_JARS.get(m.group(1)).pkg())) {
            KnownJar k = KNOWN_JARS.get(m.group(1));
            return new Library(k.group(), m.group(1), m.group(2), null, k.testOnly(), from);
        }
        if (name.equals("annotations.jar") && !jar.startsWith(d)) // IntelliJ's bundled copy, in its lib/
            return new Library("org.jetbrains", "annotations", "24.1.0", null, false, "IntelliJ's bundled annotations");
        if (!jar.startsWith(d)) return null;
        String artifact = name.replaceAll("\\.jar$", "");
        return new Library("local.lib", artifact, "0", rel(d, jar), false, from);
    }

    /**
     * A jar named like a known artifact holds that artifact's package (a student's own "json.jar"
     * may not); one the project names but does not have (its lib/ not committed) is taken at its word.
     */
    private static boolean holds(Path jar, String pkg) {
        if (!Files.exists(jar)) return true;
        try (var zip = new java.util.zip.ZipFile(jar.toFile())) {
            return zip.stream().anyMatch(e -> e.getName().startsWith(pkg));
        } catch (IOException e) {
            return false; // not a readable jar: kept as the project's own file, as the IDE had it
        }
    }

    /** JUnit 5's jars (and what they bring): the written pom's JUnit takes their place. */
    static boolean isJUnit5(String jarName) {
        return jarName.startsWith("junit-jupiter") || jarName.startsWith("junit-platform") || jarName.startsWith("junit-vintage")
                || jarName.startsWith("opentest4j") || jarName.startsWith("apiguardian");
    }

    /** The jar of a library for the compile checks: the project's own, or the local repository's (empty when not there). */
    static Optional<Path> jar(Library l, Path d, Path mavenRepository) {
        if (l.systemPath != null) return Optional.of(d.resolve(l.systemPath)).filter(Files::isRegularFile);
        return Optional.of(Toolchain.repositoryJar(mavenRepository, l.group, l.artifact, l.version)).filter(Files::isRegularFile);
    }

    /**
     * The jar of each library that has one on this machine, fetched into the local repository with
     * Maven where it is missing there (each fetch announced on {@code progress}: it takes seconds).
     */
    static Map<Library, Path> resolved(List<Library> libraries, Path d, Toolchain tools, PrintStream progress) {
        Map<Library, Path> resolved = new LinkedHashMap<>();
        for (Library l : libraries) {
            Path jar = jar(l, d, tools.mavenRepository()).orElse(null);
            if (jar == null) {
                progress.println("raytracer migrate: fetching " + l.coordinates() + " (" + l.from() + ") with mvn...");
                jar = tools.fetch(l.coordinates()).orElse(null);
            }
            if (jar != null) resolved.put(l, jar);
        }
        return resolved;
    }

    /** IntelliJ's project libraries ({@code .idea/libraries/*.xml}) by name: their jars' URLs. */
    static Map<String, List<String>> projectLibraries(Path d) throws IOException {
        Map<String, List<String>> libraries = new LinkedHashMap<>();
        Path folder = d.resolve(".idea/libraries");
        if (!Files.isDirectory(folder)) return libraries;
        Pattern name = Pattern.compile("<library\\s+name=\"([^\"]+)\"");
        Pattern mavenId = Pattern.compile("maven-id=\"([^\":]+):([^\":]+):([^\"]+)\"");
        Pattern classes = Pattern.compile("(?s)<CLASSES>(.*?)</CLASSES>");
        Pattern root = Pattern.compile("<root\\s+url=\"jar://([^\"!]+)!/\"");
        try (Stream<Path> files = Files.list(folder)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".xml")).sorted().toList()) {
                String text = Files.readString(f, StandardCharsets.UTF_8);
                Matcher n = name.matcher(text);
                if (!n.find()) continue;
                List<String> urls = new ArrayList<>();
                Matcher c = classes.matcher(text);
                if (c.find()) {
                    Matcher r = root.matcher(c.group(1));
                    while (r.find()) urls.add(r.group(1));
                }
                Matcher id = mavenId.matcher(text);
                if (urls.isEmpty() && id.find())
                    urls.add("$MAVEN_REPOSITORY$/" + id.group(1).replace('.', '/') + "/" + id.group(2) + "/" + id.group(3) + "/"
                            + id.group(2) + "-" + id.group(3) + ".jar");
                libraries.put(n.group(1), urls);
            }
        }
        return libraries;
    }

    private static String rel(Path d, Path p) {
        return d.relativize(p).toString().replace('\\', '/');
    }
}
