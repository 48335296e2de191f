package bench;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.function.Supplier;
import java.util.regex.Pattern;

import javax.imageio.ImageIO;

import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.RenderStats;
import scene.Scene;
import scene.samples.GlossyScene;
import scene.samples.Showcase;
import scene.samples.TeapotScene;

/**
 * The quality benchmark (see BENCHMARKS.md, "Image quality per ray"): renders the showcase, the
 * glossy scene and the teapot with each anti-aliasing mode and setting, compares every image with
 * a RANDOM 16×16 render of the same scene (the reference, cached under {@code target/quality/}),
 * and prints a Markdown table (PSNR, share of pixels off by more than 8/255, camera rays and all
 * rays per pixel, render time) and draws PSNR against camera rays per pixel as a PNG.
 *
 * <p>Options: {@code --side N} (image side, default 300), {@code --only a,b}, {@code --threads N}
 * (default 2), {@code --plot FILE} (default docs/quality-plot.png), {@code --out FILE},
 * {@code --match REGEX} (only the settings whose name matches), {@code --fresh} (re-render the
 * references), {@code --images} (write every render to target/quality/), {@code --quick} (side 60,
 * for a smoke run).
 */
public final class QualityBenchmark {
    /** The reference: jittered 16×16 per pixel. */
    static final int REFERENCE_GRID = 16;
    /** A pixel counts as off when some 8-bit channel differs from the reference by more than this. */
    static final int OFF_LEVEL = 8;
    private static final Path CACHE = Path.of("target", "quality");

    private final int side;
    private final int threads;
    private final boolean fresh;
    private final PrintStream log = System.err;

    private final Pattern match;

    private final boolean images;

    private QualityBenchmark(int side, int threads, boolean fresh, Pattern match, boolean images) {
        this.images = images;
        this.match = match;
        this.side = side;
        this.threads = threads;
        this.fresh = fresh;
    }

    /** The scenes: how to build each and its camera with a tracer. */
    private record SceneSpec(String key, Supplier<Scene> scene, Function<Scene, Camera.Builder> camera) {
    }

    /**
     * The depth-of-field panel's lens: focal distance 900 (the showcase's centre, 906 from the
     * camera, stays sharp), aperture radius 12 (the floor in front and the back wall blur over
     * several pixels at 200×200); the scene file's {@code <depth-of-field focal-distance="900"
     * aperture="12"/>}.
     */
    static final double DOF_FOCAL_DISTANCE = 900, DOF_APERTURE = 12;

    private static final List<SceneSpec> SCENES = List.of(
            new SceneSpec("showcase", Showcase::create, Configurations::showcaseCamera),
            // Its reference is RANDOM 16×16 with the same lens: 256 camera rays per pixel, each its own lens point.
            new SceneSpec("showcase-dof", Showcase::create,
                    s -> Configurations.showcaseCamera(s).setDepthOfField(DOF_FOCAL_DISTANCE, DOF_APERTURE)),
            new SceneSpec("glossy", GlossyScene::create, s -> GlossyScene.camera().setRayTracer(new RayTracerBasic(s))),
            new SceneSpec("teapot", TeapotScene::create, s -> TeapotScene.camera().setRayTracer(new RayTracerBasic(s))));

