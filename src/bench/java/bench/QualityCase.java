package bench;

import renderer.Camera;

/**
 * One row of the quality benchmark: a scene, an anti-aliasing setting, and how to configure the
 * camera for it.
 *
 * @param scene   the scene's key (showcase, glossy, teapot)
 * @param mode    the line of the plot this row belongs to (NONE, CORNERS, RANDOM, ADAPTIVE depth d)
 * @param setting the setting within the mode, as printed in the table
 * @param sampling adds the anti-aliasing setting to a camera builder that has the view and tracer
 */
record QualityCase(String scene, String mode, String setting, Sampling sampling) {
    /** The anti-aliasing part of a camera configuration. */
    interface Sampling {
        Camera.Builder apply(Camera.Builder builder);
    }
}
