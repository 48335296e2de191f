package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.within;

import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * Camera ray construction and orientation. The expected rays are worked out by hand: with the
 * course camera at the origin looking along −z with up (0,−1,0), vRight = vTo × vUp = (−1,0,0),
 * so the view-plane point of pixel (j, i) is (0,0,−d) − xOffset·x̂ − yOffset·ŷ with
 * xOffset = (j − (nX−1)/2)·w/nX and yOffset = −(i − (nY−1)/2)·h/nY.
 */
class CameraRayTest {
    /** The course's camera: at the origin, looking along −z, with (0,−1,0) as up, VP at 10. */
    private static Camera.Builder courseCamera() {
        return Camera.getBuilder()
                .setRayTracer(new RayTracerBasic(new Scene("rays")))
                .setImageWriter(new ImageWriter("rays", 1, 1))
                .setLocation(Point.ZERO)
                .setDirection(new Vector(0, 0, -1), new Vector(0, -1, 0))
                .setVpDistance(10)
                .setSummary(false);
    }

    private static void assertRay(Ray actual, Point head, Vector direction) {
        assertThat(actual).as("ray").isEqualTo(new Ray(head, direction));
        assertThat(actual.getDirection().length()).as("direction length").isCloseTo(1, within(1e-12));
    }

    @Nested
    @DisplayName("3x3 pixels on a 6x6 view plane (pixel side 2)")
    class ThreeByThree {
        private final Camera camera = courseCamera().setVpSize(6, 6).build();

        @ParameterizedTest(name = "pixel (j={0}, i={1}) {5} -> direction ({2}, {3}, {4})")
        @CsvSource({
                "0, 0,  2, -2, -10, top-left corner",
                "1, 0,  0, -2, -10, top side",
                "2, 0, -2, -2, -10, top-right corner",
                "0, 1,  2,  0, -10, left side",
                "1, 1,  0,  0, -10, centre",
                "2, 1, -2,  0, -10, right side",
                "0, 2,  2,  2, -10, bottom-left corner",
                "1, 2,  0,  2, -10, bottom side",
                "2, 2, -2,  2, -10, bottom-right corner"})
        void everyPixel(int j, int i, double x, double y, double z, String where) {
            assertRay(camera.constructRay(3, 3, j, i), Point.ZERO, new Vector(x, y, z));
        }
    }

    @Nested
    @DisplayName("4x4 pixels: no pixel centre on the view-plane centre")
    class FourByFour {
        @ParameterizedTest(name = "8x8 VP, pixel (j={0}, i={1}) {5} -> ({2}, {3}, {4})")
        @CsvSource({
                "0, 0,  3, -3, -10, top-left corner",
                "3, 0, -3, -3, -10, top-right corner",
                "0, 3,  3,  3, -10, bottom-left corner",
                "3, 3, -3,  3, -10, bottom-right corner",
                "1, 0,  1, -3, -10, top side",
                "0, 2,  3,  1, -10, left side",
                "1, 1,  1, -1, -10, inside, up-left of centre",
                "2, 1, -1, -1, -10, inside, up-right of centre",
                "2, 2, -1,  1, -10, inside, down-right of centre"})
        void eightByEightPlane(int j, int i, double x, double y, double z, String where) {
            Camera camera = courseCamera().setVpSize(8, 8).build();
            assertRay(camera.constructRay(4, 4, j, i), Point.ZERO, new Vector(x, y, z));
        }

        @ParameterizedTest(name = "6x6 VP, pixel (j={0}, i={1}) -> ({2}, {3}, {4})")
        @CsvSource({
                "0, 0,  2.25, -2.25, -10",
                "3, 3, -2.25,  2.25, -10",
                "1, 2,  0.75,  0.75, -10",
                "3, 0, -2.25, -2.25, -10"})
        void sixBySixPlane(int j, int i, double x, double y, double z) {
            Camera camera = courseCamera().setVpSize(6, 6).build();
            assertRay(camera.constructRay(4, 4, j, i), Point.ZERO, new Vector(x, y, z));
        }
    }

