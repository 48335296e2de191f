package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowable;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Plane;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * The Java API's ray budget: a camera whose pixel would take more than
 * {@link RayBudget#MAX_RAYS_PER_PIXEL} rays by the up-front count is refused, as a scene file is;
 * the rays a pixel traces are counted and never exceed the limit; and a render interrupted in the
 * middle of a pixel of millions of rays stops within a bounded time.
 */
class RayBudgetTest {
    static Stream<Arguments> builds() {
        return Stream.of(
                Arguments.of("RANDOM 256x256, beams of 128", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.RANDOM, 256, 256), Sampling.DEFAULT.withAntiAliasing(AntiAliasing.RANDOM)
                        .withGrid(256, 256), false, 128, 1, 0),
                Arguments.of("ADAPTIVE depth 6 with a lens, 3 soft lights", (UnaryOperator<Camera.Builder>) b -> b
                        .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(6, 1).setDepthOfField(10, 1),
                        Sampling.DEFAULT.withAntiAliasing(AntiAliasing.ADAPTIVE).withAdaptive(6, 1), true, 64, 64, 3),
                Arguments.of("NONE with 60000 lens samples", (UnaryOperator<Camera.Builder>) b -> b.setDepthOfField(10, 1)
                        .setDepthOfFieldSamples(60_000), Sampling.DEFAULT.withLensSamples(60_000), true, 200, 1, 0));
    }

    /** A camera on {@link TestScenes#EYE} of side × side pixels with {@code tracer}. */
    /** The rule as a scene file's settings meet it: the sampling's camera rays under a lens or not, the tracer's factors. */
    private static void rule(Sampling sampling, boolean lens, int beamSize, int shadowSamples,
                             java.util.Collection<? extends lighting.LightSource> lights) {
        RayBudget.require(sampling.antiAliasing(), sampling.maxSamplesPerPixel(lens), beamSize, shadowSamples, lights);
    }

    private static Camera.Builder camera(RayTracerBasic tracer, int side) {
        return Camera.getBuilder().setLocation(TestScenes.EYE)
                .setDirection(new Vector(0, 0, -1), new Vector(0, 1, 0))
                .setVpSize(side / 10.0, side / 10.0).setVpDistance(10).setResolution(side, side)
                .setRayTracer(tracer).setSummary(false);
    }

    /**
     * A scene with {@code soft} point lights of radius 0.5 and {@code other} point lights of radius
     * 0, all near z = 6, in front of the camera's view plane.
     */
    private static Scene lit(int soft, int other) {
        Scene scene = new Scene("lit");
        for (int i = 0; i < soft; ++i)
            scene.lights.add(new PointLight(new Color(50, 50, 50), new Point(i % 4 - 1.5, 2 + i / 4 * 0.1, 6)).setRadius(0.5));
        for (int i = 0; i < other; ++i)
            scene.lights.add(new PointLight(new Color(20, 20, 20), new Point(i % 4 - 1.5, -2 - i / 4 * 0.1, 6)));
        return scene;
    }

    /** The up-front figure: camera samples × (1 + 2 beams) × (1 + shadow samples × soft lights + other lights). */
    private static long figure(long cameraRays, int beam, int shadows, int soft, int other) {
        return cameraRays * (1 + 2L * beam) * (1 + (long) shadows * soft + other);
    }

    @Nested
    @DisplayName("build() holds a camera to 2^24 rays per pixel, counting both beams and every light, naming the factors")
    class Build {
        @Test
        @DisplayName("the message names every factor, the product and the limit")
        void message() {
            Camera.Builder builder = camera(new RayTracerBasic(lit(3, 2)).setBeamSize(4096).setShadowSamples(4096), 1);
            assertThatThrownBy(builder::build).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("NONE sampling with 1 samples per pixel × (1 + 2 beams of 4096 rays: reflection and"
                            + " transmission) × (1 + 4096 shadow samples × 3 soft lights + 2 other lights) is "
                            + figure(1, 4096, 4096, 3, 2) + " rays per pixel, more than the limit of 16777216");
        }

        @ParameterizedTest(name = "{0}² grid × beam {1} × {2} shadow samples × {3} soft + {4} other lights")
        @CsvSource({
                "1, 1000000000, 16, 0, 0",
                "1, 16, 1000000000, 1, 0",
                "1, 4096, 4096, 16, 0", // the beam 4096 × 4096 with 16 soft lights
                "1, 256, 256, 128, 0",  // 513 × 32,769: one soft light more than fits
                "256, 4096, 4096, 16, 0" })
        void refused(int grid, int beam, int shadows, int soft, int other) {
            Scene scene = new Scene("s");
            scene.lights.addAll(lit(soft, 0).lights);
            scene.lights.addAll(lit(0, other).lights);
            Camera.Builder builder = camera(new RayTracerBasic(scene).setBeamSize(beam).setShadowSamples(shadows), 1);
            if (grid > 1) builder.setAntiAliasing(AntiAliasing.RANDOM, grid, grid);
            assertThatThrownBy(builder::build).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining(" is " + figure((long) grid * grid, beam, shadows, soft, other)
                            + " rays per pixel, more than the limit of 16777216");
        }

        @ParameterizedTest(name = "{0} soft lights")
        @ValueSource(ints = { 0, 1, 16, 127 })
        @DisplayName("beam 256 × 256 shadow samples fits with up to 127 soft lights (513 × 32,513 rays)")
        void softLightsThatFit(int soft) {
            assertThat(camera(new RayTracerBasic(lit(soft, 0)).setBeamSize(256).setShadowSamples(256), 1).build())
                    .isNotNull();
        }

        @Test
        @DisplayName("shadow samples cost nothing without a soft light: only lights with a radius take them")
        void shadowSamplesWithoutSoftLights() {
            assertThat(camera(new RayTracerBasic(lit(0, 3)).setShadowSamples(1 << 30), 1).build()).isNotNull();
        }

        @Test
        @DisplayName("the rule alone, as a scene file is checked: sampling, lens, beam and shadow samples over the lights")
        void theRuleAlone() {
            assertThatThrownBy(() -> rule(Sampling.DEFAULT, false, 1_000_000_000, 16, List.of()))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("NONE sampling with 1 samples per pixel × (1 + 2 beams of 1000000000 rays: reflection and"
                            + " transmission) × (1 + 16 shadow samples × 0 soft lights + 0 other lights) is 2000000001 rays"
                            + " per pixel, more than the limit of 16777216");
            rule(Sampling.DEFAULT.withAntiAliasing(AntiAliasing.ADAPTIVE), true, 16, 16, lit(1, 2).lights);
            assertThatIllegalArgumentException().isThrownBy(() -> rule(Sampling.DEFAULT, false, 0, 16, List.of()))
                    .withMessage("beam size must be at least 1 ray, got 0");
        }

        @ParameterizedTest(name = "{0}")
        @MethodSource("renderer.RayBudgetTest#builds")
        @DisplayName("the rule refuses exactly what build() refuses, with its message")
        void theRuleIsBuilds(String name, UnaryOperator<Camera.Builder> settings, Sampling sampling, boolean lens,
                             int beamSize, int shadowSamples, int softLights) {
            Scene scene = lit(softLights, 1);
            Throwable built = catchThrowable(() -> settings.apply(camera(new RayTracerBasic(scene).setBeamSize(beamSize)
                    .setShadowSamples(shadowSamples), 1)).build());
            Throwable ruled = catchThrowable(() -> rule(sampling, lens, beamSize, shadowSamples, scene.lights));
            assertThat(built).as("build() refuses").isNotNull();
            assertThat(ruled).isInstanceOf(IllegalArgumentException.class).hasMessage(built.getMessage());
        }

        @Test
        @DisplayName("refused before the image is allocated: a 40000x40000 resolution costs nothing")
        void beforeTheImage() {
            Camera.Builder builder = camera(new RayTracerBasic(new Scene("s")).setBeamSize(1_000_000_000), 1)
                    .setResolution(40_000, 40_000);
            assertThatThrownBy(builder::build).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("more than the limit of 16777216");
        }

        @Test
        @DisplayName("ADAPTIVE counts its lattice, (2^depth + 1)² points: depth 6 × (1 + 2 × 117) × 17 is over, beam 116 fits")
        void adaptive() {
            Camera.Builder builder = camera(new RayTracerBasic(lit(1, 0)).setBeamSize(117).setShadowSamples(16), 1)
                    .setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(6, 8);
            assertThatThrownBy(builder::build).hasMessage("ADAPTIVE sampling with 4225 samples per pixel × (1 + 2 beams"
                    + " of 117 rays: reflection and transmission) × (1 + 16 shadow samples × 1 soft light + 0 other lights)"
                    + " is 16878875 rays per pixel, more than the limit of 16777216");
            builder.setRayTracer(new RayTracerBasic(lit(1, 0)).setBeamSize(116).setShadowSamples(16));
            assertThat(builder.build()).isNotNull(); // 4225 × 233 × 17 = 16,735,225
        }

        @Test
        @DisplayName("the limit itself is allowed: 65,536 samples × 3 × 85 = 16,711,680 fits, one light more does not")
        void atTheLimit() {
            Camera.Builder builder = camera(new RayTracerBasic(lit(0, 84)).setBeamSize(1), 1)
                    .setAntiAliasing(AntiAliasing.RANDOM, 256, 256);
            assertThat(builder.build()).isNotNull();
            builder.setRayTracer(new RayTracerBasic(lit(0, 85)).setBeamSize(1));
            assertThatThrownBy(builder::build).hasMessageContaining("is 16908288 rays per pixel");
        }

        @Test
        @DisplayName("a tracer raised after build() is refused when the render starts")
        void raisedLater() {
            RayTracerBasic tracer = new RayTracerBasic(lit(1, 0));
            Camera built = camera(tracer, 1).build();
            tracer.setShadowSamples(1 << 30);
            assertThatThrownBy(built::renderImage).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("× (1 + 1073741824 shadow samples × 1 soft light + 0 other lights) is");
        }

        @Test
        @DisplayName("soft lights added after build() are refused when the render starts")
        void lightsAddedLater() {
            Scene scene = lit(1, 0);
            RayTracerBasic tracer = new RayTracerBasic(scene).setBeamSize(256).setShadowSamples(256);
            Camera built = camera(tracer, 1).build(); // 513 × 257
            scene.lights.addAll(lit(127, 0).lights);
            assertThatThrownBy(built::renderImage).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("× (1 + 256 shadow samples × 128 soft lights + 0 other lights) is 16810497 rays");
        }
    }

    /**
     * The rays a pixel actually traces, counted by the render ({@link RenderStats#totalRays()}):
     * the up-front figure is exactly what the worst case of one bounce traces, and a pixel whose
     * bounces go deeper is stopped by the count before it traces more than the limit.
     */
    @Nested
    @DisplayName("the rays actually traced never exceed the budget")
    class Counted {
        /**
         * The worst case of one bounce: the camera sees a pane that reflects and transmits (both
         * with a spread, so both bounces are beams) and is lit by every light; each beam ray hits a
         * matte wall, behind the camera or behind the pane, lit by every light through the clear pane.
         */
        private Scene pane(int soft, int other) {
            Scene scene = lit(soft, other);
            scene.geometries.add(
                    new Plane(new Point(0, 0, 0), new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.5).setKr(1)
                            .setKt(1).setReflectionSpread(0.3).setTransmissionSpread(0.3)),
                    new Plane(new Point(0, 0, -5), new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.5)),
                    new Plane(new Point(0, 0, 20), new Vector(0, 0, 1)).setMaterial(new Material().setKd(0.5)));
            return scene;
        }

        @ParameterizedTest(name = "{0}² grid × beam {1} × {2} shadow samples × {3} soft + {4} other lights")
        @CsvSource({ "1, 1, 1, 0, 0", "2, 4, 8, 1, 0", "1, 8, 4, 3, 2", "2, 16, 16, 2, 1", "1, 64, 1, 0, 5", "3, 1, 32, 4, 0" })
        @DisplayName("the worst case of each factor traces exactly the up-front figure")
        void worstCaseOfOneBounce(int grid, int beam, int shadows, int soft, int other) {
            RayTracerBasic tracer = new RayTracerBasic(pane(soft, other)).setBeamSize(beam).setShadowSamples(shadows);
            Camera.Builder builder = camera(tracer, 1).setMultithreading(0);
            if (grid > 1) builder.setAntiAliasing(AntiAliasing.RANDOM, grid, grid);
            RenderStats stats = builder.build().render();
            assertThat(stats.totalRays()).isEqualTo(figure((long) grid * grid, beam, shadows, soft, other));
        }

        /**
         * Deeper bounces: twelve parallel panes that each reflect and transmit everything, so every
         * path splits in two at each of the tracer's levels: far more than the one-bounce figure.
         */
        private Limited hallOfPanes() {
            Scene scene = lit(1, 1);
            for (int i = 0; i < 12; ++i)
                scene.geometries.add(new Plane(new Point(0, 0, -i), new Vector(0, 0, 1))
                        .setMaterial(new Material().setKd(0.1).setKr(1).setKt(1)));
            Limited tracer = new Limited(scene);
            tracer.setBeamSize(1).setShadowSamples(4);
            return tracer;
        }

        /**
         * The library's tracer whose workers hold a pixel to {@link #maxRaysPerPixel} rather than
         * 2^24 rays, which a worst-case pixel would take seconds to reach.
         */
        private static final class Limited extends RayTracerBasic {
            long maxRaysPerPixel = Long.MAX_VALUE;

            Limited(Scene scene) {
                super(scene);
            }

            @Override
            TraceContext newContext() {
                return new TraceContext(MAX_CALC_COLOR_LEVEL, MIN_CALC_COLOR_K, maxRaysPerPixel);
            }
        }

        @Test
        @DisplayName("a pixel that needs more than the limit fails naming it, and one at the limit is rendered within it")
        void deeperBouncesAreStoppedAtTheLimit() {
            Limited tracer = hallOfPanes();
            long needed = camera(tracer, 1).setMultithreading(0).build().render().totalRays();
            assertThat(needed).isGreaterThan(10 * figure(1, 1, 4, 1, 1)); // what the up-front figure cannot see

            for (int threads : new int[] { 0, 2 }) {
                tracer.maxRaysPerPixel = needed;
                assertThat(camera(tracer, 1).setMultithreading(threads).build().render().totalRays()).isEqualTo(needed);
                tracer.maxRaysPerPixel = needed - 1;
                Camera over = camera(tracer, 1).setMultithreading(threads).build();
                assertThatThrownBy(over::render).isInstanceOf(IllegalStateException.class)
                        .hasMessageStartingWith("pixel (0, 0) needs more than " + (needed - 1) + " rays: each reflection"
                                + " and refraction below the first bounce shades again");
            }
        }

        @Test
        @DisplayName("the limit of a pixel is its own: a 2x2 image of pixels within it renders")
        void perPixel() {
            Limited tracer = hallOfPanes();
            long needed = camera(tracer, 1).setMultithreading(0).build().render().totalRays();
            tracer.maxRaysPerPixel = needed + needed / 2; // the four pixels need about 4 × needed together
            assertThat(camera(tracer, 2).setMultithreading(0).build().render().totalRays()).isGreaterThan(2 * needed);
        }
    }

    @Nested
    @DisplayName("an interrupt stops a render inside a pixel of 2^24 rays")
    class Interrupt {
        @ParameterizedTest(name = "{0} threads")
        @ValueSource(ints = { 0, 2 })
        void stopsWithinAPixel(int threads) {
            // Beams of 2000 glossy rays, each shaded under two lights of 2000 shadow rays (4001 × 4002
            // rays, within the budget): seconds per pixel, minutes for the image before the tracer
            // asked within a pixel.
            RayTracerBasic tracer = new RayTracerBasic(TestScenes.everyEffect()).setBeamSize(2000).setShadowSamples(2000);
            Camera camera = camera(tracer, 16).setMultithreading(threads).build();
            AtomicReference<Throwable> thrown = new AtomicReference<>();
            CountDownLatch started = new CountDownLatch(1);
            Thread renderer = new Thread(() -> {
                started.countDown();
                try {
                    camera.renderImage();
                } catch (Throwable t) {
                    thrown.set(t);
                }
            }, "budget-render");
            assertTimeoutPreemptively(Duration.ofSeconds(20), () -> {
                renderer.start();
                started.await();
                TimeUnit.MILLISECONDS.sleep(300);
                renderer.interrupt();
                renderer.join();
            });
            assertThat(thrown.get()).isInstanceOf(CancellationException.class).hasMessageContaining("was interrupted");
        }
    }
}
