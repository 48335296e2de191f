package app.cli;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Turns the camera's progress lines into one progress bar redrawn in place with '\r', for a
 * terminal. The camera prints progress as full lines (right for logs and IDE consoles); this
 * stream sits between the camera and the terminal, recognises those lines and redraws the bar
 * instead; every other line (the render summary) ends the bar's line first and passes unchanged.
 *
 * <p>The line format it recognises is the camera's: {@code LABEL:  45.0%  450/1000 px  elapsed
 * 3.1 s  ETA 3.8 s} (a Spark render counts {@code tiles} instead of {@code px}). A test renders through this stream, so a change of that format shows.
 */
final class ProgressBar extends OutputStream {
    static final Pattern PROGRESS_LINE = Pattern.compile(
            "(.*): +(\\d+(?:\\.\\d+)?)%\\s+\\d+/\\d+ (?:px|tiles)\\s+elapsed (\\d+(?:\\.\\d+)?) s\\s+ETA (\\d+(?:\\.\\d+)?) s");
    private static final int BAR_WIDTH = 30;

    private final PrintStream terminal;
    private final ByteArrayOutputStream line = new ByteArrayOutputStream();
    /** Length of the bar as last drawn; 0 when no bar is on the current line. */
    private int drawn;

    ProgressBar(PrintStream terminal) {
        this.terminal = terminal;
    }

    @Override
    public synchronized void write(int b) {
        if (b == '\n') flushLine();
        else if (b != '\r') line.write(b);
    }

    @Override
    public synchronized void write(byte[] b, int off, int len) {
        for (int i = off; i < off + len; ++i) write(b[i]);
    }

    @Override
    public synchronized void flush() {
        terminal.flush();
    }

    /** Ends the bar's line, if a bar is showing, so that the next output starts on a new line. */
    synchronized void finish() {
        if (drawn > 0) terminal.println();
        drawn = 0;
        terminal.flush();
    }

    private void flushLine() {
        String text = line.toString(StandardCharsets.UTF_8);
        line.reset();
        Matcher m = PROGRESS_LINE.matcher(text);
        if (m.matches()) {
            draw(m.group(1), Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3)),
                    Double.parseDouble(m.group(4)));
        } else {
            finish();
            terminal.println(text);
        }
        terminal.flush();
    }

    private void draw(String label, double percent, double elapsed, double eta) {
        int filled = (int) Math.round(BAR_WIDTH * Math.min(100, percent) / 100);
        String bar = String.format(Locale.ROOT, "%s [%s%s] %5.1f%%  elapsed %s  ETA %s", label, "#".repeat(filled),
                "-".repeat(BAR_WIDTH - filled), percent, duration(elapsed), duration(eta));
        // Spaces wipe what is left of a longer previous bar (ETAs shrink).
        terminal.print("\r" + bar + " ".repeat(Math.max(0, drawn - bar.length())));
        drawn = bar.length();
    }

    /** Seconds as "4.2 s", "3 min 05 s" or "2 h 03 min". */
    static String duration(double seconds) {
        if (seconds < 59.95) return String.format(Locale.ROOT, "%.1f s", seconds); // not "60.0 s"
        long s = Math.round(seconds);
        if (s < 3600) return String.format(Locale.ROOT, "%d min %02d s", s / 60, s % 60);
        return String.format(Locale.ROOT, "%d h %02d min", s / 3600, s / 60 % 60);
    }
}
