package renderer;

import java.util.Objects;

import primitives.Checks;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;

/**
 * What a camera sees: where it stands, its orthonormal frame, its view plane cut into pixels and
 * its lens. A value, checked when it is made; {@link Camera.Builder#build()} makes one from a
 * builder's settings, and a camera generates its rays from it. Units are scene units.
 *
 * @param location where the camera stands: the head of every pinhole ray, the lens centre
 * @param frame    the directions: view, image up and image right
 * @param plane    the view plane's size and distance, and the pixels it is cut into
 * @param lens     the thin lens: a pinhole when its aperture is 0
 *
 * @hidden internal: the camera's view value, public for the scene reader's checks; a scene test sets it through Camera.Builder
 */
public record View(Point location, Frame frame, ViewPlane plane, Lens lens) {
    /**
     * @param location the camera's position
     * @param frame    its directions
     * @param plane    its view plane and resolution
     * @param lens     its lens
     * @throws NullPointerException naming a missing part
     */
    public View {
        Objects.requireNonNull(location, "camera location");
        Objects.requireNonNull(frame, "camera frame");
        Objects.requireNonNull(plane, "view plane");
        Objects.requireNonNull(lens, "lens");
    }

    /**
     * The camera's directions: unit length, mutually orthogonal (within {@link Util#isZero}), and
     * right-handed, {@code right = to × up}.
     *
     * @param to    the view direction, through the view plane's centre
     * @param up    the image's up direction
     * @param right the image's right direction
     *
     * @hidden internal: part of the camera's view value
     */
    public record Frame(Vector to, Vector up, Vector right) {
        /**
         * @param to    the view direction
         * @param up    the image's up direction
         * @param right the image's right direction
         * @throws IllegalArgumentException when the three are not unit length, orthogonal and
         *                                  right-handed, naming them
         */
        public Frame {
            Objects.requireNonNull(to, "camera direction 'to'");
            Objects.requireNonNull(up, "camera direction 'up'");
            Objects.requireNonNull(right, "camera direction 'right'");
            if (!Util.isZero(to.lengthSquared() - 1) || !Util.isZero(up.lengthSquared() - 1)
                    || !Util.isZero(right.lengthSquared() - 1) || !Util.isZero(to.dotProduct(up))
                    || !Util.isZero(to.crossProduct(up).dotProduct(right) - 1))
                throw new IllegalArgumentException("camera frame 'to' " + to + ", 'up' " + up + ", 'right' " + right
                        + " must be unit vectors, orthogonal, with right = to x up");
        }

        /**
         * The frame looking along {@code to} with image up {@code up}.
         *
         * @param to the view direction, unit length
         * @param up the image's up direction, unit length and orthogonal to {@code to}
         * @return the frame, its right direction {@code to × up}
         */
        public static Frame of(Vector to, Vector up) {
            return new Frame(to, up, to.crossProduct(up).normalize());
        }

        /**
         * The frame looking along {@code to} with image up {@code up}, of any length: the rule of
         * the course's {@code setDirection(to, up)}, which the scene reader checks a
         * {@code <camera direction up>} with.
         *
         * @param to the view direction, any length
         * @param up the image's up direction, any length
         * @return the frame of the two normalized
         * @throws NullPointerException     naming a missing direction
         * @throws IllegalArgumentException when the two are not orthogonal, naming them
         */
        public static Frame along(Vector to, Vector up) {
            Objects.requireNonNull(to, "camera direction 'to'");
            Objects.requireNonNull(up, "camera direction 'up'");
            Vector unitTo = to.normalize(), unitUp = up.normalize();
            if (!Util.isZero(unitTo.dotProduct(unitUp)))
                throw new IllegalArgumentException("camera 'to' " + to + " and 'up' " + up + " must be orthogonal");
            return of(unitTo, unitUp);
        }

        /**
         * The frame of a camera at {@code location} looking at {@code target}: the image's up is
         * the part of the up hint orthogonal to the view direction.
         *
         * @param location the camera's position
         * @param target   the point at the image's centre
         * @param upHint   the up hint; null: +y
         * @return the frame
         * @throws IllegalArgumentException when the target is the location, or lies along the up
         *                                  hint from it (no image up can be derived), naming them
         */
        public static Frame lookingAt(Point location, Point target, Vector upHint) {
            if (target.equals(location))
                throw new IllegalArgumentException("camera target " + target + " is the camera location");
            Vector to = target.subtract(location).normalize();
            Vector hint = upHint != null ? upHint : Vector.AXIS_Y;
            if (Util.isZero(Math.abs(to.dotProduct(hint)) - 1))
                throw new IllegalArgumentException("camera target " + target + " seen from " + location
                        + " lies along the up " + (upHint != null ? "vector " : "hint +y ") + hint
                        + ": no image up can be derived; give an up vector not parallel to the view direction " + to);
            Vector right = to.crossProduct(hint).normalize();
            return of(to, right.crossProduct(to).normalize());
        }

