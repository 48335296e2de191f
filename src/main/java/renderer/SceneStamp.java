package renderer;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Collections;
import java.util.ConcurrentModificationException;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;

import geometries.Geometries;
import geometries.Geometry;
import geometries.GeometryLists;
import geometries.Intersectable;
import lighting.AmbientLight;
import lighting.LightQueries;
import lighting.LightSource;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Materials;

/**
 * What a render saw of its scene when it started: the geometry list and how often it and the
 * lists within it were added to, the light list and its lights, and everything the shading reads
 * besides (the background, the ambient light, each geometry's material and emission, each
 * light's settings). A scene must not change while it renders (the workers read it, and a tracer
 * shared by two renders is prepared again by the second); the render compares at its end, and a
 * change fails it with one message instead of an image of two states. The comparison walks the
 * scene once at each end of the render, never per ray or per tile.
 *
 * <p>The scene is read through its tracer ({@link RayTracerBase#sceneParts()}), the one class of
 * the renderer that holds it because the course says so: this class knows the parts, not the
 * course's {@code Scene}.
 *
 * @param tracer      the tracer whose scene is rendered, read again at the end
 * @param start       the scene's parts at the start
 * @param changes     {@link GeometryLists#changeCount} at the start
 * @param lights      the lights in its light list at the start
 * @param surfaces    the fingerprint of every geometry's material and emission at the start ({@link #surfaces})
 * @param lightStamps each light's {@link LightQueries#settingsStamp} at the start, in the order of {@code lights}
 */
