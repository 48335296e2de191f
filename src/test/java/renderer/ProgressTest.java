package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.locks.LockSupport;
import java.util.function.UnaryOperator;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import scene.Scene;

/** What a render prints: progress lines while it runs and a one-line summary at the end. */
class ProgressTest {
    private static final Pattern PERCENT = Pattern.compile("(\\d+\\.\\d)%");

    /** Renders an empty 64x64 scene and returns what it printed, line by line. */
    private static List<String> printed(UnaryOperator<Camera.Builder> settings) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        ImageWriter image = new ImageWriter("tiles", 64, 64);
        settings.apply(TestScenes.camera(new Scene("progress"), image).setOutput(out)).build().renderImage();
        out.flush();
        String text = bytes.toString(StandardCharsets.UTF_8);
        return text.isEmpty() ? List.of() : text.lines().toList();
    }

    private static double percent(String line) {
        Matcher m = PERCENT.matcher(line);
        assertThat(m.find()).as("a percentage in '%s'", line).isTrue();
        return Double.parseDouble(m.group(1));
    }

    @ParameterizedTest(name = "{0} threads")
    @ValueSource(ints = {0, 2})
    @DisplayName("every 25 %: four progress lines rising to 100.0 %, then the summary")
    void progressEveryQuarter(int threads) {
        List<String> lines = printed(b -> b.setDebugPrint(25).setSummary(true).setMultithreading(threads));
        assertThat(lines).hasSize(5);
        List<String> progress = lines.subList(0, 4);
        assertThat(progress).allSatisfy(line ->
                assertThat(line).startsWith("render tiles: ").contains("elapsed").contains("ETA"));
        double previous = 0;
        for (String line : progress) {
            double p = percent(line);
            assertThat(p).as("'%s' after %.1f %%", line, previous).isGreaterThan(previous);
            previous = p;
        }
        assertThat(progress.get(3)).contains("100.0%");
        // 64x64 pixels, one camera ray each with no anti-aliasing.
        assertThat(lines.get(4)).contains("rays: camera 4096").contains("4096 px").contains("64x64");
    }

    @Test
    @DisplayName("on the calling thread the lines come at exactly 25, 50, 75 and 100 % of a 64x64 image")
    void exactQuartersOnTheCallingThread() {
        List<String> lines = printed(b -> b.setDebugPrint(25).setMultithreading(0).setSummary(false));
        assertThat(lines).extracting(ProgressTest::percent).containsExactly(25.0, 50.0, 75.0, 100.0);
    }

    @Test
    @DisplayName("no debug print and no summary: nothing is printed")
    void silent() {
        assertThat(printed(b -> b.setSummary(false))).isEmpty();
        assertThat(printed(b -> b.setSummary(false).setMultithreading(2).setDebugPrint(0))).isEmpty();
    }

    @Test
    @DisplayName("the summary alone is one line")
    void summaryOnly() {
        assertThat(printed(b -> b.setSummary(true))).singleElement().asString().contains("rays: camera 4096");
    }

    @Test
    @DisplayName("a step smaller than a tile's share prints one line per tile, never the same line twice")
    void tinyStepsPrintEachLineOnce() {
        // 64x64 in 16 tiles of 16x16: each tile is 6.25 % of the image, so a 0.001 % step is
        // crossed thousands of times per tile but may print only one line for it.
        List<String> lines = printed(b -> b.setDebugPrint(0.001).setMultithreading(0).setSummary(false));
        assertThat(lines).hasSize(16).doesNotHaveDuplicates();
        assertThat(lines.get(15)).contains("100.0%");
    }

    @Test
    @DisplayName("the pace left after a warm-up: unknown until it is measured, then counted from the mark, not from the start")
    void paceAfterWarmUp() {
        Progress progress = new Progress("pace", 100, "px", 0, new PrintStream(OutputStream.nullOutputStream()));
        double warmUp = 0.05;
        progress.advance(50); // the first tiles, before the mark
        assertThat(progress.remainingSecondsAfter(warmUp)).as("within the warm-up").isNaN();
        LockSupport.parkNanos(60_000_000L);
        assertThat(progress.remainingSecondsAfter(warmUp)).as("the first call after the warm-up: the mark").isNaN();
        assertThat(progress.remainingSecondsAfter(warmUp)).as("right after the mark").isNaN();
        LockSupport.parkNanos(60_000_000L);
        assertThat(progress.remainingSecondsAfter(warmUp)).as("nothing done since the mark").isNaN();
        progress.advance(10);
        // 40 units left at 10 units per span of at least 0.05 s: at least 0.2 s; the pace from the
        // start (60 units in about 0.12 s) would promise about 0.08 s.
        assertThat(progress.remainingSecondsAfter(warmUp)).isGreaterThanOrEqualTo(4 * warmUp);
    }

    @Test
    @DisplayName("the summary reports the preparation (BVH build) apart from the render time")
    void summaryReportsPreparation() {
        assertThat(printed(b -> b.setSummary(true))).singleElement().asString().contains("prepared in");
    }
}
