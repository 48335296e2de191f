package app.spark;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import app.Project;
import app.cli.SparkRequest;

/**
 * A cluster master outside spark-submit: the executors need this program's classes. From a jar,
 * the command ships it ({@code spark.jars}); from class folders (the tests', the Maven profile's)
 * it refuses at once, exit 2, one line saying to use spark-submit, instead of a job whose every
 * task failed with ClassNotFoundException after a minute.
 */
class ClusterJarTest {
    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource({ "local, true", "local[2], true", "'local[2,3]', true", "local[*], true", "spark://127.0.0.1:7077, false",
            "yarn, false", "k8s://https://h:443, false", "'local-cluster[2,1,1024]', false" })
    @DisplayName("which masters run their executors in the driver's JVM")
    void inThisJvm(String master, boolean local) {
        assertThat(SparkCommand.runsInThisJvm(master)).isEqualTo(local);
    }

    @Test
    @DisplayName("from class folders there is no jar to ship")
    void classFolders() {
        assertThat(SparkCommand.applicationJar()).isNull(); // the tests run from target/classes
    }

    @Test
    @DisplayName("--spark spark://… from class folders: exit 2 at once, one line naming spark-submit, no Spark started")
    void refusedAtOnce() {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8), e = new PrintStream(err, true, StandardCharsets.UTF_8);
        // Port 1: nothing listens there; the command must not try.
        SparkRequest request = new SparkRequest("spark://127.0.0.1:1", List.of(Project.file("scenes/glossy.xml")),
                (s, scene) -> s.withImage("glossy", 4, 4), dir.resolve("x.png"), 0, true);
        assertThat(SparkCommand.run(request, o, o, e)).isEqualTo(SparkEntry.BAD_INPUT);
        assertThat(err.toString(StandardCharsets.UTF_8)).hasLineCount(1)
                .startsWith("raytracer: --spark spark://127.0.0.1:1: a cluster's executors need this program's jar")
                .contains("spark-submit --master spark://127.0.0.1:1 --class app.cli.Main target/raytracer.jar --spark submit");
        assertThat(dir.resolve("x.png")).doesNotExist();
    }
}