        /**
         * This frame turned about its view direction by {@code degrees}, by the right-hand rule
         * about {@code to}: a positive angle takes up toward right, so 90 makes the old right the
         * new up (and the old down the new right). Seen by the viewer, looking along {@code to},
         * the camera turns clockwise and the scene in the image counter-clockwise. Multiples of
         * 90° are exact (no cosine of π/2 rounding to 6e-17), so 0 and 360 return this frame.
         *
         * @param degrees the angle, any int (taken modulo 360)
         * @return the turned frame, with the same view direction
         */
        Frame rolled(int degrees) {
            Vector newUp = switch (Math.floorMod(degrees, 360)) {
                case 0 -> null;
                case 90 -> right;
                case 180 -> up.scale(-1);
                case 270 -> right.scale(-1);
                default -> {
                    double radians = Math.toRadians(Math.floorMod(degrees, 360));
                    yield up.scale(Math.cos(radians)).add(right.scale(Math.sin(radians))).normalize();
                }
            };
            return newUp == null ? this : of(to, newUp);
        }
    }

    /**
     * The view plane: a rectangle at {@code distance} along the view direction, centred on it,
     * cut into nX × nY pixels (the image's resolution).
     *
     * @param width    its width, positive and finite
     * @param height   its height, positive and finite
     * @param distance its distance from the location, positive and finite
     * @param nX       pixel columns, positive
     * @param nY       pixel rows, positive
     *
     * @hidden internal: part of the camera's view value
     */
    public record ViewPlane(double width, double height, double distance, int nX, int nY) {
        /**
         * @param width    the width
         * @param height   the height
         * @param distance the distance from the location
         * @param nX       pixel columns
         * @param nY       pixel rows
         * @throws IllegalArgumentException when a size, the distance or the resolution is not
         *                                  positive, naming it (checked in the builder's order)
         */
        public ViewPlane {
            requireSize(width, height);
            Checks.requirePositive(distance, "view plane distance");
            requireResolution(nX, nY);
        }

        /** The size check on its own, for a builder that reports a missing distance after it. */
        static void requireSize(double width, double height) {
            Checks.requirePositive(width, "view plane width");
            Checks.requirePositive(height, "view plane height");
        }

        static void requireResolution(int nX, int nY) {
            if (nX <= 0 || nY <= 0) throw new IllegalArgumentException("resolution must be positive, got " + nX + "x" + nY);
        }
    }

    /**
     * A thin lens: objects at {@code focalDistance} along the view direction stay sharp, the blur
     * grows with the aperture radius. Aperture 0 is the pinhole camera, whatever the focal
     * distance.
     *
     * @param aperture      the lens radius, finite and ≥ 0
     * @param focalDistance the distance of the sharp plane, finite and ≥ 0; positive with an aperture
     *
     * @hidden internal: part of the camera's view value
     */
    public record Lens(double aperture, double focalDistance) {
        /** The pinhole camera: every ray starts at the location. */
        public static final Lens PINHOLE = new Lens(0, 0);

        /**
         * @param aperture      the lens radius
         * @param focalDistance the distance of the sharp plane
         * @throws IllegalArgumentException for a negative or infinite value, or an aperture
         *                                  without a positive focal distance, naming it
         */
        public Lens {
            Checks.requireNonNegative(aperture, "aperture radius");
            if (aperture > 0) Checks.requirePositive(focalDistance, "focal distance");
            else Checks.requireNonNegative(focalDistance, "focal distance");
        }

        /**
         * The rule of the course's {@code setDepthOfField(focalDistance, apertureRadius)}: the
         * focal distance checked first, then the aperture.
         *
         * @param focalDistance  the distance of the sharp plane, positive and finite
         * @param apertureRadius the lens radius, finite and ≥ 0 (0: the pinhole camera)
         * @return the lens
         * @throws IllegalArgumentException when either is out of range, naming it
         */
        public static Lens thin(double focalDistance, double apertureRadius) {
            Checks.requirePositive(focalDistance, "focal distance");
            Checks.requireNonNegative(apertureRadius, "aperture radius");
            return new Lens(apertureRadius, focalDistance);
        }

        /** @return whether this is the pinhole camera (aperture 0): a camera sample draws no lens point */
        public boolean isPinhole() {
            return aperture == 0;
        }
    }

    /**
     * The ray from the camera through the centre of pixel (column j, row i) of the view plane cut
     * into nX × nY pixels (not necessarily the plane's own resolution): the course's
     * {@code constructRay}, a pinhole ray whatever the lens.
     *
     * @param nX the number of columns the view plane is cut into, &gt; 0
     * @param nY the number of rows, &gt; 0
     * @param j  the column, 0 at the left, &lt; nX
     * @param i  the row, 0 at the top, &lt; nY
     * @return the ray from the location through the pixel's centre (unit direction)
     * @throws IllegalArgumentException for a non-positive resolution or a pixel outside it, or
     *                                  when the view plane is too near or too small for the
     *                                  location's precision to give the ray a direction
     */
    public Ray constructRay(int nX, int nY, int j, int i) {
        ViewPlane.requireResolution(nX, nY);
        if (j < 0 || j >= nX || i < 0 || i >= nY)
            throw new IllegalArgumentException("pixel (" + j + "," + i + ") is outside the " + nX + "x" + nY + " view plane");
        double[] d = new double[3];
        CameraRays rays = cameraRays();
        rays.direction((j - (nX - 1) / 2.0) * (plane.width / nX), -(i - (nY - 1) / 2.0) * (plane.height / nY), d);
        return new Ray(location, new Vector(d[0], d[1], d[2]));
    }

