package renderer;

import java.io.PrintStream;

/**
 * What a camera renders with besides its image: what it sees, how it samples and runs, and the
 * tracer that colours each camera ray. {@link #check} holds a builder's settings to the ray budget
 * together, as {@link Camera.Builder#build()} does before it allocates an image; a camera, a
 * region renderer and a builder's description are made from what it returns. The values do not
 * change; the tracer stays mutable, so a render holds it to the budget again.
 *
 * @param view      the location, frame, view plane, resolution and lens
 * @param sampling  the anti-aliasing mode and its parameters, the lens samples and the seed
 * @param execution the threads, the tile size (the sampling plan's), progress and output
 * @param tracer    the tracer, over its scene
 */
record RenderSetup(View view, Sampling sampling, Execution execution, RayTracerBase tracer) {
    /**
     * The setup of a builder's settings, once its view is made.
     *
     * @param threads      as set: -1 and -2 (all cores) become the core count here
     * @param progressStep percent of the pixels between progress lines; 0: none
     * @param output       where the progress lines, and the camera's summary and write lines, go
     * @throws IllegalArgumentException when a pixel would take more rays than the budget, naming the settings
     */
    static RenderSetup check(View view, Sampling sampling, RayTracerBase tracer, int threads, double progressStep,
                             PrintStream output) {
        SamplerPlan plan = withinBudget(sampling, view.lens(), tracer);
        Execution execution = new Execution(Execution.resolveThreads(threads), plan.tileSize(), progressStep, output);
        return new RenderSetup(view, sampling, execution, tracer);
    }

    /**
     * The sampling's plan under {@code lens}, its ray budget held with {@code tracer}: the budget
     * needs no view, so a scene file's settings are checked by it before they have one.
     *
     * @throws IllegalArgumentException when a pixel would take more rays than the budget, naming the settings
     */
    static SamplerPlan withinBudget(Sampling sampling, View.Lens lens, RayTracerBase tracer) {
        SamplerPlan plan = sampling.plan(!lens.isPinhole());
        tracer.requireRayBudget(plan);
        return plan;
    }

    /** @return the render loop of this setup, writing {@code image} (null for a loop that renders regions only) */
    RenderLoop loop(ImageWriter image) {
        return new RenderLoop(view, sampling, execution, tracer, image);
    }

    /** @return the sampling settings, the tracer's and the seed in words, for summaries and benchmark tables */
    String describe() {
        return sampling.describe(view.lens()) + ", " + tracer.describe() + ", seed " + sampling.seed();
    }
}
