package renderer;

import java.util.MissingResourceException;
import java.util.Objects;

import primitives.Point;
import primitives.Vector;

/**
 * A {@link Camera.Builder}'s view settings as they are given: location, direction, roll, view
 * plane, resolution and lens, turned into a {@link View} by {@link #view()}. What the course checks
 * in the setter is checked here at once; the view plane and the resolution only by {@link #view()},
 * still naming the bad value (the 2025–26 course sets bad ones up first and expects only
 * {@code build()} to throw). Mutable, and owned by one builder.
 */
final class ViewDraft {
    private Point location;
    /** The unit view direction and image up, with {@code to} null when looking at {@link #target}. */
    private Vector to, up;
    /** The point looked at, or null; {@code up} is then the unit up hint, null for +y. */
    private Point target;
    /** The view plane's size and distance in scene units, as set (checked by {@link #view()}). */
    private double width, height, distance;
    private boolean sizeSet, distanceSet;
    /** Degrees the frame is turned about the view direction when the view is made, in [0, 360). */
    private int roll;
    /** Pixel columns and rows, as set (checked by {@link #view()}). */
    private int nX = 1, nY = 1;
    private View.Lens lens = View.Lens.PINHOLE;

    /** No location or direction yet, no view plane, a 1×1 resolution, the pinhole. */
    ViewDraft() {
    }

    /** The settings of a built view: its location, its final frame (to and up, no roll), plane, resolution and lens. */
    ViewDraft(View view) {
        location = view.location();
        to = view.frame().to();
        up = view.frame().up();
        width = view.plane().width();
        height = view.plane().height();
        distance = view.plane().distance();
        sizeSet = distanceSet = true;
        nX = view.plane().nX();
        nY = view.plane().nY();
        lens = view.lens();
    }

    void location(Point location) {
        this.location = Objects.requireNonNull(location, "camera location");
    }

    /** Looks along {@code to} with image up {@code up}, both of any length; refused at once when they are not orthogonal. */
    void direction(Vector to, Vector up) {
        View.Frame frame = View.Frame.along(to, up);
        this.to = frame.to();
        this.up = frame.up();
        this.target = null;
    }

    /** Looks at {@code target} with an up hint, which need not be orthogonal to the view direction. */
    void target(Point target, Vector up) {
        this.target = Objects.requireNonNull(target, "camera target");
        this.up = Objects.requireNonNull(up, "camera up").normalize();
        this.to = null;
    }

    /** Looks at {@code target} with +y as the up hint. */
    void target(Point target) {
        this.target = Objects.requireNonNull(target, "camera target");
        this.up = null;
        this.to = null;
    }

    /** Adds {@code degrees} (any int) to the roll. */
    void roll(int degrees) {
        this.roll = Math.floorMod(roll + Math.floorMod(degrees, 360), 360);
    }

    void size(double width, double height) {
        this.width = width;
        this.height = height;
        this.sizeSet = true;
    }

    void distance(double distance) {
        this.distance = distance;
        this.distanceSet = true;
    }

    void resolution(int nX, int nY) {
        this.nX = nX;
        this.nY = nY;
    }

    void lens(View.Lens lens) {
        this.lens = lens;
    }

    View.Lens lens() {
        return lens;
    }

    /**
     * The view of these settings, checked in the order {@code build()} reports them: location,
     * direction, view plane size, its distance, resolution, and last the frame a target gives.
     *
     * @throws MissingResourceException naming the location or direction when it is missing
     * @throws IllegalArgumentException when the view plane's size or distance is missing, when it
     *                                  or the resolution is not positive (naming the value), or
     *                                  when a target is the location or lies along the up
     *                                  direction from it
     */
    View view() {
        final String missing = "Missing rendering data";
        final String camera = "Camera";
        if (location == null) throw new MissingResourceException(missing + ": location", camera, "location");
        if (to == null && target == null) throw new MissingResourceException(missing + ": direction", camera, "direction");
        if (!sizeSet) throw new IllegalArgumentException(missing + ": view plane size (setVpSize)");
        View.ViewPlane.requireSize(width, height);
        if (!distanceSet) throw new IllegalArgumentException(missing + ": view plane distance (setVpDistance)");
        View.ViewPlane plane = new View.ViewPlane(width, height, distance, nX, nY);
        View.Frame frame = (to != null ? View.Frame.of(to, up) : View.Frame.lookingAt(location, target, up)).rolled(roll);
        return new View(location, frame, plane, lens);
    }
}
