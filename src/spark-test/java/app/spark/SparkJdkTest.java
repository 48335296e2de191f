package app.spark;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledForJreRange;
import org.junit.jupiter.api.condition.JRE;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Which JDKs the Spark path accepts, and what it says on the others. */
class SparkJdkTest {
    @ParameterizedTest(name = "Java {0}")
    @ValueSource(ints = { 17, 18, 19, 20, 21 })
    @DisplayName("Spark 4.0's JDKs are accepted")
    void supported(int feature) {
        assertThat(SparkJdk.unsupported(feature, "/opt/jdk")).isEmpty();
    }

    @ParameterizedTest(name = "Java {0}")
    @ValueSource(ints = { 11, 16, 22, 23, 25, 26 })
    @DisplayName("any other JDK: one line naming it, its folder, the JDKs Spark runs on and what to do")
    void unsupported(int feature) {
        assertThat(SparkJdk.unsupported(feature, "/opt/jdk-x")).hasValueSatisfying(why -> assertThat(why)
                .startsWith("Spark 4.0 runs on Java 17 to 21, and this is Java " + feature + " (/opt/jdk-x)")
                .contains("JDK 17 or 21", "JAVA_HOME").doesNotContain("\n"));
    }

    @Test
    @EnabledForJreRange(min = JRE.JAVA_22)
    @DisplayName("the Java API refuses on such a JDK before any context is made")
    void javaApiRefuses() {
        assertThatThrownBy(SparkRenderer::requireSupportedJava).isInstanceOf(UnsupportedOperationException.class)
                .hasMessageStartingWith("Spark 4.0 runs on Java 17 to 21, and this is Java " + Runtime.version().feature());
    }

    @Test
    @EnabledForJreRange(max = JRE.JAVA_21)
    @DisplayName("the Java API accepts this JDK")
    void javaApiAccepts() {
        SparkRenderer.requireSupportedJava();
        assertThat(SparkJdk.unsupported()).isEmpty();
    }
}
