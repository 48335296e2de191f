package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import app.Project;

/**
 * The starter the README prints is the one the build proves: the integration test
 * {@code src/it/starter} (run by maven-invoker-plugin in {@code mvn verify}) is a consumer project
 * made of exactly the README's pom and its first scene test, built against the just-packaged
 * library. These tests hold the two copies equal, so the README cannot drift from what was built.
 */
class ReadmeStarterTest {
    private static final Path README = Project.file("README.md");
    private static final Path STARTER = Project.file("src/it/starter");

    private static List<String> blocks(String language) throws IOException {
        return ReadmeExampleTest.blocks(Files.readString(README), language);
    }

    private static String projectVersion() throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        return factory.newDocumentBuilder().parse(Project.file("pom.xml").toFile()).getDocumentElement()
                .getElementsByTagName("version").item(0).getTextContent().trim();
    }

    @Test
    @DisplayName("the README's consumer pom is the starter's, with the library's version filled in")
    void pom() throws Exception {
        String starter = Files.readString(STARTER.resolve("pom.xml"));
        assertThat(starter).contains("<version>@project.version@</version>");
        assertThat(blocks("xml")).as("the README's whole-pom block")
                .filteredOn(b -> b.contains("<artifactId>my-scenes</artifactId>"))
                .singleElement().isEqualTo(starter.replace("@project.version@", projectVersion()));
    }

    @Test
    @DisplayName("the starter's scene test is the README's first Java block")
    void sceneTest() throws IOException {
        assertThat(blocks("java")).first()
                .isEqualTo(Files.readString(STARTER.resolve("src/test/java/SpheresTest.java")));
    }

    @Test
    @DisplayName("the starter's compiler level is a property a student on Java 21 raises, 17 by default")
    void javaLevelIsAProperty() throws IOException {
        assertThat(Files.readString(STARTER.resolve("pom.xml")))
                .contains("<maven.compiler.release>17</maven.compiler.release>")
                .doesNotContain("<release>", "<source>", "<target>");
    }
}
