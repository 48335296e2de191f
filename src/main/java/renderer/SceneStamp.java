package renderer;

import java.util.ConcurrentModificationException;
import java.util.List;

import geometries.Geometries;
import lighting.LightSource;
import scene.Scene;

/**
 * What a render saw of its scene when it started: the geometry list and how often it and the
 * lists within it were added to, the light list and its lights. A scene must not change while it
 * renders (the workers read it, and a tracer shared by two renders is prepared again by the
 * second); the render compares at its end, and a change fails it with one message instead of an
 * image of two states.
 *
 * @param scene      the scene rendered
 * @param geometries its geometry list at the start
 * @param changes    {@link Geometries#changeCount()} at the start
 * @param lightList  its light list at the start
 * @param lights     the lights in it at the start
 */
record SceneStamp(Scene scene, Geometries geometries, long changes, List<LightSource> lightList, LightSource[] lights) {
    /**
     * @throws ConcurrentModificationException when the light list changes while it is read
     */
    static SceneStamp of(Scene scene, String image) {
        try {
            List<LightSource> lightList = scene.lights;
            Geometries geometries = scene.geometries;
            return new SceneStamp(scene, geometries, geometries.changeCount(), lightList,
                    lightList.toArray(new LightSource[0]));
        } catch (RuntimeException e) { // a list read while another thread adds to it
            throw changed(scene, image, "it was being changed as the render started", e);
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
            what = "its lights were being changed as the render ended";
        }
        if (what != null) throw changed(scene, image, what, failure);
    }

    /**
     * @return whether the scene is no longer as it was: a list replaced or added to (nested
     *         lists included), a light added, removed or replaced
     */
    boolean changed() {
        return change() != null;
    }

    /** @return what changed, in words, or null */
    private String change() {
        if (scene.geometries != geometries) return "its geometry list was replaced";
        long now = geometries.changeCount();
        if (now != changes) return "its geometries were added to (" + (now - changes) + " times)";
        if (scene.lights != lightList) return "its light list was replaced";
        LightSource[] nowLights = lightList.toArray(new LightSource[0]);
        if (nowLights.length != lights.length) return "its lights went from " + lights.length + " to " + nowLights.length;
        for (int i = 0; i < lights.length; ++i)
            if (nowLights[i] != lights[i]) return "its light #" + i + " was replaced";
        return null;
    }

    private static ConcurrentModificationException changed(Scene scene, String image, String what, Throwable cause) {
        return new ConcurrentModificationException("the scene '" + scene.name + "' changed during the render of " + image
                + ": " + what + " (a scene must not change while it renders; render it again when it is complete)",
                cause);
    }
}
