package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.BiFunction;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.GeometryLists;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * Course names the 2024–25 and 2025–26 suites use that are a thin spelling of something the
 * library does once: {@code Camera.writeToImage(name)} returning the camera,
 * {@code Builder.rotate(degrees)}, {@code Material.setnShininess} / {@code setNShininess}, and
 * the BVH switches {@code buildBVH()}, {@code makeBVH()}, {@code enableBVH()}.
 */
class CourseNamesTest {
    private static final Vector TO = new Vector(0, 0, -1);

    /** A camera at the origin looking along −z, up +y, so right is +x; 3×3 pixels on a 3×3 plane at distance 1. */
    private static Camera.Builder builder() {
        return Camera.getBuilder().setLocation(Point.ZERO).setDirection(TO, Vector.AXIS_Y).setVpSize(3, 3).setVpDistance(1)
                .setResolution(3, 3).setSummary(false);
    }

    @Nested
    @DisplayName("Camera.writeToImage returns the camera (2024–25), for every spelling")
    class WriteToImage {
        private final Path folder = Path.of("images", "course-names");

        @AfterEach
        void removeImages() throws IOException {
            try (Stream<Path> files = Files.exists(folder) ? Files.list(folder) : Stream.empty()) {
                for (Path f : files.toList()) Files.delete(f);
            }
            Files.deleteIfExists(folder);
        }

        @Test
        @DisplayName("renderImage().writeToImage(name) chains and writes images/<name>.png")
        void named() {
            Camera camera = builder().build();
            Camera written = camera.renderImage().writeToImage("course-names/chained");
            assertThat(written).isSameAs(camera);
            assertThat(folder.resolve("chained.png")).isRegularFile();
        }

        @Test
        @DisplayName("renderImage().writeToImage() (2023–24: the writer's name) returns the camera too")
        void writersName() {
            Camera camera = builder().setImageWriter(new ImageWriter("course-names/own", 3, 3)).build();
            assertThat(camera.renderImage().writeToImage()).isSameAs(camera);
            assertThat(folder.resolve("own.png")).isRegularFile();
        }

        @Test
        @DisplayName("a blank name is still refused, naming the fault")
        void blank() {
            assertThatIllegalArgumentException().isThrownBy(() -> builder().build().writeToImage(" "))
                    .withMessage("image name must not be blank");
        }
    }

    @Nested
    @DisplayName("Builder.rotate(degrees): the camera turns about its view direction (2025–26)")
    class Rotate {
        private static void assertVector(Vector actual, double x, double y, double z) {
            assertThat(new double[] { actual.getX(), actual.getY(), actual.getZ() })
                    .containsExactly(new double[] { x, y, z }, org.assertj.core.api.Assertions.within(1e-12));
        }

        @ParameterizedTest(name = "rotate({0}): up = ({1}, {2}, 0), right = ({3}, {4}, 0)")
        @CsvSource({
                "0,    0, 1,  1, 0",
                "90,   1, 0,  0, -1",
                "180,  0, -1, -1, 0",
                "270, -1, 0,  0, 1",
                "-90, -1, 0,  0, 1",
                "360,  0, 1,  1, 0",
                "450,  1, 0,  0, -1",
                "45,   0.7071067811865476, 0.7071067811865476, 0.7071067811865476, -0.7071067811865476" })
        @DisplayName("a positive angle takes up toward right (right-hand rule about the view direction)")
        void frame(int degrees, double upX, double upY, double rightX, double rightY) {
            Camera camera = builder().rotate(degrees).build();
            assertVector(camera.getVUp(), upX, upY, 0);
            assertVector(camera.getVRight(), rightX, rightY, 0);
            assertVector(camera.getVTo(), 0, 0, -1);
        }

        @Test
        @DisplayName("multiples of 90 are exact: rotate(90)'s up is the old right, bit for bit")
        void exactQuarterTurns() {
            Camera plain = builder().build(), turned = builder().rotate(90).build();
            assertThat(turned.getVUp()).isEqualTo(plain.getVRight());
            assertThat(turned.getVUp().getY()).isZero();
            assertThat(builder().rotate(360).build().getVUp().getX()).isZero();
        }

        @Test
        @DisplayName("the rays turn with it: the top middle pixel looks to the old right after rotate(90)")
        void rays() {
            Ray top = builder().rotate(90).build().constructRay(1, 0);
            assertVector(top.getDirection(), Math.sqrt(0.5), 0, -Math.sqrt(0.5));
            Ray left = builder().rotate(90).build().constructRay(0, 1);
            assertVector(left.getDirection(), 0, Math.sqrt(0.5), -Math.sqrt(0.5));
        }

        @Test
        @DisplayName("rotate(0) leaves every ray bit for bit as without it")
        void zeroChangesNothing() {
            Camera plain = builder().build(), zero = builder().rotate(0).build();
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    assertThat(zero.constructRay(j, i).getDirection()).isEqualTo(plain.constructRay(j, i).getDirection());
        }

        @Test
        @DisplayName("calls add up, and the turn applies to a direction set before or after it, target form included")
        void composesWhateverTheOrder() {
            Vector up = builder().rotate(90).build().getVUp();
            assertThat(builder().rotate(30).rotate(60).build().getVUp()).isEqualTo(up);
            assertThat(builder().rotate(90).setDirection(TO, Vector.AXIS_Y).build().getVUp()).isEqualTo(up);
            Camera looking = Camera.getBuilder().setLocation(Point.ZERO).setDirection(new Point(0, 0, -5)).rotate(90)
                    .setVpSize(3, 3).setVpDistance(1).build();
            assertThat(looking.getVUp()).isEqualTo(up);
        }

