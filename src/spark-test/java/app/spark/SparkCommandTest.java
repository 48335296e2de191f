package app.spark;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

import org.apache.spark.TaskContext;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import app.Project;
import app.cli.SparkRequest;

/**
 * The command line's Spark run when the cluster fails: Spark retries a task up to its limit,
 * then the command ends with exit code 1, one line, and no image.
 */
@EnabledWhereSparkRuns
class SparkCommandTest {
    @TempDir
    Path dir;

    @Test
    @DisplayName("a task failing every attempt under local[2, 3]: exit 1, one line on the error stream, no PNG")
    void exhaustedRetries() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8), e = new PrintStream(err, true, StandardCharsets.UTF_8);
        Path png = dir.resolve("fail.png");
        SparkRequest request = new SparkRequest("local[2,3]", List.of(Project.file("scenes/glossy.xml")),
                (s, scene) -> s.withImage("glossy", 40, 30), png, 0, true);
        int code = SparkCommand.run(request, tile -> {
            if (TaskContext.getPartitionId() == 0) throw new IllegalStateException("injected: the executor lost its disk");
        }, o, o, e);
        assertThat(code).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).hasLineCount(1)
                .startsWith("raytracer: failed on Spark: spark render glossy: Job aborted due to stage failure: Task 0 in stage 0.0 failed 3 times")
                .contains("injected: the executor lost its disk");
        assertThat(png).doesNotExist();
        assertThat(out.toString(StandardCharsets.UTF_8)).doesNotContain("wrote");
    }

    @Test
    @DisplayName("the request refuses one output for several scenes")
    void oneOutputOneScene() {
        List<Path> two = List.of(Path.of("a.xml"), Path.of("b.xml"));
        org.assertj.core.api.Assertions.assertThatIllegalArgumentException()
                .isThrownBy(() -> new SparkRequest("local", two, (s, scene) -> s, Path.of("x.png"), 0, true))
                .withMessageContaining("one output file for 2 scenes");
    }
}