    @Nested
    @DisplayName("non-square view planes and cameras away from the origin")
    class General {
        @ParameterizedTest(name = "4 columns x 2 rows on an 8x2 VP, pixel (j={0}, i={1}) -> ({2}, {3}, {4})")
        @CsvSource({
                "0, 0,  3, -0.5, -10",
                "3, 0, -3, -0.5, -10",
                "2, 0, -1, -0.5, -10",
                "0, 1,  3,  0.5, -10",
                "3, 1, -3,  0.5, -10"})
        void columnsAreAlongWidthAndRowsAlongHeight(int j, int i, double x, double y, double z) {
            Camera camera = courseCamera().setVpSize(8, 2).build();
            assertRay(camera.constructRay(4, 2, j, i), Point.ZERO, new Vector(x, y, z));
        }

        @Test
        @DisplayName("the head is the camera location; vRight = vTo x vUp")
        void cameraAwayFromOrigin() {
            // vTo = x̂, vUp = ẑ, so vRight = x̂ × ẑ = −ŷ. Pixel (0,0) of 3x3 on a 6x6 VP at 5:
            // 5·x̂ − 2·vRight + 2·vUp = (5, 2, 2).
            Point location = new Point(1, 2, 3);
            Camera camera = courseCamera().setLocation(location)
                    .setDirection(new Vector(1, 0, 0), new Vector(0, 0, 1))
                    .setVpSize(6, 6).setVpDistance(5).build();
            assertThat(camera.getVRight()).isEqualTo(new Vector(0, -1, 0));
            assertRay(camera.constructRay(3, 3, 0, 0), location, new Vector(5, 2, 2));
            // Pixel (2,1): 5·x̂ + 2·vRight = (5, −2, 0).
            assertRay(camera.constructRay(3, 3, 2, 1), location, new Vector(5, -2, 0));
        }

        @ParameterizedTest(name = "pixel (j={2}, i={3}) of {0}x{1}")
        @CsvSource({"3, 3, 3, 0", "3, 3, 0, 3", "3, 3, -1, 0", "3, 3, 0, -1", "0, 3, 0, 0", "3, -2, 0, 0"})
        @DisplayName("a pixel outside the view plane or a non-positive resolution is rejected")
        void outsideRejected(int nX, int nY, int j, int i) {
            Camera camera = courseCamera().setVpSize(6, 6).build();
            assertThatIllegalArgumentException().isThrownBy(() -> camera.constructRay(nX, nY, j, i))
                    .withMessageContaining(nX + "x" + nY);
        }
    }

    @Nested
    @DisplayName("orientation: vTo, vUp, vRight are orthonormal")
    class Orientation {
        private Camera at(Point location, Camera.Builder builder) {
            return builder.setLocation(location).setVpSize(1, 1).build();
        }

        private void assertOrthonormal(Camera camera) {
            Vector to = camera.getVTo(), up = camera.getVUp(), right = camera.getVRight();
            assertThat(to.length()).as("|vTo|").isCloseTo(1, within(1e-12));
            assertThat(up.length()).as("|vUp|").isCloseTo(1, within(1e-12));
            assertThat(right.length()).as("|vRight|").isCloseTo(1, within(1e-12));
            assertThat(to.dotProduct(up)).as("vTo.vUp").isCloseTo(0, within(1e-12));
            assertThat(to.dotProduct(right)).as("vTo.vRight").isCloseTo(0, within(1e-12));
            assertThat(up.dotProduct(right)).as("vUp.vRight").isCloseTo(0, within(1e-12));
            // Right-handed: vRight = vTo × vUp.
            assertThat(to.crossProduct(up)).as("vTo x vUp").isEqualTo(right);
        }

        @Test
        @DisplayName("setDirection(to, up) normalizes both")
        void toAndUpNormalized() {
            Camera camera = at(Point.ZERO, courseCamera().setDirection(new Vector(0, 0, -5), new Vector(0, 3, 0)));
            assertThat(camera.getVTo()).isEqualTo(new Vector(0, 0, -1));
            assertThat(camera.getVUp()).isEqualTo(new Vector(0, 1, 0));
            assertThat(camera.getVRight()).isEqualTo(new Vector(1, 0, 0));
            assertOrthonormal(camera);
        }

