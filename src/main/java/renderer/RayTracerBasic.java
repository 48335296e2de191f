package renderer;

import geometries.Bvh;
import geometries.GeometryLists;
import geometries.Intersectable;
import lighting.LightQueries;
import lighting.LightSource;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * The Whitted tracer of the course (named {@link SimpleRayTracer} from 2024–25 on): emission,
 * ambient light scaled by the material's {@code kA}, Phong diffuse and specular per
 * light, shadows attenuated by the product of kT of the occluders up to the light, and mirror
 * reflection and (direction-keeping) refraction recursing to {@link #MAX_CALC_COLOR_LEVEL} while
 * the accumulated coefficient stays above {@link #MIN_CALC_COLOR_K}. A material with an index of
 * refraction other than 1 ({@link Material#ior}) bends its transmitted rays instead (Snell's law,
 * total internal reflection, Fresnel).
 *
 * <p>Extensions, each one fluent line and off by default in effect:
 * <ul>
 * <li>{@link #setBvh(boolean)}: the bounding volume hierarchy (on by default; off gives the same
 * image, slower);</li>
 * <li>glossy reflection and diffuse glass, when a material has a non-zero spread: each such
 * bounce traces a beam of {@link #setBeamSize(int)} rays; see {@link #setBeamSize(int)} for the
 * cost policy;</li>
 * <li>soft shadows, when a light has a non-zero radius: {@link #setShadowSamples(int)} shadow
 * rays to points of the light's disk, their transparencies averaged.</li>
 * </ul>
 * Settings are made before rendering; the tracer is then only read, by any number of threads.
 *
 * <p>This class is the course's face: its settings and {@link #traceRay(Ray)}. The shading itself
 * is a package-private {@code WhittedShader}, made by each render's preparation from the scene and
 * these settings and shared by the render's workers.
 */
public class RayTracerBasic extends RayTracerBase {
    /** The recursion depth limit of reflection and refraction. */
    public static final int MAX_CALC_COLOR_LEVEL = WhittedShader.MAX_CALC_COLOR_LEVEL;
    /** Below this accumulated coefficient (in every channel) a contribution is not traced. */
    public static final double MIN_CALC_COLOR_K = WhittedShader.MIN_CALC_COLOR_K;
    /** Rays per glossy or diffuse-glass beam when none is set ({@link #setBeamSize(int)}). */
    public static final int DEFAULT_BEAM_SIZE = WhittedShader.DEFAULT_BEAM_SIZE;
    /** Shadow rays toward a light with a radius when none is set ({@link #setShadowSamples(int)}). */
    public static final int DEFAULT_SHADOW_SAMPLES = WhittedShader.DEFAULT_SHADOW_SAMPLES;

    private boolean useBvh = true;
    private int beamSize = DEFAULT_BEAM_SIZE;
    private int shadowSamples = DEFAULT_SHADOW_SAMPLES;

    /**
     * The shading over the scene as the last prepare() took it (the BVH or the flat list, the
     * lights, these settings); null before the first.
     */
    private volatile WhittedShader shader;
    /** Scratch for calls of {@link #traceRay(Ray)} made outside a render, one per calling thread. */
    private final ThreadLocal<TraceContext> directContexts =
            ThreadLocal.withInitial(this::newContext);

    /**
     * A tracer with the defaults: the BVH on, beams of 16 rays, 16 shadow samples for lights with
     * a radius.
     *
     * @param scene the scene to trace; its BVH is built when a render starts
     */
    public RayTracerBasic(Scene scene) {
        super(scene);
    }

    /**
     * Switches the bounding volume hierarchy on (the default) or off, to compare: both give the
     * same image.
     *
     * @param on whether closest-hit and shadow queries go through the BVH
     * @return this tracer, for chaining
     */
    public RayTracerBasic setBvh(boolean on) {
        this.useBvh = on;
        forgetPreparation();
        return this;
    }

    /**
     * The number of rays in a glossy-reflection or diffuse-glass beam (default 16).
     * <p>Cost policy: the first glossy or diffuse-glass bounce on the way from the camera traces
     * the full beam; every bounce below a beam traces one ray (drawn from the sample's own random
     * stream). The cost per camera sample thus grows like {@code beamSize × depth}, not
     * {@code beamSize^depth}, and as the beam grows the deeper bounces are averaged over more
     * parents, so the image converges to the same result.
     *
     * @param rays rays per beam, ≥ 1
     * @return this tracer, for chaining
     * @throws IllegalArgumentException when {@code rays < 1}
     */
    public RayTracerBasic setBeamSize(int rays) {
        this.beamSize = WhittedShader.requireBeamSize(rays);
        forgetPreparation();
        return this;
    }

    /**
     * The number of shadow rays toward a light with a radius (default 16); lights of radius 0 always
     * use one.
     *
     * @param samples shadow rays per light with a radius and per shaded point, ≥ 1
     * @return this tracer, for chaining
     * @throws IllegalArgumentException when {@code samples < 1}
     */
    public RayTracerBasic setShadowSamples(int samples) {
        this.shadowSamples = WhittedShader.requireShadowSamples(samples);
        forgetPreparation();
        return this;
    }

    /** @return whether queries go through the bounding volume hierarchy */
    public boolean isBvh() {
        return useBvh;
    }

    /** @return rays per glossy or diffuse-glass beam */
    public int getBeamSize() {
        return beamSize;
    }

    /** @return shadow rays toward a light with a radius */
    public int getShadowSamples() {
        return shadowSamples;
    }

    /**
     * Snapshots the scene for tracing: checks the nesting of its geometries
     * ({@link geometries.Geometries#MAX_NESTING_DEPTH}) and every light's settings (before any
     * worker starts, so a bad scene fails the render at once with its message) and builds the BVH, or reuses the
     * one an earlier render built over the same, unchanged shapes ({@link Bvh#of}).
     */
    @Override
    synchronized PreparedTracer prepare() {
        GeometryLists.requireNestingWithinLimit(scene.geometries); // the flat walk recurses once per level
        for (LightSource light : scene.lights) LightQueries.validate(light);
        Intersectable world = useBvh ? Bvh.of(scene.geometries) : scene.geometries;
        WhittedShader prepared = new WhittedShader(scene.background, scene.ambientLight.getIntensity(), world, scene.lights.toArray(new LightSource[0]), beamSize, shadowSamples);
        shader = prepared;
        return prepared;
    }

    @Override
    TraceContext newContext() {
        return new TraceContext(MAX_CALC_COLOR_LEVEL, MIN_CALC_COLOR_K);
    }

    @Override
    void requireRayBudget(SamplerPlan sampling) {
        RayBudget.require(sampling.mode(), sampling.maxSamplesPerPixel(), beamSize, shadowSamples,
                SceneStamp.lightsForBudget(sceneParts()));
    }

    /**
     * @return which walk the BVH takes (vector or scalar, {@link Bvh#walkDescription()}), after a
     *         comma: the last prepared tree's, once a render prepared one; "" without the BVH
     */
    @Override
    String walk() {
        WhittedShader prepared = shader;
        return useBvh ? ", " + (prepared != null ? prepared.walk() : Bvh.walkDescription()) : "";
    }

    @Override
    String describe() {
        return "bvh " + (useBvh ? "on" : "off") + ", beam " + beamSize + ", shadow samples " + shadowSamples;
    }

    /**
     * The colour seen along {@code ray}, for use outside a render (a render calls the tracer
     * through its own loop). Random choices (glossy beams, soft shadows) are keyed by the ray
     * itself, so the same ray always gives the same colour and different rays are independent.
     */
    @Override
    public Color traceRay(Ray ray) {
        prepareIfChanged();
        TraceContext ctx = directContexts.get();
        ctx.beginPixel(-1, -1);
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        ctx.random.reset(Double.doubleToLongBits(h.getX()) * 31 + Double.doubleToLongBits(h.getY()),
                Double.hashCode(h.getZ()), Double.hashCode(d.getX()) * 31 + Double.hashCode(d.getY()), Double.hashCode(d.getZ()));
        ctx.cameraRay().ray(h.getX(), h.getY(), h.getZ(), d.getX(), d.getY(), d.getZ());
        return shader.traceRay(ctx).toColor();
    }
}
