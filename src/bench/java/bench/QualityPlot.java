package bench;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Draws the quality benchmark's figure with Java2D: one panel per scene, PSNR (dB) against camera
 * rays per pixel on a log₂ axis, one line per mode (a single point for NONE and CORNERS).
 */
final class QualityPlot {
    private static final int PANEL_W = 460, PANEL_H = 360, MARGIN_L = 56, MARGIN_R = 16, MARGIN_T = 34, MARGIN_B = 46;
    private static final double X_MIN = 0.5, X_MAX = 128; // camera rays per pixel
    private static final double Y_MIN = 20, Y_MAX = 65; // dB
    private static final Color[] PALETTE = { new Color(0x444444), new Color(0x8c564b), new Color(0x1f77b4),
            new Color(0x2ca02c), new Color(0xff7f0e), new Color(0xd62728), new Color(0x9467bd), new Color(0x17becf) };
    /**
     * Each mode's colour, the same in every panel (NONE with a lens is NONE's line); a mode not
     * named here takes the palette's next colour.
     */
    private static final Map<String, Color> COLOURS = Map.of("NONE", PALETTE[0], "NONE + lens", PALETTE[0],
            "CORNERS", PALETTE[1], "RANDOM", PALETTE[2], "ADAPTIVE depth 2", PALETTE[3], "ADAPTIVE depth 3", PALETTE[4],
            "ADAPTIVE depth 4", PALETTE[5], "ADAPTIVE default", PALETTE[6]);

    private QualityPlot() {
    }

    static BufferedImage draw(Map<String, List<QualityResult>> results, int side) {
        int panels = Math.max(1, results.size());
        BufferedImage img = new BufferedImage(PANEL_W * panels, PANEL_H + 24, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, img.getWidth(), img.getHeight());
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.setColor(Color.DARK_GRAY);
        g.drawString(String.format(Locale.ROOT, "PSNR against RANDOM %d×%d of the same scene (%d×%d pixels)",
                QualityBenchmark.REFERENCE_GRID, QualityBenchmark.REFERENCE_GRID, side, side), 8, PANEL_H + 16);
        int i = 0;
        for (Map.Entry<String, List<QualityResult>> e : results.entrySet())
            panel(g, i++ * PANEL_W, e.getKey(), e.getValue());
        g.dispose();
        return img;
    }

    private static void panel(Graphics2D g, int x0, String scene, List<QualityResult> rows) {
        int left = x0 + MARGIN_L, right = x0 + PANEL_W - MARGIN_R, top = MARGIN_T, bottom = PANEL_H - MARGIN_B;
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.drawString(scene.endsWith("-dof") ? scene.substring(0, scene.length() - 4) + " with depth of field (focal "
                + QualityBenchmark.fmt(QualityBenchmark.DOF_FOCAL_DISTANCE) + ", aperture "
                + QualityBenchmark.fmt(QualityBenchmark.DOF_APERTURE) + ")" : scene, left, 20);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        // Grid and axes.
        for (double x = 1; x <= X_MAX; x *= 2) {
            int px = xPixel(x, left, right);
            g.setColor(new Color(0xe6e6e6));
            g.drawLine(px, top, px, bottom);
            g.setColor(Color.DARK_GRAY);
            g.drawString(QualityBenchmark.fmt(x), px - 6, bottom + 14);
        }
        for (double y = Y_MIN; y <= Y_MAX; y += 5) {
            int py = yPixel(y, top, bottom);
            g.setColor(y == 50 ? new Color(0xbbbbbb) : new Color(0xe6e6e6));
            g.drawLine(left, py, right, py);
            g.setColor(Color.DARK_GRAY);
            g.drawString(QualityBenchmark.fmt(y), left - 22, py + 4);
        }
        g.drawRect(left, top, right - left, bottom - top);
        g.drawString("camera rays per pixel (log scale)", left + 90, bottom + 32);
        Graphics2D rotated = (Graphics2D) g.create();
        rotated.rotate(-Math.PI / 2);
        rotated.drawString("PSNR dB", -(top + bottom) / 2 - 20, x0 + 16);
        rotated.dispose();
        // One line per mode, in the order the modes first appear.
        Map<String, List<QualityResult>> lines = new LinkedHashMap<>();
        for (QualityResult r : rows) lines.computeIfAbsent(r.c().mode(), k -> new ArrayList<>()).add(r);
        // The legend in the lower right corner, where few points fall (many rays, low PSNR).
        int k = 0, legendY = bottom - 6 - 14 * (lines.size() - 1);
        for (Map.Entry<String, List<QualityResult>> line : lines.entrySet()) {
            Color colour = COLOURS.getOrDefault(line.getKey(), PALETTE[(COLOURS.size() + k) % PALETTE.length]);
            ++k;
            g.setColor(colour);
            g.setStroke(new BasicStroke(1.8f));
            List<QualityResult> pts = new ArrayList<>(line.getValue());
            pts.sort((a, b) -> Double.compare(a.cameraPerPixel(), b.cameraPerPixel()));
            int prevX = -1, prevY = -1;
            for (QualityResult r : pts) {
                int px = xPixel(r.cameraPerPixel(), left, right), py = yPixel(r.psnr(), top, bottom);
                g.fillOval(px - 3, py - 3, 7, 7);
                if (prevX >= 0) g.drawLine(prevX, prevY, px, py);
                prevX = px;
                prevY = py;
            }
            g.fillRect(right - 150, legendY - 8, 10, 10);
            g.setColor(Color.BLACK);
            g.drawString(line.getKey(), right - 135, legendY + 1);
            legendY += 14;
        }
        g.setStroke(new BasicStroke(1f));
    }

    private static int xPixel(double x, int left, int right) {
        double t = (log2(Math.max(X_MIN, Math.min(X_MAX, x))) - log2(X_MIN)) / (log2(X_MAX) - log2(X_MIN));
        return (int) Math.round(left + t * (right - left));
    }

    private static int yPixel(double y, int top, int bottom) {
        double c = Double.isInfinite(y) ? Y_MAX : Math.max(Y_MIN, Math.min(Y_MAX, y));
        return (int) Math.round(bottom - (c - Y_MIN) / (Y_MAX - Y_MIN) * (bottom - top));
    }

    private static double log2(double v) {
        return Math.log(v) / Math.log(2);
    }
}
