package scene.io;

import java.util.Objects;

import primitives.Point;
import primitives.Vector;
import renderer.Camera;

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

    /** The two ways a {@code <camera>} states where it looks. */
    sealed interface Direction {
        Camera.Builder applyTo(Camera.Builder camera);
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
    }
}
