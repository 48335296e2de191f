package renderer;

import java.util.Objects;

/**
 * The values a camera renders with, read from its package-private parts, for tests of other
 * packages to compare cameras by value (with {@code isEqualTo}) instead of by
 * {@link Camera#describe()}'s words: the sampling (its mode, every mode's parameters, the lens
 * samples and the seed), the lens, and the tracer's extensions. The view's position and the
 * image are left out: the tests that use this read them through the camera's public getters.
 *
 * @param sampling the camera's sampling, whole: the parameters of the modes it does not use too
 * @param lens     the camera's lens ({@link View.Lens#PINHOLE} without depth of field)
 * @param tracer   the settings of its {@link RayTracerBasic}
 */
public record CameraValues(Sampling sampling, View.Lens lens, Tracer tracer) {
    /**
     * A {@link RayTracerBasic}'s extensions, as its getters give them.
     *
     * @param bvh           whether it walks the bounding volume hierarchy
     * @param beamSize      rays per glossy or diffuse-glass beam
     * @param shadowSamples shadow rays toward a light with a radius
     */
    public record Tracer(boolean bvh, int beamSize, int shadowSamples) {
        /** The tracer a camera gets when its settings are not changed: BVH on, 16 and 16. */
        public static final Tracer DEFAULT = new Tracer(true, RayTracerBasic.DEFAULT_BEAM_SIZE,
                RayTracerBasic.DEFAULT_SHADOW_SAMPLES);
    }

    /**
     * @param camera a built camera whose tracer is a {@link RayTracerBasic}
     * @return the values it renders with
     * @throws IllegalArgumentException for a tracer of another kind, whose settings this does not know, naming it
     */
    public static CameraValues of(Camera camera) {
        Objects.requireNonNull(camera, "camera");
        if (!(camera.rayTracer() instanceof RayTracerBasic basic))
            throw new IllegalArgumentException("CameraValues reads a RayTracerBasic's settings; the camera's tracer is a "
                    + camera.rayTracer().getClass().getName());
        return new CameraValues(camera.sampling(), camera.view().lens(),
                new Tracer(basic.isBvh(), basic.getBeamSize(), basic.getShadowSamples()));
    }
}
