package app.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The terminal progress bar made of the camera's progress lines. */
class ProgressBarTest {
    private final ByteArrayOutputStream terminal = new ByteArrayOutputStream();
    private final ProgressBar bar = new ProgressBar(new PrintStream(terminal, true, StandardCharsets.UTF_8));
    private final PrintStream camera = new PrintStream(bar, true, StandardCharsets.UTF_8);

    private String shown() {
        return terminal.toString(StandardCharsets.UTF_8);
    }

    @Test
    @DisplayName("each progress line redraws the bar in place; a shorter bar wipes the longer one's rest")
    void redraws() {
        camera.println("render x:  50.0%  50/100 px  elapsed 75.0 s  ETA 75.0 s");
        camera.println("render x: 100.0%  100/100 px  elapsed 150.0 s  ETA 0.0 s");
        String first = "render x [" + "#".repeat(15) + "-".repeat(15) + "]  50.0%  elapsed 1 min 15 s  ETA 1 min 15 s";
        String second = "render x [" + "#".repeat(30) + "] 100.0%  elapsed 2 min 30 s  ETA 0.0 s";
        assertThat(shown()).isEqualTo("\r" + first + "\r" + second + " ".repeat(first.length() - second.length()));
    }

    @Test
    @DisplayName("another line ends the bar's line first and passes unchanged")
    void otherLines() {
        camera.println("render x:  10.0%  10/100 px  elapsed 0.1 s  ETA 0.9 s");
        camera.println("render x: 0.100 s, 10x10 [NONE] of scene 's', 100 px");
        camera.println("more");
        assertThat(shown()).endsWith("ETA 0.9 s\nrender x: 0.100 s, 10x10 [NONE] of scene 's', 100 px\nmore\n");
    }

    @Test
    @DisplayName("finish() ends the bar's line once, and does nothing without a bar")
    void finish() {
        bar.finish();
        assertThat(shown()).isEmpty();
        camera.println("render x: 100.0%  1/1 px  elapsed 0.0 s  ETA 0.0 s");
        bar.finish();
        bar.finish();
        assertThat(shown()).endsWith("ETA 0.0 s\n").doesNotEndWith("\n\n");
    }

    @ParameterizedTest(name = "{0} s is \"{1}\"")
    @CsvSource({ "0, 0.0 s", "4.24, 4.2 s", "59.94, 59.9 s", "59.96, 1 min 00 s", "60, 1 min 00 s", "185.4, 3 min 05 s", "3599.4, 59 min 59 s",
            "7380, 2 h 03 min" })
    void durations(double seconds, String text) {
        assertThat(ProgressBar.duration(seconds)).isEqualTo(text);
    }
}
