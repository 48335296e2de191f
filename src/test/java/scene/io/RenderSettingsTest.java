package scene.io;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import primitives.Point;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.ImageWriter;
import scene.Scene;

/**
 * {@link RenderSettings}: what {@code applyTo} sets on a camera builder. Cameras are only built
 * and described here, never rendered.
 */
class RenderSettingsTest {
    private static final Scene SCENE = new Scene("empty");

    /** A builder with a complete view, ready for the settings. */
    private static Camera.Builder view() {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(0, 0, -1)).setVpSize(1, 1)
                .setVpDistance(1);
    }

    private static Camera apply(RenderSettings settings, Camera.Builder camera) {
        return settings.applyTo(camera, SCENE, new ImageWriter("settings", 1, 1)).setSummary(false).build();
    }

    @Nested
    @DisplayName("anti-aliasing: the grid belongs to RANDOM alone")
    class AntiAliasingGrid {
        @Test
        @DisplayName("RANDOM sets its grid")
        void random() {
            RenderSettings s = RenderSettings.defaults("x").withAntiAliasing(AntiAliasing.RANDOM)
                    .withAntiAliasingParameters(3, 5, 3, 8);
            assertThat(apply(s, view()).describe()).startsWith("RANDOM 3x5,");
        }

        /**
         * The camera accepts a grid only together with RANDOM, so for the other modes the
         * settings do not pass theirs: a grid set on the builder before stays.
         */
        @ParameterizedTest(name = "{0}")
        @EnumSource(value = AntiAliasing.class, names = "RANDOM", mode = EnumSource.Mode.EXCLUDE)
        @DisplayName("another mode leaves the builder's grid alone")
        void otherModes(AntiAliasing mode) {
            RenderSettings s = RenderSettings.defaults("x").withAntiAliasing(mode).withAntiAliasingParameters(3, 5, 3, 8);
            Camera.Builder camera = view().setAntiAliasingGrid(7, 2);
            assertThat(apply(s, camera).describe()).startsWith(mode.name());
            assertThat(camera.setAntiAliasing(AntiAliasing.RANDOM).setSummary(false).build().describe())
                    .startsWith("RANDOM 7x2,");
        }
    }
}