record SceneStamp(RayTracerBase tracer, Parts start, long changes, LightSource[] lights, Surfaces surfaces,
                  long[] lightStamps) {
    /**
     * The parts of a scene a render reads, as they are at one moment: compared by identity (a
     * {@link Color} and an ambient light are immutable; the lists are compared by their contents
     * besides).
     *
     * @param name       the scene's name, for messages
     * @param geometries its geometry list
     * @param lights     its light list
     * @param background its background
     * @param ambient    its ambient light
     */
    record Parts(String name, Geometries geometries, List<LightSource> lights, Color background, AmbientLight ambient) {
    }

    /**
     * @throws ConcurrentModificationException when the light list changes while it is read
     */
    static SceneStamp of(RayTracerBase tracer, String image) {
        Parts start = tracer.sceneParts();
        try {
            LightSource[] lights = start.lights.toArray(new LightSource[0]);
            return new SceneStamp(tracer, start, GeometryLists.changeCount(start.geometries), lights, Surfaces.of(start.geometries),
                    settingsStamps(lights));
        } catch (RuntimeException e) { // a list read while another thread adds to it
            throw changed(start.name, image, "it was being changed as the render started", e);
        }
    }

    /**
     * The scene's lights as the ray budget counts them, when a camera is built on the scene or
     * starts to render it: a copy of its light list. The list is the course's public field, of
     * any kind, and not safe to read while another thread adds to it; a read that fails that way
     * (an index out of its bounds, a null node) fails with the scene-change message instead.
     *
     * @throws ConcurrentModificationException naming the scene, when the list could not be read
     */
    static List<LightSource> lightsForBudget(Parts scene) {
        try {
            return Arrays.asList(scene.lights.toArray(new LightSource[0])); // not List.of: a null light fails where it did
        } catch (RuntimeException e) { // a list read while another thread adds to it
            throw new ConcurrentModificationException("the scene '" + scene.name + "' changed while its lights were counted"
                    + " for the ray budget (a camera built on it, or a render starting): its light list was being changed"
                    + " as it was read (a scene must not change while a camera is built on it or renders it; build and"
                    + " render when it is complete)", e);
        }
    }

    /**
     * Checks that the scene is as it was.
     *
     * @param image   the image rendered, for the message
     * @param failure what the render failed with, if it did (kept as the cause), or null
     * @throws ConcurrentModificationException naming the scene, the image and what changed
     */
    void requireUnchanged(String image, Throwable failure) {
        String what;
        try {
            what = change();
        } catch (RuntimeException e) {
            what = "it was being changed as the render ended";
        }
        if (what != null) throw changed(tracer.sceneParts().name, image, what, failure);
    }

    /**
     * What a direct {@code traceRay} call asks before each ray, so kept cheap (no walk over the
     * shapes): whether the tracer's preparation is out of date.
     *
     * @return whether the scene is no longer as it was: a list replaced or added to (nested
     *         lists included), a light added, removed or replaced
     */
    boolean changed() {
        return structuralChange() != null;
    }

    /** @return what changed, in words, or null */
    private String change() {
        String structural = structuralChange();
        if (structural != null) return structural;
        Parts now = tracer.sceneParts();
        if (now.background != start.background) return "its background was replaced (setBackground)";
        if (now.ambient != start.ambient) return "its ambient light was replaced (setAmbientLight)";
        Surfaces surfacesNow = Surfaces.of(start.geometries);
        if (surfacesNow.materials != surfaces.materials)
            return "a material of its geometries changed (a Material setter such as setKd, a field, or setMaterial)";
        if (surfacesNow.emissions != surfaces.emissions) return "the emission of one of its geometries changed (setEmission)";
        for (int i = 0; i < lights.length; ++i)
            if (LightQueries.settingsStamp(lights[i]) != lightStamps[i])
                return "the settings of its light #" + i + " changed (" + lights[i].getClass().getSimpleName() + ")";
        return null;
    }

    private static long[] settingsStamps(LightSource[] lights) {
        long[] stamps = new long[lights.length];
        for (int i = 0; i < lights.length; ++i) stamps[i] = LightQueries.settingsStamp(lights[i]);
        return stamps;
    }

    /**
     * Fingerprints of what the shading reads from the geometries: every material's coefficients
     * and every emission, over each geometry in the nested lists (each list walked once, without
     * recursion: lists may nest deeper than the stack allows, see {@link Geometries#MAX_NESTING_DEPTH}).
     * Values, not identities, so that a field written directly (the course's public fields) is seen
     * as a setter is; in walk order, so that two geometries swapping materials is seen too.
     *
     * @param materials the fingerprint of the materials (their coefficients, shininess, spreads, index of refraction)
     * @param emissions the fingerprint of the emissions
     */
    record Surfaces(long materials, long emissions) {
        static Surfaces of(Geometries root) {
            long materials = 0, emissions = 0;
            Set<Geometries> seen = Collections.newSetFromMap(new IdentityHashMap<>());
            Deque<Geometries> todo = new ArrayDeque<>(List.of(root));
            while (!todo.isEmpty()) {
                Geometries list = todo.pop();
                if (!seen.add(list)) continue;
                for (Intersectable item : list.getItems()) {
                    if (item instanceof Geometries nested) todo.push(nested);
                    else if (item instanceof Geometry g) {
                        // the counts as well as the values: a change put back within the render still differs
                        materials = mix(mix(material(materials, g.getMaterial()), Materials.changes(g.getMaterial())),
                                GeometryLists.materialChanges(g));
                        Color e = g.getEmission();
                        emissions = mix(mix(mix(mix(emissions, e.getR()), e.getG()), e.getB()), GeometryLists.emissionChanges(g));
                    }
                }
            }
            return new Surfaces(materials, emissions);
        }

        private static long material(long stamp, Material m) {
            stamp = mix(mix(mix(mix(mix(stamp, m.kA), m.kD), m.kS), m.kT), m.kR);
            return mix(mix(mix(mix(stamp, m.nShininess), m.reflectionSpread), m.transmissionSpread), m.ior);
        }

        private static long mix(long stamp, Double3 k) {
            return mix(mix(mix(stamp, k.d1()), k.d2()), k.d3());
        }

        /** One step of a 64-bit multiply-and-add fingerprint over the bits of {@code value}. */
        private static long mix(long stamp, double value) {
            return (stamp ^ Double.doubleToLongBits(value)) * 0x9E3779B97F4A7C15L + 0x632BE59BD9B4E019L;
        }
    }

    /** The structural part of {@link #change()}: lists and lights added, removed or replaced. */
    private String structuralChange() {
        Parts now = tracer.sceneParts();
        if (now.geometries != start.geometries) return "its geometry list was replaced";
        long count = GeometryLists.changeCount(start.geometries);
        if (count != changes) return "its geometries were added to (" + (count - changes) + (count - changes == 1 ? " time)" : " times)");
        if (now.lights != start.lights) return "its light list was replaced";
        LightSource[] nowLights = start.lights.toArray(new LightSource[0]);
        if (nowLights.length != lights.length) return "its lights went from " + lights.length + " to " + nowLights.length;
        for (int i = 0; i < lights.length; ++i)
            if (nowLights[i] != lights[i]) return "its light #" + i + " was replaced";
        return null;
    }

    private static ConcurrentModificationException changed(String scene, String image, String what, Throwable cause) {
        return new ConcurrentModificationException("the scene '" + scene + "' changed during the render of " + image
                + ": " + what + " (a scene must not change while it renders; render it again when it is complete)",
                cause);
    }
}
