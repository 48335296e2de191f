package renderer.junit;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import renderer.junit.Comparison.Metrics;
import renderer.junit.Comparison.Status;

/**
 * The Java side of the parity proof ({@code scripts/test_image_assertions_parity.py}): reads
 * lines "render TAB reference" from the file named by its first argument and prints, for each
 * pair, the verdict and the figures the image assertions reach, as JSON. The thresholds are the
 * defaults, or the five numbers after the file (failthresh failpercent hardfail warnthresh
 * warnpercent). The Python test compares them with {@code verify_images.py}'s, image for image.
 * <p>Run: {@code java -cp target/classes:target/test-classes renderer.junit.VerdictTool pairs.tsv}
 */
final class VerdictTool {
    private VerdictTool() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 1 && args.length != 6) {
            System.err.println("usage: VerdictTool PAIRS_FILE [failthresh failpercent hardfail warnthresh warnpercent]");
            System.exit(2);
        }
        ImageThresholds t = args.length == 1 ? ImageThresholds.DEFAULTS
                : new ImageThresholds(Double.parseDouble(args[1]), Double.parseDouble(args[2]), Double.parseDouble(args[3]),
                        Double.parseDouble(args[4]), Double.parseDouble(args[5]));
        List<String> out = new ArrayList<>();
        for (String line : Files.readAllLines(Path.of(args[0]), StandardCharsets.UTF_8)) {
            if (line.isBlank()) continue;
            String[] pair = line.split("\t");
            out.add(json(pair[0], pair[1], judge(Path.of(pair[0]), Path.of(pair[1]), t)));
        }
        System.out.println(String.format(Locale.ROOT,
                "{\"thresholds\": {\"failthresh\": %s, \"failpercent\": %s, \"hardfail\": %s, \"warnthresh\": %s, \"warnpercent\": %s},%n\"results\": [%n",
                t.failThreshold(), t.failPercent(), t.hardFail(), t.warnThreshold(), t.warnPercent()) + String.join(",\n", out)
                + "\n]}");
    }

    /** The script's order: a missing reference first, then the render read, then the reference. */
    static Comparison judge(Path render, Path reference, ImageThresholds t) {
        if (!Files.exists(reference)) return Comparison.without(Status.MISSING_REFERENCE, "no reference " + reference);
        try {
            return Comparison.of(Picture.read(render, "render"), Picture.read(reference, "reference"), t);
        } catch (Picture.UnreadableException e) {
            return Comparison.without(Status.ERROR, e.getMessage());
        }
    }

    private static String json(String render, String reference, Comparison c) {
        StringBuilder s = new StringBuilder("{\"render\": ").append(quote(render)).append(", \"reference\": ").append(quote(reference))
                .append(", \"verdict\": ").append(quote(c.status().label())).append(", \"message\": ").append(quote(c.message()));
        Metrics m = c.metrics();
        if (m != null)
            s.append(String.format(Locale.ROOT,
                    ", \"metrics\": {\"meanerror\": %s, \"maxerror\": %s, \"maxx\": %d, \"maxy\": %d, \"maxc\": %d, \"psnr\": %s, \"rms_error\": %s, \"nfail\": %d, \"nwarn\": %d, \"npixels\": %d}",
                    number(m.meanError()), number(m.maxError()), m.maxX(), m.maxY(), m.maxChannel(), number(m.psnr()),
                    number(m.rmsError()), m.failing(), m.warning(), m.pixels()));
        return s.append('}').toString();
    }

    private static String number(double x) {
        return Double.isFinite(x) ? Double.toString(x) : "null";
    }

    private static String quote(String text) {
        StringBuilder s = new StringBuilder("\"");
        for (char ch : text.toCharArray()) {
            if (ch == '"' || ch == '\\') s.append('\\').append(ch);
            else if (ch < 0x20) s.append(String.format("\\u%04x", (int) ch));
            else s.append(ch);
        }
        return s.append('"').toString();
    }
}
