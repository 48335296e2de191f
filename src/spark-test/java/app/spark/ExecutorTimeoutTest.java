package app.spark;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

import org.apache.spark.SparkConf;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import app.Project;
import app.cli.SparkRequest;

/**
 * {@value SparkRenderer#EXECUTOR_TIMEOUT} is checked as {@link SparkRenderer#setExecutorTimeout}
 * checks its argument: a positive time, or the command line ends with exit 2 and one line, before
 * Spark starts.
 */
class ExecutorTimeoutTest {
    @TempDir
    Path dir;

    private static SparkConf with(String value) {
        return new SparkConf(false).set(SparkRenderer.EXECUTOR_TIMEOUT, value);
    }

    @ParameterizedTest(name = "{0} = {1} s")
    @CsvSource({ "120s, 120", "5m, 300", "1ms, 0.001", "1500ms, 1.5", "30, 30" })
    @DisplayName("a positive time, in Spark's units (a bare number is seconds)")
    void accepted(String value, double seconds) {
        assertThat(SparkRenderer.executorTimeout(with(value))).isEqualTo(seconds);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = { "0s", "0", "-5s", "0ms" })
    @DisplayName("zero or negative: refused, naming the setting and the value")
    void notPositive(String value) {
        assertThatThrownBy(() -> SparkRenderer.executorTimeout(with(value))).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("spark.raytracer.executorTimeout '" + value + "' is not positive (expected a positive time"
                        + " such as 120s, 5m or 500ms)");
    }

    @ParameterizedTest(name = "\"{0}\"")
    @ValueSource(strings = { "abc", "5 parsecs", "1.5s", "" })
    @DisplayName("not a time: refused, naming the setting and the value")
    void garbage(String value) {
        assertThatThrownBy(() -> SparkRenderer.executorTimeout(with(value))).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("spark.raytracer.executorTimeout '" + value + "' is not a time (expected a positive time"
                        + " such as 120s, 5m or 500ms)");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = { "0s", "-5s", "abc" })
    @DisplayName("the command line: exit 2, one line, before Spark starts")
    void commandLine(String value) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8), e = new PrintStream(err, true, StandardCharsets.UTF_8);
        SparkRequest request = new SparkRequest("local[1]", List.of(Project.file("scenes/glossy.xml")),
                (s, scene) -> s.withImage("glossy", 4, 4), dir.resolve("x.png"), 0, true);
        String before = System.getProperty(SparkRenderer.EXECUTOR_TIMEOUT);
        System.setProperty(SparkRenderer.EXECUTOR_TIMEOUT, value); // what spark-submit's --conf does
        try {
            assertThat(SparkCommand.run(request, o, o, e)).isEqualTo(SparkEntry.BAD_INPUT);
        } finally {
            if (before == null) System.clearProperty(SparkRenderer.EXECUTOR_TIMEOUT);
            else System.setProperty(SparkRenderer.EXECUTOR_TIMEOUT, before);
        }
        assertThat(err.toString(StandardCharsets.UTF_8)).hasLineCount(1)
                .startsWith("raytracer: spark.raytracer.executorTimeout '" + value + "' is not ");
        assertThat(dir.resolve("x.png")).doesNotExist();
    }
}
