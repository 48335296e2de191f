package renderer;

import java.util.function.Supplier;

import primitives.Rgb;

/**
 * {@link AntiAliasing#NONE}: rays through the pixel centre: one, or with depth of field one per
 * lens sample. The lens points of a pixel are stratified ({@link SobolPoints} under the pixel's
 * seed: 16 samples cover the lens as a jittered 4×4 grid would), not independent: measured on the
 * showcase with a lens, 16 stratified samples come as close to the 256-sample reference as 64
 * independent ones did (40.28 dB against 40.22; BENCHMARKS.md, depth of field). Each sample's
 * tracer numbers still come from its own stream, (seed, pixel, sample).
 */
final class CenterSampler extends PixelSampler {
    private final int samples;
    private final Rgb pixel = new Rgb();

    private CenterSampler(Plan plan, Estimator estimator) {
        super(plan.seed, plan.lens, estimator);
        this.samples = plan.samples;
    }

    /**
     * @param seed    the render's seed
     * @param lens    whether the view has a lens
     * @param samples camera rays per pixel: the lens samples with a lens, else 1
     */
    record Plan(long seed, boolean lens, int samples) implements SamplerPlan {
        /** A pinhole's one ray per pixel, or with a lens {@code lensSamples}. */
        static Plan of(long seed, boolean lens, int lensSamples) {
            return new Plan(seed, lens, lens ? lensSamples : 1);
        }

        @Override
        public AntiAliasing mode() {
            return AntiAliasing.NONE;
        }

        @Override
        public long maxSamplesPerPixel() {
            return samples;
        }

        @Override
        public int tileSize() {
            return 16;
        }

        @Override
        public Supplier<PixelSampler> samplers(Estimator estimator, int tileSize, int x0, int y0, int x1, int y1) {
            return () -> new CenterSampler(this, estimator);
        }

        @Override
        public String describe() {
            return "NONE";
        }

        @Override
        public String lensSamples() {
            return lens ? " x" + samples : "";
        }
    }

    @Override
    Rgb sample(int x, int y, TraceContext ctx) {
        if (!hasLens()) {
            ctx.random.reset(seed, x, y, 0);
            return trace(x + 0.5, y + 0.5, ctx);
        }
        int lensSeed = (int) pixelSeeds(x, y, ctx);
        Rgb sum = pixel.setZero();
        for (int s = 0; s < samples; ++s) {
            ctx.random.reset(seed, x, y, s);
            sum.add(trace(x + 0.5, y + 0.5, SobolPoints.x(s, lensSeed), SobolPoints.y(s, lensSeed), ctx));
        }
        return sum.reduce(samples);
    }
}
