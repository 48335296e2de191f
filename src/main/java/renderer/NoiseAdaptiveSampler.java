package renderer;

import java.util.function.Supplier;

import primitives.Rgb;

/**
 * {@link AntiAliasing#ADAPTIVE} with depth of field: samples a pixel until its estimated error is
 * small. The lattice sampler ({@link LatticeSampler}, ADAPTIVE without a lens) decides from the
 * spread of a few shared corners, which under a lens are each one random lens point: corners that
 * agree by chance stop a pixel whose blur is noisy. Here every sample is the pixel's own, a film
 * point and a lens point, both stratified ({@link SobolPoints}, two independent seeds per pixel),
 * and the pixel stops on the noise the samples show:
 * <ul>
 * <li>it takes {@link #FIRST} samples, then {@link #BATCH} at a time, up to 4^depth (as many as the
 * lattice has squares at the deepest level);</li>
 * <li>after each batch it estimates the standard error of its mean in each channel from the
 * samples' variance s² (values clamped to 255 as the image stores them), √(s² / n), and stops when
 * every channel's is at most the threshold (0..255 scale; the default 8).</li>
 * </ul>
 * The variance of independent samples overstates the error of stratified ones, so the test errs
 * towards more rays. A smooth region, sharp or blurred, costs {@link #FIRST} rays a pixel; edges in
 * focus and noisy blur take more. Every number depends on (seed, pixel, sample) alone, so the
 * image is the same on any thread count and in any region.
 */
final class NoiseAdaptiveSampler extends PixelSampler {
    /**
     * Samples before the first test. Fewer agree by chance too often (the lattice's failure):
     * measured on the showcase with a lens, a first test after 4 samples (then 4 at a time) gave
     * 39.3 dB for 10.8 camera rays a pixel, against 40.7 dB for 10.2 with 8 (BENCHMARKS.md,
     * depth of field).
     */
    static final int FIRST = 8;
    /** Samples between two tests: a test at every multiple of 8, so also at 16, 32 and 64, where the points are whole nets. */
    static final int BATCH = 8;

    private final int max;
    /** The squared standard error at which a pixel stops: the threshold², (0..255 scale)². */
    private final double tolerance2;
    private final Rgb pixel = new Rgb();

    private NoiseAdaptiveSampler(Plan plan, Estimator estimator) {
        super(plan.seed, true, estimator);
        this.max = (int) plan.maxSamplesPerPixel();
        this.tolerance2 = plan.threshold * plan.threshold;
    }

    /**
     * ADAPTIVE with a lens.
     *
     * @param seed      the render's seed
     * @param depth     ADAPTIVE's depth, 1..6: at most 4^depth samples a pixel
     * @param threshold the standard error of a pixel's mean at which it stops, 0..255 scale
     */
    record Plan(long seed, int depth, double threshold) implements SamplerPlan {
        @Override
        public AntiAliasing mode() {
            return AntiAliasing.ADAPTIVE;
        }

        /** @return 4^depth */
        @Override
        public long maxSamplesPerPixel() {
            return 1L << (2 * depth);
        }

        /** @return {@link #FIRST} (or 4^depth, when fewer): a smooth pixel stops at its first test */
        @Override
        public long leastSamplesPerPixel() {
            return Math.min(FIRST, maxSamplesPerPixel());
        }

        /** @return 16, as the other samplers that sample each pixel on its own */
        @Override
        public int tileSize() {
            return 16;
        }

        @Override
        public Supplier<PixelSampler> samplers(Estimator estimator, int tileSize, int x0, int y0, int x1, int y1) {
            return () -> new NoiseAdaptiveSampler(this, estimator);
        }

        @Override
        public String describe() {
            return LatticeSampler.Plan.adaptiveWords(depth, threshold);
        }
    }

    @Override
    Rgb sample(int x, int y, TraceContext ctx) {
        long seeds = pixelSeeds(x, y, ctx);
        int filmSeed = (int) (seeds >>> 32), lensSeed = (int) seeds;
        Rgb sum = pixel.setZero();
        // Sums and sums of squares of the clamped channels: the variance estimate's.
        double sr = 0, sg = 0, sb = 0, qr = 0, qg = 0, qb = 0;
        int n = 0;
        for (int next = Math.min(FIRST, max); ; next = Math.min(n + BATCH, max)) {
            for (; n < next; ++n) {
                ctx.random.reset(seed, x, y, n);
                Rgb c = trace(x + SobolPoints.x(n, filmSeed), y + SobolPoints.y(n, filmSeed),
                        SobolPoints.x(n, lensSeed), SobolPoints.y(n, lensSeed), ctx);
                sum.add(c);
                double r = Math.min(c.r(), 255), g = Math.min(c.g(), 255), b = Math.min(c.b(), 255);
                sr += r;
                sg += g;
                sb += b;
                qr += r * r;
                qg += g * g;
                qb += b * b;
            }
            if (n >= max || settled(n, sr, qr) && settled(n, sg, qg) && settled(n, sb, qb)) break;
        }
        return sum.reduce(n);
    }

    /**
     * Whether a channel's estimated standard error, from n samples of sum s and sum of squares q,
     * is within the tolerance: s² / n = (q − s²/n) / (n − 1) / n.
     */
    private boolean settled(int n, double s, double q) {
        double variance = Math.max(0, q - s * s / n) / (n - 1);
        return variance / n <= tolerance2;
    }
}
