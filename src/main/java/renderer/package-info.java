/**
 * The course's renderer: a scene test builds a {@link renderer.Camera} with
 * {@link renderer.Camera.Builder}, gives it a tracer ({@link renderer.RayTracerBasic}, named
 * {@link renderer.SimpleRayTracer} from 2024&ndash;25 on, or {@link renderer.RayTracerType}) and
 * an image ({@link renderer.ImageWriter}, or a resolution), renders and writes.
 *
 * <p>From a scene to a picture: {@link renderer.Camera} (built by {@link renderer.Camera.Builder},
 * which validates every setting), the tracer {@link renderer.RayTracerBasic}, the image
 * {@link renderer.ImageWriter} and what a render did, {@link renderer.RenderStats}. One render
 * loop serves every anti-aliasing mode, depth of field and thread count; every random number
 * comes from a stream keyed by (seed, pixel, sample), so images do not depend on threads.
 *
 * <p>Roles in this package, in the order a render meets them. Values flow one way: the limits and
 * defaults are defined in the values that own them ({@code Sampling}, {@code Execution},
 * {@code WhittedShader}) and the course classes re-export them ({@code Camera.MAX_SAMPLES_PER_PIXEL},
 * {@code RayTracerBasic.MIN_CALC_COLOR_K}); nothing below reads settings back from what is above
 * it. The one tie that runs up is the course's own: its tracers take a {@code scene.Scene}, and
 * only the classes the course names with it ({@code Camera}, the tracers, {@code RayTracerType})
 * import it; {@code SceneStamp} reads the scene's parts through its tracer, and
 * {@code WhittedShader} gets them as values when the tracer prepares.
 * <ul>
 * <li>The course's face, which scene tests call: {@code Camera} and its {@code Builder},
 * {@code ImageWriter}, {@code RayTracerBase} with {@code RayTracerBasic} (the Whitted tracer) and
 * {@code SimpleRayTracer}, {@code AntiAliasing}, {@code RayTracerType} (their engine members
 * package-private, reached from other packages through {@code CameraReports} and
 * {@code ImageWriters}), and what a render reports,
 * {@code RenderStats} (with the JDK Flight Recorder events {@code RenderEvent} and, for each PNG
 * written, {@code ImageWriteEvent}), and {@code WriteListener}, which a render listener implements
 * to hear of the camera's writes too.</li>
 * <li>The values a built camera is a facade over, each checked once, where it is made:
 * {@code View} (location, frame, view plane and resolution, lens: it makes camera rays from film
 * and lens coordinates), {@code Sampling} (the anti-aliasing mode and its parameters, lens samples,
 * seed: its {@code plan(lens)} is the one place the mode is decided, a {@code SamplerPlan} that
 * each sampler class defines beside it, giving the camera rays a pixel may take, the tile size and
 * each worker's sampler) and
 * {@code Execution} (threads, tile size, progress, output). {@code RayBudget} holds the rays of a
 * pixel to one limit. Each limit is a static rule there ({@code Execution.requireThreads},
 * {@code Sampling.Grid}, {@code View.Frame.along}, {@code RayBudget.require}, ...), which the
 * builder, the scene reader and the command line call alike; the three are public for those
 * callers and hidden from the course's Javadoc. Around them: a builder keeps its view settings in
 * a {@code ViewDraft} until {@code build()} makes the {@code View}; {@code RenderSetup} holds the
 * four values a camera renders with to the budget together; {@code CameraOutput} runs a camera's
 * render and write and tells of them (its listener, and the lines whose words are
 * {@code CameraReports}').</li>
 * <li>The loop: {@code RenderLoop(View, Sampling, Execution, tracer, image)} prepares the tracer
 * once per render and holds the {@code PreparedTracer} it returns; it cuts the image into tiles
 * that workers claim; each worker asks the tracer for its {@code TraceContext} (its scratch state,
 * never shared, with the pixel's ray limit) and the sampling's plan for a {@code PixelSampler} ({@code CenterSampler},
 * {@code GridSampler}, {@code LatticeSampler}, and for ADAPTIVE with a lens
 * {@code NoiseAdaptiveSampler}) over the pass's {@code Estimator} (the view's camera ray, traced by
 * the prepared tracer). The sampler positions the {@code SampleStream} of each sample, draws film
 * and lens coordinates (stratified ones from {@code SobolPoints}, under seeds keyed by the pixel)
 * and gets the sample's colour back as the estimator's return value: it knows neither the camera
 * nor the tracer.
 * {@code RegionRenderer} renders rectangles of an image for a distributed render;
 * {@code Progress} prints the progress lines; {@code SceneStamp} notices a scene changed during a
 * render.</li>
 * <li>The shading, package-private under {@code RayTracerBasic}: {@code WhittedShader} (Phong per
 * light, shadows, reflection and refraction by one ray or a beam, colours in one small mutable
 * {@code primitives.Rgb} per recursion level), {@code Transmittance} (the kT product of a shadow
 * ray's any-hit walk) and {@code ShadowCache} (the occluder a shadow ray found last, then the
 * light's {@code geometries.ShadowIndex}, then the walk).</li>
 * <li>Around the write: {@code InFlightFile} (a PNG is written to a temporary file and moved into
 * place) and {@code CallingTest} (the image name a 2024&ndash;25 flow takes from the JUnit test).</li>
 * </ul>
 *
 * <p>Invariants the tests hold: an image does not depend on the thread count or the tiling
 * ({@code DeterminismTest}, {@code RegionRendererTest}); the camera rays a pixel traces in the worst
 * case equal the budget's figure for every mode ({@code SamplingTest}); the render path allocates
 * at most 16 bytes per ray ({@code AllocationTest}); every image equals its committed reference
 * (the golden tests, {@code renderer.golden}).
 */
package renderer;
