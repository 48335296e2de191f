package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import javax.xml.XMLConstants;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import javax.xml.validation.Validator;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.xml.sax.SAXException;

import app.Project;

/** docs/scene.xsd agrees with the reader on the scene files and on the format's vocabulary. */
class SceneSchemaTest {
    private static Schema schema;

    @TempDir
    Path dir;

    @BeforeAll
    static void loadSchema() throws SAXException {
        SchemaFactory factory = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
        schema = factory.newSchema(Project.file("docs/scene.xsd").toFile());
    }

    private static void validate(String xml) throws SAXException, IOException {
        Validator validator = schema.newValidator();
        validator.validate(new StreamSource(new StringReader(xml)));
    }

    static Stream<Path> sceneFiles() throws IOException {
        try (Stream<Path> files = Files.list(Project.file("scenes"))) {
            List<Path> xml = files.filter(f -> f.toString().endsWith(".xml")).sorted().toList();
            assertThat(xml).isNotEmpty();
            return xml.stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sceneFiles")
    @DisplayName("every file in scenes/ is valid against the schema")
    void scenesAreValid(Path file) throws Exception {
        validate(Files.readString(file));
    }

    /** Every element and every attribute of the format, once. */
    private static final String EVERYTHING = """
            <scene name="all" background-color="1 2 3" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
                   xsi:noNamespaceSchemaLocation="scene.xsd">
                <ambient-light color="255 255 255" ka="0.1 0.2 0.3"/>
                <geometries>
                    <sphere center="0 0 -100" radius="50" emission="10 0 0">
                        <material kd="0.5" ks="0.5 0.4 0.3" kt="0.1" kr="0.2" shininess="30"
                                  reflection-spread="0.1" transmission-spread="0.05" ior="1.5"/>
                    </sphere>
                    <plane p0="0 -60 0" p1="1 -60 0" p2="0 -60 -1"/>
                    <plane point="0 0 -500" normal="0 0 1"/>
                    <triangle p0="0 0 -90" p1="10 0 -90" p2="0 10 -90"/>
                    <polygon p0="0 0 -95" p1="10 0 -95" p2="12 8 -95" p3="5 12 -95" p4="-2 8 -95"/>
                    <tube radius="2" origin="30 0 -100" axis="0 1 0"/>
                    <cylinder radius="3" origin="-30 -20 -100" axis="0 1 0" height="20"/>
                    <mesh file="quad.obj" emission="0 0 10"/>
                </geometries>
                <lights>
                    <directional-light color="50 50 50" direction="0 -1 -1"/>
                    <point-light color="300 300 300" position="0 100 0" kc="1" kl="0.001" kq="0.00001" radius="5"/>
                    <spot-light color="300 300 300" position="0 100 0" direction="0 -1 0" kc="1" kl="0.001" kq="0.00001"
                                radius="5" narrow-beam="4"/>
                </lights>
                <camera location="0 0 0" direction="0 0 -1" up="0 1 0" vp-size="100 100" vp-distance="100"/>
                <image name="all" width="8" height="8" grid-interval="4" grid-color="255 255 0"/>
                <render threads="1" seed="3" bvh="false" beam-size="2" shadow-samples="2">
                    <anti-aliasing mode="Adaptive" grid="2 3" depth="2" threshold="4"/>
                    <depth-of-field focal-distance="100" aperture="1" samples="2"/>
                </render>
            </scene>
            """;

    @Test
    @DisplayName("a file with every element and attribute is valid for both the schema and the reader")
    void everything() throws Exception {
        validate(EVERYTHING);
        Files.writeString(dir.resolve("quad.obj"), "v 0 0 -99\nv 1 0 -99\nv 1 1 -99\nv 0 1 -99\nf 1 2 3 4\n");
        Path file = dir.resolve("all.xml");
        Files.writeString(file, EVERYTHING);
        assertThatCode(() -> XmlSceneReader.read(file)).doesNotThrowAnyException();
        assertThat(XmlSceneReader.read(file).scene().geometries.getItems()).hasSize(8);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = { "radius=\"50\"|radiuss=\"50\"", "<tube |<tubes ", "mode=\"Adaptive\"|mode=\"fast\"",
            "bvh=\"false\"|bvh=\"0\"", "radius=\"50\"|radius=\"NaN\"", "radius=\"50\"|radius=\"2,5\"",
            "center=\"0 0 -100\"|center=\"0 0\"" })
    @DisplayName("a mistake is refused by both the schema and the reader")
    void mistakes(String replacement) throws IOException {
        String[] parts = replacement.split("\\|");
        // Without the mesh, so that the reader fails on the mistake and not on the missing OBJ file.
        String xml = EVERYTHING.replace(parts[0], parts[1]).replace("<mesh file=\"quad.obj\" emission=\"0 0 10\"/>", "");
        assertThat(xml).isNotEqualTo(EVERYTHING);
        assertThatThrownBy(() -> validate(xml)).isInstanceOf(SAXException.class);
        Path file = dir.resolve("mistake.xml");
        Files.writeString(file, xml);
        assertThatThrownBy(() -> XmlSceneReader.read(file)).isInstanceOf(SceneFormatException.class);
    }
}