    /** @return the generator of this view's camera rays, its per-ray constants computed once */
    CameraRays cameraRays() {
        return new CameraRays(this);
    }

    /**
     * A view's camera rays from film coordinates (pixels from the image's top-left corner) and
     * lens coordinates (a point of the unit square, mapped onto the lens disk). It holds the
     * view's numbers as flat doubles and computes the per-ray constants once, by the very
     * operations a ray would repeat (so rays keep their bits): two of them are divisions. Shared
     * by the workers of a render; immutable.
     */
    static final class CameraRays {
        private final double locX, locY, locZ;
        private final double toX, toY, toZ;
        private final double upX, upY, upZ;
        private final double rightX, rightY, rightZ;
        private final double aperture, focalDistance;
        /** The view plane's centre, location + to · distance. */
        private final double centreX, centreY, centreZ;
        /** A pixel's width and height on the view plane, and half the image's width and height in pixels. */
        private final double pixelWidth, pixelHeight, halfNx, halfNy;

        private CameraRays(View view) {
            Point location = view.location;
            Frame f = view.frame;
            ViewPlane p = view.plane;
            locX = location.getX();
            locY = location.getY();
            locZ = location.getZ();
            toX = f.to.getX();
            toY = f.to.getY();
            toZ = f.to.getZ();
            upX = f.up.getX();
            upY = f.up.getY();
            upZ = f.up.getZ();
            rightX = f.right.getX();
            rightY = f.right.getY();
            rightZ = f.right.getZ();
            aperture = view.lens.aperture;
            focalDistance = view.lens.focalDistance;
            centreX = locX + toX * p.distance;
            centreY = locY + toY * p.distance;
            centreZ = locZ + toZ * p.distance;
            pixelWidth = p.width / p.nX;
            pixelHeight = p.height / p.nY;
            halfNx = p.nX / 2.0;
            halfNy = p.nY / 2.0;
        }

        /** @return whether a camera sample draws a lens point (the aperture is above 0) */
        boolean hasLens() {
            return aperture != 0;
        }

        /**
         * Writes the camera ray through film point (px, py) and lens point (u, v) into
         * {@link TraceContext#cameraRay()}, as doubles: no object per ray. Pixel (x, y)'s centre
         * is film point (x + 0.5, y + 0.5); (u, v) in [0, 1)² is ignored by a pinhole and
         * otherwise becomes the lens point at radius aperture·√u, angle 2πv. Every ray through
         * the lens meets the pinhole ray where it crosses the focal plane.
         */
        void generate(double px, double py, double u, double v, TraceContext ctx) {
            double xOffset = (px - halfNx) * pixelWidth;
            double yOffset = -(py - halfNy) * pixelHeight;
            double[] d = ctx.cameraDirection;
            direction(xOffset, yOffset, d);
            if (aperture == 0) {
                // new Ray(location, direction): the direction goes through the same normalization.
                ctx.cameraRay().ray(locX, locY, locZ, d[0], d[1], d[2]);
                return;
            }
            double t = focalDistance / (d[0] * toX + d[1] * toY + d[2] * toZ);
            double fx = locX + d[0] * t, fy = locY + d[1] * t, fz = locZ + d[2] * t;
            double r = aperture * Math.sqrt(u);
            double a = 2 * Math.PI * v;
            double lu = r * Math.cos(a), lv = r * Math.sin(a);
            double lx = locX + rightX * lu + upX * lv;
            double ly = locY + rightY * lu + upY * lv;
            double lz = locZ + rightZ * lu + upZ * lv;
            ctx.cameraRay().ray(lx, ly, lz, fx - lx, fy - ly, fz - lz);
        }

        /**
         * The unit direction from the location through the view-plane point at (xOffset,
         * yOffset) from the plane's centre, along right and up, written into {@code out[0..2]}:
         * the one computation behind {@link View#constructRay} and the render's camera rays, so
         * that pixel centres give both the same rays.
         */
        void direction(double xOffset, double yOffset, double[] out) {
            double px = centreX, py = centreY, pz = centreZ;
            if (xOffset != 0) {
                px += rightX * xOffset;
                py += rightY * xOffset;
                pz += rightZ * xOffset;
            }
            if (yOffset != 0) {
                px += upX * yOffset;
                py += upY * yOffset;
                pz += upZ * yOffset;
            }
            double dx = px - locX, dy = py - locY, dz = pz - locZ;
            double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
            out[0] = dx * inv;
            out[1] = dy * inv;
            out[2] = dz * inv;
        }
    }
}