    /** The settings measured on every scene, in plot-line order. */
    static List<QualityCase> cases(String scene) {
        if (scene.endsWith("-dof")) return lensCases(scene);
        List<QualityCase> list = new ArrayList<>();
        list.add(new QualityCase(scene, "NONE", "NONE", b -> b.setAntiAliasing(AntiAliasing.NONE)));
        list.add(new QualityCase(scene, "CORNERS", "CORNERS", b -> b.setAntiAliasing(AntiAliasing.CORNERS)));
        for (int n : new int[] { 2, 3, 4, 6, 8 })
            list.add(new QualityCase(scene, "RANDOM", "RANDOM " + n + "×" + n, b -> b.setAntiAliasing(AntiAliasing.RANDOM, n, n)));
        for (int depth : ADAPTIVE_DEPTHS)
            for (double t : ADAPTIVE_THRESHOLDS)
                list.add(new QualityCase(scene, "ADAPTIVE depth " + depth,
                        "ADAPTIVE depth " + depth + ", threshold " + fmt(t),
                        b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(depth, t)));
        list.add(new QualityCase(scene, "ADAPTIVE default", "ADAPTIVE (defaults)", b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE)));
        return list;
    }

    /**
     * The settings measured with a lens: NONE's lens samples (the default 16 among them), CORNERS,
     * RANDOM's grids (each sample its own lens point) and ADAPTIVE at depth 3 (its default) over
     * the thresholds, then its defaults.
     */
    static List<QualityCase> lensCases(String scene) {
        List<QualityCase> list = new ArrayList<>();
        for (int n : new int[] { 4, 8, 16, 32, 64 })
            list.add(new QualityCase(scene, "NONE + lens", "NONE, " + n + " lens samples",
                    b -> b.setAntiAliasing(AntiAliasing.NONE).setDepthOfFieldSamples(n)));
        list.add(new QualityCase(scene, "CORNERS", "CORNERS", b -> b.setAntiAliasing(AntiAliasing.CORNERS)));
        for (int n : new int[] { 2, 3, 4, 6, 8 })
            list.add(new QualityCase(scene, "RANDOM", "RANDOM " + n + "×" + n, b -> b.setAntiAliasing(AntiAliasing.RANDOM, n, n)));
        for (double t : LENS_ADAPTIVE_THRESHOLDS)
            list.add(new QualityCase(scene, "ADAPTIVE depth 3", "ADAPTIVE depth 3, threshold " + fmt(t),
                    b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, t)));
        list.add(new QualityCase(scene, "ADAPTIVE default", "ADAPTIVE (defaults)", b -> b.setAntiAliasing(AntiAliasing.ADAPTIVE)));
        return list;
    }

    static final double[] LENS_ADAPTIVE_THRESHOLDS = { 2, 4, 6, 8, 12, 16 };

    static final int[] ADAPTIVE_DEPTHS = { 2, 3, 4 };
    static final double[] ADAPTIVE_THRESHOLDS = { 2, 4, 6, 8, 12, 16 };

    public static void main(String[] args) throws IOException {
        int side = 300, threads = 2;
        boolean fresh = false, images = false;
        Set<String> only = Set.of("showcase", "glossy", "teapot", "showcase-dof");
        Path plot = Path.of("docs", "quality-plot.png");
        Path out = null;
        Pattern match = null;
        for (int i = 0; i < args.length; ++i) {
            switch (args[i]) {
                case "--side" -> side = Integer.parseInt(args[++i]);
                case "--threads" -> threads = Integer.parseInt(args[++i]);
                case "--only" -> only = Set.of(args[++i].split(","));
                case "--plot" -> plot = Path.of(args[++i]);
                case "--out" -> out = Path.of(args[++i]);
                case "--match" -> match = Pattern.compile(args[++i]);
                case "--fresh" -> fresh = true;
                case "--images" -> images = true;
                case "--quick" -> side = 60;
                default -> {
                    System.err.println("bench.QualityBenchmark: unknown option " + args[i]
                            + " (options: --side N --threads N --only a,b (showcase, glossy, teapot, showcase-dof) --match REGEX --plot FILE --out FILE --fresh --images --quick)");
                    System.exit(2);
                }
            }
        }
        QualityBenchmark bench = new QualityBenchmark(side, threads, fresh, match, images);
        Map<String, List<QualityResult>> results = new LinkedHashMap<>();
        for (SceneSpec spec : SCENES)
            if (only.contains(spec.key())) results.put(spec.key(), bench.measure(spec));
        String table = bench.table(String.join(" ", args), results);
        System.out.print(table);
        if (out != null) {
            Files.writeString(out, table);
            System.err.println("wrote " + out);
        }
        Path parent = plot.toAbsolutePath().getParent();
        if (parent != null) Files.createDirectories(parent);
        ImageIO.write(QualityPlot.draw(results, side), "png", plot.toFile());
        System.err.println("wrote " + plot);
    }

    private List<QualityResult> measure(SceneSpec spec) throws IOException {
        Scene scene = spec.scene().get();
        int[] reference = reference(spec, scene);
        List<QualityResult> list = new ArrayList<>();
        for (QualityCase c : cases(spec.key())) {
            if (match != null && !match.matcher(c.setting()).find()) continue;
            render(spec, scene, c.sampling(), Math.max(16, side / 4), null); // warm-up
            int[] pixels = new int[side * side];
            RenderStats s = render(spec, scene, c.sampling(), side, pixels);
            if (images) writePng(pixels, CACHE.resolve(spec.key() + "-" + c.setting().replaceAll("[^A-Za-z0-9]+", "_") + ".png"));
            double pixelsCount = (double) side * side;
            QualityResult r = new QualityResult(c, psnr(pixels, reference), offShare(pixels, reference),
                    s.cameraRays() / pixelsCount, s.totalRays() / pixelsCount, s.seconds());
            log.printf(Locale.ROOT, "%s %s: %.2f dB, %.2f%% off, %.2f camera / %.1f rays per px, %.3f s%n", spec.key(),
                    c.setting(), r.psnr(), 100 * r.offShare(), r.cameraPerPixel(), r.raysPerPixel(), r.seconds());
            list.add(r);
        }
        return list;
    }

    /** The RANDOM 16×16 render of the scene, from the cache when there. */
    private int[] reference(SceneSpec spec, Scene scene) throws IOException {
        Path file = CACHE.resolve("reference-" + spec.key() + "-" + side + ".png");
        int[] pixels = new int[side * side];
        if (!fresh && Files.exists(file)) {
            BufferedImage img = ImageIO.read(file.toFile());
            if (img.getWidth() == side && img.getHeight() == side) {
                img.getRGB(0, 0, side, side, pixels, 0, side);
                log.println("reference " + file + " (cached; --fresh re-renders it)");
                return pixels;
            }
        }
        log.printf(Locale.ROOT, "rendering the reference of %s at %d×%d, RANDOM %d×%d...%n", spec.key(), side, side,
                REFERENCE_GRID, REFERENCE_GRID);
        RenderStats s = render(spec, scene, b -> b.setAntiAliasing(AntiAliasing.RANDOM, REFERENCE_GRID, REFERENCE_GRID),
                side, pixels);
        log.printf(Locale.ROOT, "  %.1f s%n", s.seconds());
        writePng(pixels, file);
        return pixels;
    }

    private void writePng(int[] pixels, Path file) throws IOException {
        BufferedImage img = new BufferedImage(side, side, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, side, side, pixels, 0, side);
        Files.createDirectories(file.toAbsolutePath().getParent());
        ImageIO.write(img, "png", file.toFile());
    }

    private RenderStats render(SceneSpec spec, Scene scene, QualityCase.Sampling sampling, int n, int[] pixels) {
        ImageWriter writer = new ImageWriter("quality/" + spec.key(), n, n);
        Camera camera = sampling.apply(spec.camera().apply(scene)).setImageWriter(writer)
                .setMultithreading(threads).setSummary(false).build();
        RenderStats stats = camera.render();
        if (pixels != null)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) pixels[y * n + x] = writer.getRgb(x, y);
        return stats;
    }

    /** PSNR over the three 8-bit channels of every pixel, in dB. */
    static double psnr(int[] a, int[] b) {
        double sum = 0;
        for (int i = 0; i < a.length; ++i)
            for (int shift = 0; shift <= 16; shift += 8) {
                int d = ((a[i] >> shift) & 0xff) - ((b[i] >> shift) & 0xff);
                sum += d * d;
            }
        double mse = sum / (3.0 * a.length);
        return 10 * Math.log10(255.0 * 255.0 / mse);
    }

    /** The share of pixels with some channel off by more than {@link #OFF_LEVEL}. */
    static double offShare(int[] a, int[] b) {
        int off = 0;
        for (int i = 0; i < a.length; ++i)
            for (int shift = 0; shift <= 16; shift += 8)
                if (Math.abs(((a[i] >> shift) & 0xff) - ((b[i] >> shift) & 0xff)) > OFF_LEVEL) {
                    ++off;
                    break;
                }
        return off / (double) a.length;
    }

    private String table(String commandLine, Map<String, List<QualityResult>> results) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "Quality against RANDOM %d×%d of the same scene, %d×%d, %d threads (`%s`)%n%n",
                REFERENCE_GRID, REFERENCE_GRID, side, side, threads, commandLine));
        sb.append("| scene | setting | PSNR dB | pixels off > 8/255 | camera rays/px | all rays/px | render s |\n");
        sb.append("|---|---|--:|--:|--:|--:|--:|\n");
        for (List<QualityResult> list : results.values())
            for (QualityResult r : list)
                sb.append(String.format(Locale.ROOT, "| %s | %s | %.2f | %.2f %% | %.2f | %.1f | %.3f |%n", r.c().scene(),
                        r.c().setting(), r.psnr(), 100 * r.offShare(), r.cameraPerPixel(), r.raysPerPixel(), r.seconds()));
        return sb.toString();
    }

    static String fmt(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
