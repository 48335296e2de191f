package app.migrate;

import java.util.List;

/**
 * What the project's build must say after the migration, whatever writes it (a new pom, an
 * updated one): paths relative to the project folder with {@code /}, patterns relative to their
 * source folder as Maven's compiler takes them.
 *
 * @param library       the library's coordinates, {@code group:artifact:version}
 * @param junit         the JUnit version of the BOM
 * @param release       the Java release the code needs and this JDK can give
 * @param mainRoots     the source folders (the first is {@code sourceDirectory}, the others added)
 * @param testRoots     the test folders (the same, for tests); may repeat a source folder
 * @param mainExcludes  test files that live in a source folder, kept out of the main compile
 * @param testIncludes  where tests share a folder with sources: the tests (empty: the whole folder)
 * @param testExcludes  test files left out because they do not compile against the library
 * @param libraries     the project's own libraries ({@link Libraries}): coordinates, or its jars with system scope
 * @param junit4        whether tests use JUnit 4: its jar and the Vintage engine join Jupiter
 * @param encoding      the sources' character encoding, as Maven names it
 */
record BuildPlan(String library, String junit, int release, List<String> mainRoots, List<String> testRoots,
        List<String> mainExcludes, List<String> testIncludes, List<String> testExcludes, List<Libraries.Library> libraries,
        boolean junit4, String encoding) {
    static final String COMPILER_VERSION = "3.13.0";
    static final String SUREFIRE_VERSION = "3.5.2";
    static final String BUILD_HELPER_VERSION = "3.6.0";

    String groupId() {
        return library.split(":")[0];
    }

    String artifactId() {
        return library.split(":")[1];
    }

    String version() {
        return library.split(":")[2];
    }
}
