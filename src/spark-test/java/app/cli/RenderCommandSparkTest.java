package app.cli;

import static app.cli.Cli.run;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledForJreRange;
import org.junit.jupiter.api.condition.JRE;
import org.junit.jupiter.api.io.TempDir;

import app.cli.Cli.Run;
import app.spark.EnabledWhereSparkRuns;

import renderer.ImageWriter;

/**
 * {@code render --spark MASTER}: the command line's Spark render in local mode, against the same
 * command without {@code --spark}. Each Spark run starts and stops its own context.
 */
class RenderCommandSparkTest {
    /**
     * The prefix of the image names: frames are written to images/&lt;image name&gt;.png (an image
     * name is a name, not a path), and removed after each test.
     */
    private static final String PREFIX = "spark-test-";

    @TempDir
    Path dir;

    /** A small scene: a sphere's edge, a glossy floor and a soft shadow, so that sampling shows. */
    private Path scene(String name, int seed) throws IOException {
        Path file = dir.resolve(name + ".xml");
        // The command line tests' small scene, with its own name, a larger image, a seed and a grid.
        Files.writeString(file, Cli.SMALL.replace("<scene name=\"small\"", "<scene name=\"" + name + "\"")
                .replace("<image name=\"small\" width=\"40\" height=\"20\"/>",
                        "<image name=\"" + PREFIX + name + "\" width=\"70\" height=\"35\"/>")
                .replace("<render threads=\"1\" beam-size=\"3\" shadow-samples=\"3\"/>",
                        "<render threads=\"1\" beam-size=\"3\" shadow-samples=\"3\" seed=\"" + seed + "\">"
                                + "<anti-aliasing mode=\"random\" grid=\"2 3\"/></render>"));
        return file;
    }

    private static Path frame(String name) {
        return ImageWriter.IMAGES.resolve(PREFIX + name + ".png");
    }

    @AfterEach
    void removeFrames() throws IOException {
        for (String name : List.of("one", "a", "b", "good"))
            Files.deleteIfExists(frame(name));
    }

