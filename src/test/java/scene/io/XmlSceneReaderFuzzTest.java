package scene.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

import com.code_intelligence.jazzer.junit.DictionaryFile;
import com.code_intelligence.jazzer.junit.FuzzTest;

import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;

/**
 * Scene files from the fuzzer: every input either loads and renders (tiny, sampling turned down,
 * so that an input cannot ask for a long render) or ends in one {@link SceneFormatException}
 * line that names the file. Anything else (another exception, an error, a hang) is a finding.
 *
 * <p>Without {@code JAZZER_FUZZ=1} this replays {@code XmlSceneReaderFuzzTestInputs/read/}: the
 * seed corpus and every input a fuzzing run found (see docs/fuzzing.md). The inputs are scene
 * files in a folder that also holds {@code cube.obj}, so that {@code <mesh file="cube.obj"/>}
 * reaches the OBJ reader. The dictionary {@code scene.dict} gives the fuzzer the format's element
 * and attribute names and edge values (1e308, 65536, /dev/zero...).
 */
class XmlSceneReaderFuzzTest {
    private static Path dir;
    private static Path scene;

    @BeforeAll
    static void folder() throws IOException {
        dir = Files.createTempDirectory("scene-fuzz");
        scene = dir.resolve("fuzz.xml");
        Files.writeString(dir.resolve("cube.obj"), ObjReaderFuzzTest.CUBE);
    }

    @AfterAll
    static void cleanUp() throws IOException {
        Files.deleteIfExists(dir.resolve("cube.obj"));
        Files.deleteIfExists(dir);
    }

    @FuzzTest
    @DictionaryFile(resourcePath = "/scene/io/scene.dict")
    void read(byte[] content) {
        LoadedScene loaded;
        try {
            loaded = XmlSceneReader.read(content, scene);
        } catch (SceneFormatException e) {
            assertThat(e.getMessage()).startsWith(scene + ":").doesNotContain("\n");
            return;
        }
        Camera.Builder view;
        try {
            view = loaded.requireView(); // the view only: no image of the file's size is allocated
        } catch (SceneFormatException noCamera) {
            assertThat(noCamera.getMessage()).startsWith(scene + ":").contains("the scene has no <camera>");
            return;
        }
        RenderSettings settings = loaded.settings().withImage("fuzz", 3, 2).withThreads(0)
                .withAntiAliasing(AntiAliasing.NONE).withDepthOfField(0, 0).withDepthOfFieldSamples(1).withBeamSize(2).withShadowSamples(2);
        ImageWriter image = settings.newImageWriter();
        settings.applyTo(view, loaded.scene(), image).setSummary(false).setDebugPrint(0).build().render();
    }
}
