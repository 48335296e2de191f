package scene.io;

import java.util.Objects;

import primitives.Point;
import primitives.Vector;
import renderer.Camera;
import renderer.View;

/**
 * A {@code <camera>} element as the file states it: the view (location, direction, view plane),
 * replayed onto a {@link Camera.Builder} by the builder's own setters, so that each camera built
 * from a file checks and frames it as the Java API does. The image and the tracer are not part of
 * it: whoever renders makes them once, at their final size (see {@link LoadedScene}).
 *
 * @param location   the camera's position
 * @param direction  where it looks: a direction and an up vector, or a target
 * @param vpWidth    the view plane's width, scene units
 * @param vpHeight   the view plane's height, scene units
 * @param vpDistance the view plane's distance from the location, scene units
 */
record ViewSpec(Point location, Direction direction, double vpWidth, double vpHeight, double vpDistance) {
    ViewSpec {
        Objects.requireNonNull(location, "camera location");
        Objects.requireNonNull(direction, "camera direction");
    }

    /**
     * Replays the view onto {@code camera}.
     *
     * @param camera the builder; its image, tracer and sampling are left as they are
     * @return {@code camera}
     */
    Camera.Builder applyTo(Camera.Builder camera) {
        camera.setLocation(location).setVpSize(vpWidth, vpHeight).setVpDistance(vpDistance);
        return direction.applyTo(camera);
    }

    /**
     * The view a camera built from this one has (at one pixel, through a pinhole), made by the
     * library's own rules without a builder: what the scene reader checks a {@code <camera>} with.
     *
     * @return the view
     * @throws IllegalArgumentException when the directions make no frame (up not orthogonal to the
     *                                  direction, a target at the location or along the up), or
     *                                  the view plane is not positive, with the builder's message
     */
    View view() {
        return new View(location, direction.frame(location), new View.ViewPlane(vpWidth, vpHeight, vpDistance, 1, 1),
                View.Lens.PINHOLE);
    }

    /** The two ways a {@code <camera>} states where it looks. */
    sealed interface Direction {
        Camera.Builder applyTo(Camera.Builder camera);

        /** The frame {@link #applyTo}'s setter makes, by the same rule, seen from {@code location}. */
        View.Frame frame(Point location);
    }

    /**
     * {@code direction} and {@code up}, which must be orthogonal.
     *
     * @param to the view direction
     * @param up the image's up direction
     */
    record Along(Vector to, Vector up) implements Direction {
        @Override
        public Camera.Builder applyTo(Camera.Builder camera) {
            return camera.setDirection(to, up);
        }

        @Override
        public View.Frame frame(Point location) {
            return View.Frame.along(to, up);
        }
    }

    /**
     * {@code target}, with an up hint or without (+y).
     *
     * @param target the point at the image's centre
     * @param up     the up hint; null: +y, the builder's
     */
    record Toward(Point target, Vector up) implements Direction {
        @Override
        public Camera.Builder applyTo(Camera.Builder camera) {
            return up != null ? camera.setDirection(target, up) : camera.setDirection(target);
        }

        @Override
        public View.Frame frame(Point location) {
            return View.Frame.lookingAt(location, target, up != null ? up.normalize() : null); // the setter normalizes it
        }
    }
}
