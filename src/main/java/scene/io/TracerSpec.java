package scene.io;

import java.util.StringJoiner;

import renderer.RayTracerBasic;
import scene.Scene;

/**
 * The tracer's extensions, as {@link RayTracerBasic}'s setters take them.
 *
 * <p>A part of {@link RenderSettings}: a component is null where it states nothing.
 *
 * @param bvh           whether the tracer uses the bounding volume hierarchy
 * @param beamSize      rays per glossy or diffuse-glass beam
 * @param shadowSamples shadow rays toward a light with a radius
 * @serial exclude
 */
public record TracerSpec(Boolean bvh, Integer beamSize, Integer shadowSamples) implements java.io.Serializable {
    static final TracerSpec NONE = new TracerSpec(null, null, null);

    TracerSpec then(TracerSpec later) {
        return new TracerSpec(Stated.or(later.bvh, bvh), Stated.or(later.beamSize, beamSize), Stated.or(later.shadowSamples, shadowSamples));
    }

    /** @return a new tracer for {@code scene} with the stated extensions, each through its own setter */
    RayTracerBasic newTracer(Scene scene) {
        RayTracerBasic tracer = new RayTracerBasic(scene);
        if (bvh != null) tracer.setBvh(bvh);
        if (beamSize != null) tracer.setBeamSize(beamSize);
        if (shadowSamples != null) tracer.setShadowSamples(shadowSamples);
        return tracer;
    }

    void describe(StringJoiner out) {
        Stated.add(out, "bvh", bvh);
        Stated.add(out, "beamSize", beamSize);
        Stated.add(out, "shadowSamples", shadowSamples);
    }
}
