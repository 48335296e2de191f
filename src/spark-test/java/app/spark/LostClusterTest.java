package app.spark;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.stream.Collectors;

import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.deploy.master.Master;
import org.apache.spark.deploy.worker.Worker;
import org.apache.spark.rpc.RpcEnv;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import scala.Option;

import app.Project;

/**
 * A real cluster on loopback: Spark's standalone master and one worker started in this JVM
 * (127.0.0.1, ports chosen by the system; their web UIs on 127.0.0.1 through SPARK_LOCAL_IP),
 * whose executor is a JVM of its own launched by the worker with this JVM's class path (as
 * Spark's own tests do without an installation: SPARK_TESTING, SPARK_SCALA_VERSION and
 * SPARK_DIST_CLASSPATH in its environment). A render starts; the worker is stopped, which kills its
 * executor; the driver, which Spark would leave waiting without end, cancels the job once it has
 * had no executor for the timeout, and says so in one line.
 */
@EnabledWhereSparkRuns
class LostClusterTest {
    @TempDir
    Path dir;

    @Test
    @DisplayName("every executor lost mid-job: the job ends within the timeout with one line, no image")
    void everyExecutorLost() throws Exception {
        // The master's and worker's web UIs bind to SPARK_LOCAL_IP, else to every interface: the
        // spark-tests execution of pom.xml sets it; elsewhere the test does not run.
        assumeTrue("127.0.0.1".equals(System.getenv("SPARK_LOCAL_IP")), "SPARK_LOCAL_IP=127.0.0.1 (pom.xml, spark-tests)");
        SparkConf daemons = new SparkConf().set("spark.ui.enabled", "false").set("spark.master.ui.port", "0")
                .set("spark.worker.ui.port", "0").set("spark.log.level", "ERROR");
        RpcEnv master = Master.startRpcEnvAndEndpoint("127.0.0.1", 0, 0, daemons)._1();
        String url = "spark://127.0.0.1:" + master.address().port();
        RpcEnv worker = Worker.startRpcEnvAndEndpoint("127.0.0.1", 0, 0, 1, 1024, new String[] { url },
                Files.createDirectories(dir.resolve("work")).toString(), Option.empty(), daemons, Option.empty());
        String opens = ManagementFactory.getRuntimeMXBean().getInputArguments().stream()
                .filter(a -> a.startsWith("--add-opens") || a.startsWith("-Djdk.") || a.startsWith("-Dio.netty"))
                .collect(Collectors.joining(" "));
        SparkConf driver = new SparkConf().setMaster(url).setAppName("LostClusterTest")
                .set("spark.driver.host", "127.0.0.1").set("spark.driver.bindAddress", "127.0.0.1")
                .set("spark.ui.enabled", "false").set("spark.log.level", "ERROR")
                .set("spark.executor.memory", "512m").set("spark.executor.extraJavaOptions", opens)
                // The worker launches its executor as Spark's own tests do: no installation, this class path.
                .set("spark.executorEnv.SPARK_TESTING", "1").set("spark.executorEnv.SPARK_SCALA_VERSION", "2.13")
                .set("spark.executorEnv.SPARK_DIST_CLASSPATH", System.getProperty("java.class.path"))
                .set(SparkRenderer.EXECUTOR_TIMEOUT, "5s");
        ByteArrayOutputStream progress = new ByteArrayOutputStream();
        try (JavaSparkContext spark = new JavaSparkContext(driver)) {
            SparkFrame frame = SparkFrame.read(Project.file("scenes/glossy.xml"));
            frame = frame.withSettings(frame.settings().withImage("lost", 64, 64)).withOutput(dir.resolve("lost.png"));
            List<SparkFrame> frames = List.of(frame);
            SparkRenderer renderer = new SparkRenderer(spark).setTileSize(16).setProgress(50)
                    .setOutput(new PrintStream(progress, true, StandardCharsets.UTF_8)).setSummary(false)
                    .setProbe(tile -> { // 16 tiles of a second each on one core
                        try {
                            Thread.sleep(1000);
                        } catch (InterruptedException e) {
                            Thread.currentThread().interrupt();
                        }
                    });
            // The executor (a JVM the worker starts) is up before the job: its start is no loss.
            assertTimeoutPreemptively(Duration.ofMinutes(2), () -> {
                while (spark.sc().statusTracker().getExecutorInfos().length < 2) Thread.sleep(200);
            });
            AtomicBoolean killedAtWork = new AtomicBoolean();
            Thread killer = new Thread(() -> {
                try {
                    // The executor at work: stop the worker, which kills its executor.
                    Thread.sleep(3000);
                    killedAtWork.set(spark.sc().statusTracker().getExecutorInfos().length == 2);
                    worker.shutdown();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "worker-killer");
            killer.setDaemon(true);
            killer.start();
            assertTimeoutPreemptively(Duration.ofMinutes(3), () -> assertThatThrownBy(() -> renderer.render(frames))
                    .isInstanceOf(SparkRenderException.class)
                    .hasMessage("spark render lost: every executor was lost and none came back for 5 s: the cluster lost"
                            + " its workers (the limit is spark.raytracer.executorTimeout)"));
            assertThat(killedAtWork).as("the executor was up when the worker was stopped").isTrue();
            assertThat(progress.toString(StandardCharsets.UTF_8))
                    .contains("spark render lost: waiting for executors: none is available (the job ends if none comes within 5 s)");
            assertThat(dir.resolve("lost.png")).doesNotExist();
        } finally {
            worker.shutdown();
            master.shutdown();
        }
    }
}
