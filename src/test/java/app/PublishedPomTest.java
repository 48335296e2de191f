package app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

/**
 * The pom a library user receives: nothing of the command line's (picocli) or of other optional
 * integrations (Spark) reaches their dependency tree, and the metadata Maven Central requires is
 * there. Checked on the project's pom.xml (the tests run from the project root).
 */
class PublishedPomTest {
    private static Element project;

    @BeforeAll
    static void parse() throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        Document pom = factory.newDocumentBuilder().parse(Project.file("pom.xml").toFile());
        project = pom.getDocumentElement();
    }

    /** The direct children of {@code parent} named {@code name}. */
    private static List<Element> children(Element parent, String name) {
        List<Element> found = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling())
            if (n instanceof Element e && e.getTagName().equals(name)) found.add(e);
        return found;
    }

    /** The dependencies of a pom's project or profile element. */
    private static List<Element> dependencies(Element owner) {
        return children(children(owner, "dependencies").get(0), "dependency");
    }

    private static String text(Element parent, String name) {
        List<Element> found = children(parent, name);
        return found.isEmpty() ? "" : found.get(0).getTextContent().trim();
    }

    @Test
    @DisplayName("every main dependency is test-scoped, provided or optional: a user inherits none")
    void noTransitiveDependencies() {
        List<Element> dependencies = dependencies(project);
        assertThat(dependencies).isNotEmpty();
        assertThat(dependencies).allSatisfy(d -> assertThat(
                List.of("test", "provided").contains(text(d, "scope")) || "true".equals(text(d, "optional")))
                .as("%s:%s reaches library users", text(d, "groupId"), text(d, "artifactId"))
                .isTrue());
    }

    @Test
    @DisplayName("picocli is among the dependencies, as an optional one (the runnable jar shades it in)")
    void picocliIsOptional() {
        List<Element> dependencies = dependencies(project);
        assertThat(dependencies).filteredOn(d -> text(d, "artifactId").equals("picocli"))
                .singleElement().satisfies(d -> assertThat(text(d, "optional")).isEqualTo("true"));
    }

    private static Element profile(String id) {
        return children(children(project, "profiles").get(0), "profile").stream()
                .filter(p -> text(p, "id").equals(id)).findFirst().orElseThrow();
    }

    @Test
    @DisplayName("Spark is a dependency of the profile spark only, which nothing but -Pspark activates")
    void sparkOnlyInItsProfile() {
        List<Element> dependencies = dependencies(project);
        assertThat(dependencies).noneSatisfy(d -> assertThat(text(d, "groupId")).isEqualTo("org.apache.spark"));
        Element spark = profile("spark");
        assertThat(children(spark, "activation")).as("no activation: -DskipTests, -Dmaven.test.skip=true and -o never download Spark").isEmpty();
        assertThat(dependencies(spark))
                .singleElement().satisfies(d -> {
                    assertThat(text(d, "artifactId")).startsWith("spark-core_");
                    assertThat(text(d, "scope")).isEqualTo("provided");
                });
    }

    @Test
    @DisplayName("the test libraries are in the profile tests, which -DskipTests turns off: the first command resolves none")
    void testLibrariesOnlyWhereTestsRun() {
        List<Element> dependencies = dependencies(project);
        assertThat(dependencies).noneSatisfy(d -> assertThat(text(d, "scope")).isEqualTo("test"));
        Element tests = profile("tests");
        Element activation = children(children(tests, "activation").get(0), "property").get(0);
        assertThat(text(activation, "name")).isEqualTo("skipTests");
        assertThat(text(activation, "value")).as("-DskipTests=false keeps the test libraries").isEqualTo("!true");
        assertThat(dependencies(tests))
                .extracting(d -> text(d, "artifactId")).contains("junit-jupiter", "assertj-core", "jazzer-junit");
        assertThat(text(children(project, "properties").get(0), "maven.test.skip"))
                .as("no test compiled when the tests are skipped").isEqualTo("${skipTests}");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = { "name", "description", "url", "licenses", "developers", "scm" })
    @DisplayName("the metadata Maven Central requires is present")
    void centralMetadata(String element) {
        assertThat(text(project, element)).as("<%s>", element).isNotBlank();
    }

    @Test
    @DisplayName("the licence in the pom is the one in LICENSE")
    void licence() throws Exception {
        Element licence = children(children(project, "licenses").get(0), "license").get(0);
        assertThat(text(licence, "name")).isEqualTo("Apache-2.0");
        assertThat(Files.readString(Project.file("LICENSE"))).contains("Apache License", "Version 2.0, January 2004");
    }
}