        @Test
        @DisplayName("a builder copied from a rotated camera keeps its frame and does not turn it again")
        void copy() {
            Camera turned = builder().rotate(90).build();
            assertThat(Camera.getBuilder(turned).build().getVUp()).isEqualTo(turned.getVUp());
        }
    }

    /** A course spelling of the shininess setter. */
    private record ShininessSetter(String name, BiFunction<Material, Integer, Material> set) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<ShininessSetter> shininessSetters() {
        return Stream.of(new ShininessSetter("setShininess", Material::setShininess),
                new ShininessSetter("setnShininess", Material::setnShininess),
                new ShininessSetter("setNShininess", Material::setNShininess));
    }

    @Nested
    @DisplayName("Material.setnShininess / setNShininess: the spellings of setShininess")
    class Shininess {
        @ParameterizedTest(name = "{0} sets nShininess and returns the material")
        @MethodSource("renderer.CourseNamesTest#shininessSetters")
        void sets(ShininessSetter setter) {
            Material m = new Material();
            assertThat(setter.set().apply(m, 42)).isSameAs(m);
            assertThat(m.nShininess).isEqualTo(42);
        }

        @ParameterizedTest(name = "{0} refuses a negative exponent, naming it")
        @MethodSource("renderer.CourseNamesTest#shininessSetters")
        void refuses(ShininessSetter setter) {
            assertThatIllegalArgumentException().isThrownBy(() -> setter.set().apply(new Material(), -3))
                    .withMessage("shininess must be non-negative, got -3");
        }
    }

    /** A BVH switch, with what it must return for the scene it is called on. */
    private record Switch(String name, Function<Scene, Object> call, Function<Scene, Object> receiver) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Arguments> bvhSwitches() {
        return Stream.of(new Switch("scene.buildBVH()", Scene::buildBVH, s -> s),
                new Switch("scene.makeBVH()", Scene::makeBVH, s -> s),
                new Switch("scene.enableBVH()", Scene::enableBVH, s -> s),
                new Switch("geometries.buildBVH()", s -> s.geometries.buildBVH(), s -> s.geometries),
                new Switch("geometries.makeBVH()", s -> s.geometries.makeBVH(), s -> s.geometries),
                new Switch("geometries.enableBVH()", s -> s.geometries.enableBVH(), s -> s.geometries))
                .map(Arguments::of);
    }

    /** A camera spelling of another year, and the library's name it must equal. */
    private record Spelling(String name, UnaryOperator<Camera.Builder> alias, UnaryOperator<Camera.Builder> same) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Arguments> cameraSpellings() {
        return Stream.of(new Spelling("setViewPlaneSize(3, 2)", b -> b.setViewPlaneSize(3, 2), b -> b.setVpSize(3, 2)),
                new Spelling("setViewPlaneDistance(7)", b -> b.setViewPlaneDistance(7), b -> b.setVpDistance(7)),
                new Spelling("setDofRays(9)", b -> b.setDepthOfField(5, 0.5).setDofRays(9),
                        b -> b.setDepthOfField(5, 0.5).setDepthOfFieldSamples(9)),
                new Spelling("enableBVH()", Camera.Builder::enableBVH, b -> b),
                new Spelling("enableCBR()", Camera.Builder::enableCBR, b -> b))
                .map(Arguments::of);
    }

    @Nested
    @DisplayName("camera spellings of other course projects: setViewPlaneSize/Distance, setDofRays, enableBVH/CBR")
    class CameraSpellings {
        @ParameterizedTest(name = "{0} renders the same image as the library's name, with the same values")
        @MethodSource("renderer.CourseNamesTest#cameraSpellings")
        void same(Spelling spelling) {
            ImageWriter expected = new ImageWriter("expected", 16, 12), actual = new ImageWriter("actual", 16, 12);
            Camera a = spelling.alias().apply(TestScenes.camera(TestScenes.everyEffect(), actual)).build().renderImage();
            Camera b = spelling.same().apply(TestScenes.camera(TestScenes.everyEffect(), expected)).build().renderImage();
            assertThat(CameraValues.of(a)).isEqualTo(CameraValues.of(b));
            assertThat(a.view()).usingRecursiveComparison().isEqualTo(b.view());
            assertThat(Pixels.of(actual)).isEqualTo(Pixels.of(expected));
        }
    }

    @Nested
    @DisplayName("the BVH switches buildBVH / makeBVH / enableBVH: documented no-ops, the BVH being always on")
    class BvhSwitches {
        @ParameterizedTest(name = "{0} returns its receiver and changes neither the scene nor the image")
        @MethodSource("renderer.CourseNamesTest#bvhSwitches")
        void noOp(Switch bvh) {
            Scene plain = TestScenes.everyEffect(), switched = TestScenes.everyEffect();
            long changes = GeometryLists.changeCount(switched.geometries);
            assertThat(bvh.call().apply(switched)).isSameAs(bvh.receiver().apply(switched));
            assertThat(GeometryLists.changeCount(switched.geometries)).as("not a change for the scene-change check").isEqualTo(changes);

            ImageWriter expected = new ImageWriter("expected", 16, 12), actual = new ImageWriter("actual", 16, 12);
            TestScenes.camera(plain, expected).build().renderImage();
            Camera camera = TestScenes.camera(switched, actual).build().renderImage();
            assertThat(Pixels.of(actual)).isEqualTo(Pixels.of(expected));
            assertThat(CameraValues.of(camera).tracer().bvh()).as("the tracer's BVH stays on, as by default").isTrue();
        }
    }
}
