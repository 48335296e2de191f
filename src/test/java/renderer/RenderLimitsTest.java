package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.OutputStream;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.ConcurrentModificationException;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Geometries;
import geometries.Plane;
import geometries.Sphere;
import lighting.DirectionalLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * What a render refuses with a message instead of a bare error: geometries nested deeper than
 * {@link Geometries#MAX_NESTING_DEPTH} (was a StackOverflowError), and an image larger than the
 * heap (was a bare OutOfMemoryError); a scene changed during its render (was a torn image or a
 * ConcurrentModificationException from inside the BVH's build).
 */
class RenderLimitsTest {
    /** A scene whose one sphere sits {@code depth} lists below the scene's own list. */
    private static Scene nested(int depth) {
        Scene scene = new Scene("nested");
        Geometries inner = scene.geometries;
        for (int i = 0; i < depth; ++i) {
            Geometries next = new Geometries();
            inner.add(next);
            inner = next;
        }
        inner.add(new Sphere(new Point(0, 0, 0), 1).setEmission(new Color(0, 200, 0)));
        return scene;
    }

    private static Camera camera(Scene scene, boolean bvh) {
        return TestScenes.camera(scene, new ImageWriter(4, 4))
                .setRayTracer(new RayTracerBasic(scene).setBvh(bvh)).build();
    }

    @Nested
    @DisplayName("nested Geometries: at most 1000 levels, refused beyond with the depth")
    class Nesting {
        @ParameterizedTest(name = "bvh {0}")
        @ValueSource(booleans = { false, true })
        @DisplayName("1000 levels render (the scene's list and 999 within it)")
        void atTheLimit(boolean bvh) {
            Camera camera = camera(nested(Geometries.MAX_NESTING_DEPTH - 1), bvh);
            camera.renderImage();
            assertThat(camera.imageWriter().getRgb(2, 2)).isEqualTo(0x00C800);
        }

        @ParameterizedTest(name = "bvh {0}")
        @ValueSource(booleans = { false, true })
        @DisplayName("10,000 and 20,000 levels are refused at the start, naming the depth")
        void deeper(boolean bvh) {
            int depth = bvh ? 20_000 : 10_000;
            assertThatThrownBy(() -> camera(nested(depth), bvh).renderImage()).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("the geometries are nested " + (depth + 1) + " levels deep (a Geometries in a Geometries ...),"
                            + " more than the limit of 1000 (Geometries.MAX_NESTING_DEPTH): add the shapes to fewer,"
                            + " flatter lists");
        }

        @Test
        @DisplayName("a list within itself is refused, by add() directly and at the render through another list")
        void cycle() {
            Geometries a = new Geometries(), b = new Geometries(a);
            assertThatThrownBy(() -> a.add(a)).hasMessage("geometry #0 to add is this list itself");
            a.add(b);
            Scene scene = new Scene("cycle");
            scene.geometries.add(a);
            assertThatThrownBy(() -> camera(scene, true).renderImage()).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("the geometries contain themselves");
            assertThatThrownBy(() -> camera(scene, false).renderImage()).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("the geometries contain themselves");
        }
    }

    @Nested
    @DisplayName("an image larger than the heap: the size, the memory it needs and -Xmx")
    class Memory {
        private static final String NEEDS = "image 40000x40000 needs 6104 MB; Java may use at most "
                + (Runtime.getRuntime().maxMemory() >> 20) + " MB here (render it smaller, or give Java more memory with -Xmx)";

        @Test
        void imageWriter() {
            assumeTrue(ImageWriter.bytesNeeded(40_000, 40_000) > Runtime.getRuntime().maxMemory(), "the heap is larger than 6.4 GB");
            assertThatThrownBy(() -> new ImageWriter("big", 40_000, 40_000)).isInstanceOf(OutOfMemoryError.class)
                    .hasMessage(NEEDS);
        }

        @Test
        void cameraResolution() {
            assumeTrue(ImageWriter.bytesNeeded(40_000, 40_000) > Runtime.getRuntime().maxMemory(), "the heap is larger than 6.4 GB");
            Camera.Builder builder = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Vector(0, 0, -1), Vector.AXIS_Y)
                    .setVpSize(1, 1).setVpDistance(1).setResolution(40_000, 40_000);
            assertThatThrownBy(builder::build).isInstanceOf(OutOfMemoryError.class).hasMessage(NEEDS);
        }

        @Test
        @DisplayName("the figures: 4 bytes a pixel, MB rounded up")
        void figures() {
            assertThat(ImageWriter.bytesNeeded(40_000, 40_000)).isEqualTo(6_400_000_000L);
            assertThat(ImageWriter.memoryNeeded(1, 1)).startsWith("image 1x1 needs 1 MB");
        }

        @Test
        @DisplayName("an image within the heap's limit says how much was free, so the refusal does not read as a contradiction")
        void withinTheLimit() {
            long max = Runtime.getRuntime().maxMemory();
            assumeTrue(max != Long.MAX_VALUE && max < ImageWriter.bytesNeeded(40_000, 40_000), "no heap limit, or one above 6.4 GB");
            int side = (int) Math.sqrt(max / 4.0 * 0.99); // 99 % of the limit: needs less than it
            assertThat(ImageWriter.memoryNeeded(side, side))
                    .matches("image " + side + "x" + side + " needs \\d+ MB; Java may use at most " + (max >> 20)
                            + " MB here, of which about \\d+ MB were free for it \\(the image is one array\\)");
            assertThat(ImageWriter.memoryNeeded(40_000, 40_000)).doesNotContain("free"); // over the limit: the limit says it
        }
    }

    @Nested
    @DisplayName("a scene changed during its render: one clear failure, never a torn image")
    class ConcurrentChange {
        @Test
        @DisplayName("a sphere and a light added mid-render fail it, naming the scene, the image and the change")
        void addedMidRender() throws Exception {
            Scene scene = TestScenes.everyEffect();
            CountDownLatch started = new CountDownLatch(1);
            Camera camera = TestScenes.camera(scene, new ImageWriter("changed", 48, 48))
                    .setAntiAliasing(AntiAliasing.RANDOM, 4, 4).setMultithreading(2)
                    .setDebugPrint(1).setOutput(new PrintStream(new OutputStream() {
                        @Override
                        public void write(int b) {
                            started.countDown();
                        }
                    }, true)).build();
            List<Throwable> thrown = new ArrayList<>();
            Thread renderer = new Thread(() -> {
                try {
                    camera.renderImage();
                } catch (Throwable t) {
                    thrown.add(t);
                }
            }, "changed-scene-render");
            renderer.start();
            assertThat(started.await(20, TimeUnit.SECONDS)).as("render under way").isTrue();
            scene.geometries.add(new Sphere(new Point(0, 0, 5), 1));
            scene.lights.add(new DirectionalLight(new Color(10, 10, 10), new Vector(0, 0, -1)));
            renderer.join(TimeUnit.SECONDS.toMillis(60)); // a liveness guard, not a timing assertion
            assertThat(thrown).hasSize(1);
            assertThat(thrown.get(0)).isInstanceOf(ConcurrentModificationException.class)
                    .hasMessage("the scene 'every-effect' changed during the render of changed: its geometries were added"
                            + " to (1 time) (a scene must not change while it renders; render it again when it is complete)");
        }

        /**
         * A light list read while another thread adds to it can fail as {@code LinkedList.toArray}
         * does when a node arrives after the array was sized; here the list fails that way every
         * time, so the build's count of the lights is seen to turn it into the scene-change failure.
         */
        @Test
        @DisplayName("a light list torn as the build counts it fails with the scene-change message, the torn read as its cause")
        void lightsTornAsTheBuildCountsThem() {
            Scene scene = new Scene("torn");
            scene.geometries.add(plane(0));
            ArrayIndexOutOfBoundsException torn = new ArrayIndexOutOfBoundsException("Index 21 out of bounds for length 21");
            scene.setLights(new java.util.LinkedList<>(List.of(new DirectionalLight(new Color(40, 40, 40), new Vector(0, 0, -1)))) {
                @Override
                public <T> T[] toArray(T[] a) {
                    throw torn;
                }
            });
            Camera.Builder builder = TestScenes.camera(scene, new ImageWriter(4, 4)).setRayTracer(new RayTracerBasic(scene));
            assertThatThrownBy(builder::build).isInstanceOf(ConcurrentModificationException.class)
                    .hasMessage("the scene 'torn' changed while its lights were counted for the ray budget (a camera built on"
                            + " it, or a render starting): its light list was being changed as it was read (a scene must not"
                            + " change while a camera is built on it or renders it; build and render when it is complete)")
                    .hasCause(torn);
        }

        /**
         * Planes facing the camera, each nearer than the last, and directional lights along the
         * view: every consistent state renders one uniform colour, so a torn image shows as two.
         */
        @ParameterizedTest(name = "bvh {0}, shared tracer")
        @ValueSource(booleans = { true, false })
        @DisplayName("renders in a loop while another thread adds shapes and lights: uniform images or the clear failure")
        void tightLoop(boolean bvh) throws Exception {
            Scene scene = new Scene("planes");
            scene.geometries.add(plane(0));
            scene.lights.add(new DirectionalLight(new Color(40, 40, 40), new Vector(0, 0, -1)));
            RayTracerBasic shared = new RayTracerBasic(scene).setBvh(bvh);
            AtomicBoolean done = new AtomicBoolean();
            Thread adder = new Thread(() -> {
                for (int k = 1; k <= 300; ++k) {
                    scene.geometries.add(plane(k));
                    if (k % 10 == 0) scene.lights.add(new DirectionalLight(new Color(k % 50, 5, 5), new Vector(0, 0, -1)));
                    try {
                        Thread.sleep(1);
                    } catch (InterruptedException e) {
                        break;
                    }
                }
                done.set(true);
            }, "scene-adder");
            adder.start();
            int renders = 0, refused = 0;
            for (boolean last = false; !last; ) {
                last = done.get(); // the render after the last change must succeed
                ImageWriter image = new ImageWriter(16, 16);
                ++renders;
                try { // the build counts the lights for the ray budget: it reads the scene too
                    TestScenes.camera(scene, image).setRayTracer(shared).setMultithreading(2).build().renderImage();
                } catch (ConcurrentModificationException e) {
                    assertThat(last).as("a render after the changes ended is refused").isFalse();
                    assertThat(e.getMessage()).matches("the scene 'planes' changed (during the render of \\(unnamed\\)"
                            + "|while its lights were counted for the ray budget .*): .*");
                    ++refused;
                    continue;
                }
                int first = image.getRgb(0, 0);
                for (int y = 0; y < 16; ++y)
                    for (int x = 0; x < 16; ++x)
                        assertThat(image.getRgb(x, y)).as("render %d, pixel (%d,%d): one state only", renders, x, y)
                                .isEqualTo(first);
            }
            adder.join();
            assertThat(refused).isLessThan(renders);
        }

        private static Plane plane(int k) {
            return (Plane) new Plane(new Point(0, 0, k * 0.01), new Vector(0, 0, 1))
                    .setEmission(new Color(k % 200, 50, 100)).setMaterial(new Material().setKd(0.5));
        }
    }
}