    @Test
    @EnabledWhereSparkRuns
    @DisplayName("--spark local[2] writes the bytes of the local render, with progress in tiles and a summary")
    void sameBytesAsLocal() throws IOException {
        Path scene = scene("one", 3);
        Run local = run(scene.toString(), "-o", dir.resolve("local.png").toString());
        Run spark = run(scene.toString(), "--spark", "local[2]", "-o", dir.resolve("spark.png").toString());
        assertThat(local.exitCode()).isZero();
        assertThat(spark.exitCode()).as(spark.err()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("spark.png"))).isEqualTo(Files.readAllBytes(dir.resolve("local.png")));
        assertThat(spark.out()).contains("spark render spark-test-one: 100.0%  2/2 tiles")
                .containsPattern("spark render spark-test-one: \\d+\\.\\d+ s, 70x35 \\[RANDOM 2x3, ").contains("1 executor, 2 tasks, 0 retries")
                .contains("wrote " + dir.resolve("spark.png"));
        assertThat(spark.err()).isEmpty();
    }

    @Test
    @EnabledWhereSparkRuns
    @DisplayName("several scene files with --spark are the frames of one job, one PNG each, each as rendered locally")
    void frames() throws IOException {
        Path a = scene("a", 1), b = scene("b", 2);
        Run spark = run("--spark", "local[2]", a.toString(), b.toString(), "--width", "20");
        assertThat(spark.exitCode()).as(spark.err()).isZero();
        assertThat(spark.out()).contains("spark render 2 frames: 100.0%  2/2 tiles");
        for (Path scene : List.of(a, b)) {
            String name = scene.getFileName().toString().replace(".xml", "");
            Path png = frame(name);
            Path local = dir.resolve(name + "-local.png");
            assertThat(run(scene.toString(), "--width", "20", "-o", local.toString()).exitCode()).isZero();
            assertThat(Files.readAllBytes(png)).as(name).isEqualTo(Files.readAllBytes(local));
        }
    }

    @Test
    @EnabledWhereSparkRuns
    @DisplayName("a bad scene among the frames: exit 2 with the local command's one line, no Spark started, no image")
    void badScene() throws IOException {
        Path good = scene("good", 0);
        Path bad = dir.resolve("bad.xml");
        Files.writeString(bad, "<scene>\n  <geometries>\n    <sphere center=\"0 0\" radius=\"1\"/>\n  </geometries>\n</scene>\n");
        Run local = run(bad.toString());
        Run spark = run("--spark", "local[2]", good.toString(), bad.toString());
        assertThat(local.exitCode()).isEqualTo(2);
        assertThat(spark.exitCode()).isEqualTo(2);
        assertThat(spark.err()).isEqualTo(local.err()).startsWith(bad + ":3:").hasLineCount(1);
        assertThat(spark.out()).as("no progress, no summary: no task ran").isEmpty();
        assertThat(frame("good")).doesNotExist();
    }

    @Test
    @DisplayName("usage: several scenes need --spark, and --output names one file")
    void usage() throws IOException {
        Path a = scene("a", 1), b = scene("b", 2);
        Run without = run(a.toString(), b.toString());
        assertThat(without.exitCode()).isEqualTo(2);
        assertThat(without.err()).startsWith("raytracer: several scene files are rendered only with --spark");
        Run output = run("--spark", "local[2]", a.toString(), b.toString(), "-o", dir.resolve("x.png").toString());
        assertThat(output.exitCode()).isEqualTo(2);
        assertThat(output.err()).startsWith("raytracer: --output names one file, for one scene");
    }

    @Test
    @EnabledWhereSparkRuns
    @DisplayName("--spark submit outside spark-submit (no spark.master): exit 2, one line, nothing started")
    void submitWithoutSparkSubmit() throws IOException {
        assertThat(System.getProperty("spark.master")).as("this JVM was not started by spark-submit").isNull();
        Run run = run("--spark", "submit", scene("one", 0).toString(), "-o", dir.resolve("x.png").toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).hasLineCount(1).startsWith("raytracer: --spark submit takes the master of spark-submit, and there is none");
        assertThat(run.out()).isEmpty();
        assertThat(dir.resolve("x.png")).doesNotExist();
    }

    @Test
    @DisplayName("--spark without Spark on the class path (the runnable jar): one line saying how to run it, exit 2")
    void noSparkOnClassPath() throws IOException, InterruptedException {
        Path scene = scene("one", 0);
        Run run = Cli.runJava(dir, "-Xmx256m", "--spark", "local[2]", scene.toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).hasLineCount(1)
                .startsWith("raytracer: --spark needs Apache Spark on the class path").contains("-Pspark", "spark-submit");
        assertThat(dir.resolve("images")).doesNotExist();
    }

    @Test
    @EnabledForJreRange(min = JRE.JAVA_22)
    @DisplayName("on a JDK Spark does not run on: one line naming the JDK and what to do, exit 2, nothing started")
    void unsupportedJdk() throws IOException {
        Run run = run("--spark", "local[2]", scene("one", 0).toString(), "-o", dir.resolve("x.png").toString());
        assertThat(run.exitCode()).isEqualTo(2);
        assertThat(run.err()).hasLineCount(1)
                .startsWith("raytracer: --spark: Spark 4.0 runs on Java 17 to 21, and this is Java " + Runtime.version().feature())
                .contains(System.getProperty("java.home"), "JAVA_HOME");
        assertThat(run.out()).as("no progress, no summary: no task ran").isEmpty();
        assertThat(dir.resolve("x.png")).doesNotExist();
    }

    @Test
    @EnabledWhereSparkRuns
    @DisplayName("--mesh-root: a mesh outside the scene's folder is refused on the driver without it, and with it renders the local bytes")
    void meshRoot() throws IOException {
        Path meshes = Files.createDirectories(dir.resolve("meshes")), scenes = Files.createDirectories(dir.resolve("scenes"));
        Files.writeString(meshes.resolve("tri.obj"), "v -10 -8 -60\nv 10 -8 -60\nv 0 10 -60\nf 1 2 3\n");
        Path scene = scenes.resolve("mesh.xml");
        Files.writeString(scene, Cli.SMALL.replace("<geometries>", "<geometries>\n<mesh file=\"../meshes/tri.obj\" emission=\"40 200 40\"/>")
                .replace("<image name=\"small\"", "<image name=\"" + PREFIX + "mesh\""));
        Run refused = run("--spark", "local[2]", scene.toString(), "-o", dir.resolve("refused.png").toString());
        assertThat(refused.exitCode()).isEqualTo(2);
        assertThat(refused.err()).hasLineCount(1).contains("is outside the folder meshes are read from");
        assertThat(refused.out()).as("no task ran").isEmpty();

        Run local = run(scene.toString(), "--mesh-root", dir.toString(), "-o", dir.resolve("local.png").toString());
        Run spark = run("--spark", "local[2]", scene.toString(), "--mesh-root", dir.toString(), "-o", dir.resolve("spark.png").toString());
        assertThat(local.exitCode()).as(local.err()).isZero();
        assertThat(spark.exitCode()).as(spark.err()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("spark.png"))).isEqualTo(Files.readAllBytes(dir.resolve("local.png")));
    }
}
