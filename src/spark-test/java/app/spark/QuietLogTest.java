package app.spark;

import static org.assertj.core.api.Assertions.assertThat;

import org.apache.spark.SparkConf;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/** The executors' log level as the command sets it in the context's configuration (no Spark started). */
class QuietLogTest {
    private static final String OPTIONS = QuietLog.EXECUTOR_JVM_OPTIONS;

    @Test
    @DisplayName("quiet: the executors start with log4j's level off, after the user's own options")
    void quiet() {
        SparkConf conf = new SparkConf(false);
        QuietLog.onExecutors(conf, true);
        assertThat(conf.get(OPTIONS)).isEqualTo("-Dorg.apache.logging.log4j.level=OFF");
        SparkConf given = new SparkConf(false).set(OPTIONS, "-XX:+UseG1GC ");
        QuietLog.onExecutors(given, true);
        assertThat(given.get(OPTIONS)).isEqualTo("-XX:+UseG1GC -Dorg.apache.logging.log4j.level=OFF");
    }

    @Test
    @DisplayName("spark.log.level asked: the executors at that level; a user's own log4j level is left alone")
    void asked() {
        SparkConf conf = new SparkConf(false).set(QuietLog.LEVEL, "warn");
        QuietLog.onExecutors(conf, false);
        assertThat(conf.get(OPTIONS)).isEqualTo("-Dorg.apache.logging.log4j.level=WARN");
        SparkConf own = new SparkConf(false).set(OPTIONS, "-Dorg.apache.logging.log4j.level=DEBUG");
        QuietLog.onExecutors(own, true);
        assertThat(own.get(OPTIONS)).isEqualTo("-Dorg.apache.logging.log4j.level=DEBUG");
    }

    @Test
    @DisplayName("a level that is not a word never reaches the executors' command line")
    void notAWord() {
        SparkConf conf = new SparkConf(false).set(QuietLog.LEVEL, "WARN -Xmx1m");
        QuietLog.onExecutors(conf, false);
        assertThat(conf.contains(OPTIONS)).isFalse();
    }
}
