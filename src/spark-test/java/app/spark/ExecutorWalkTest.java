package app.spark;

import static org.assertj.core.api.Assertions.assertThat;

import org.apache.spark.SparkConf;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

@DisplayName("the executors take the vector walk from the first ray, unless the user chose a walk")
class ExecutorWalkTest {
    private static final String OPTIONS = QuietLog.EXECUTOR_JVM_OPTIONS;

    @Test
    @DisplayName("added after the options already there")
    void added() {
        SparkConf conf = new SparkConf(false);
        ExecutorWalk.fromTheFirstRay(conf);
        assertThat(conf.get(OPTIONS)).isEqualTo("-Draytracer.simd=true");
        SparkConf given = new SparkConf(false).set(OPTIONS, "-Dorg.apache.logging.log4j.level=OFF ");
        ExecutorWalk.fromTheFirstRay(given);
        assertThat(given.get(OPTIONS)).isEqualTo("-Dorg.apache.logging.log4j.level=OFF -Draytracer.simd=true");
    }

    @Test
    @DisplayName("a user's own -Draytracer.simd is left alone")
    void usersOwn() {
        SparkConf conf = new SparkConf(false).set(OPTIONS, "-Draytracer.simd=false");
        ExecutorWalk.fromTheFirstRay(conf);
        assertThat(conf.get(OPTIONS)).isEqualTo("-Draytracer.simd=false");
    }
}