        @Test
        @DisplayName("setDirection(target, up) keeps the part of up orthogonal to the view direction")
        void targetAndTiltedUp() {
            // vTo = −ẑ; up (0,1,1) minus its −ẑ part is (0,1,0).
            Camera camera = at(Point.ZERO, courseCamera().setDirection(new Point(0, 0, -10), new Vector(0, 1, 1)));
            assertThat(camera.getVTo()).isEqualTo(new Vector(0, 0, -1));
            assertThat(camera.getVUp()).isEqualTo(new Vector(0, 1, 0));
            assertThat(camera.getVRight()).isEqualTo(new Vector(1, 0, 0));
            assertOrthonormal(camera);
        }

        @Test
        @DisplayName("setDirection(target) takes +y as up")
        void targetOnly() {
            // From (10,0,0) to the origin: vTo = −x̂, vUp = ŷ, vRight = −x̂ × ŷ = −ẑ.
            Camera camera = at(new Point(10, 0, 0), courseCamera().setDirection(Point.ZERO));
            assertThat(camera.getVTo()).isEqualTo(new Vector(-1, 0, 0));
            assertThat(camera.getVUp()).isEqualTo(new Vector(0, 1, 0));
            assertThat(camera.getVRight()).isEqualTo(new Vector(0, 0, -1));
            assertOrthonormal(camera);
        }

        @Test
        @DisplayName("setDirection(target) straight down the y axis has no up: build() rejects it, naming the target")
        void targetStraightDown() {
            // vTo = −ŷ is parallel to the +y up hint: the course throws (no +z fallback).
            assertThatIllegalArgumentException()
                    .isThrownBy(() -> at(new Point(0, 10, 0), courseCamera().setDirection(Point.ZERO)))
                    .withMessageContaining("up hint").withMessageContaining(Point.ZERO.toString());
        }

        static Stream<Arguments> obliqueTargets() {
            return Stream.of(
                    Arguments.of(new Point(1, 2, 3), new Point(-4, 7, 0.5), null),
                    Arguments.of(new Point(0, 140, 900), new Point(0, 35, 0), null),
                    Arguments.of(new Point(-3, -3, -3), new Point(5, 1, -2), new Vector(1, 1, 1)),
                    Arguments.of(new Point(2, 0, 0), new Point(0, 0.001, 0), new Vector(0.3, -2, 0.7)));
        }

        @ParameterizedTest(name = "from {0} to {1}, up hint {2}")
        @MethodSource("obliqueTargets")
        @DisplayName("setDirection(target[, up]) toward an oblique target")
        void obliqueTarget(Point location, Point target, Vector upHint) {
            Camera.Builder b = upHint == null ? courseCamera().setDirection(target)
                    : courseCamera().setDirection(target, upHint);
            Camera camera = at(location, b);
            assertOrthonormal(camera);
            assertThat(camera.getVTo()).isEqualTo(target.subtract(location).normalize());
            // vUp leans toward the hint: it is the hint's component orthogonal to vTo, normalized.
            Vector hint = upHint == null ? Vector.AXIS_Y : upHint.normalize();
            Vector orthogonal = hint.subtract(camera.getVTo().scale(hint.dotProduct(camera.getVTo())));
            assertThat(camera.getVUp()).isEqualTo(orthogonal.normalize());
        }

        @Test
        @DisplayName("a target at the camera location is rejected")
        void targetAtLocation() {
            Camera.Builder b = courseCamera().setLocation(new Point(1, 1, 1)).setVpSize(1, 1)
                    .setDirection(new Point(1, 1, 1));
            assertThatIllegalArgumentException().isThrownBy(b::build).withMessageContaining("(1.0,1.0,1.0)");
        }

        @Test
        @DisplayName("an up hint parallel to the view direction is rejected")
        void upParallelToView() {
            Camera.Builder b = courseCamera().setVpSize(1, 1).setDirection(new Point(0, 0, -4), new Vector(0, 0, 2));
            assertThatIllegalArgumentException().isThrownBy(b::build).withMessageContaining("parallel");
        }
    }
}
