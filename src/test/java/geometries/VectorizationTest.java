package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Point;

/**
 * Which walk a JVM gets, decided once per JVM (so each case is a JVM of its own): the vector walk
 * only where {@code jdk.incubator.vector} is readable, and then not before it is compiled (a
 * fresh JVM says so) unless {@code -Draytracer.simd=true} asks for it from the first ray; the
 * scalar walk otherwise, and {@code -Draytracer.simd=false} wins over the module.
 */
class VectorizationTest {
    /** Prints this JVM's walk, or with "trees" whether trees of 648 and 450 triangles are wide when built, for the cases below. */
    public static void main(String[] args) {
        if (args.length == 0) {
            System.out.println(Bvh.walkDescription());
            return;
        }
        Bvh teapotSized = Bvh.build(new Geometries(BvhTest.gridMesh(18)));
        Bvh smaller = Bvh.build(new Geometries(BvhTest.gridMesh(15)));
        System.out.println((teapotSized.wideNodes() != null) + " " + (smaller.wideNodes() != null));
    }

    @ParameterizedTest(name = "{0} camera rays")
    @ValueSource(longs = { 1, Vectorization.FIRST_RAY_CAMERA_RAYS - 1, Vectorization.FIRST_RAY_CAMERA_RAYS })
    @DisplayName("a render long from the start gives a tree of 4096 primitives or more the vector walk from its"
            + " first ray, on every JDK; smaller trees, and shorter renders, keep the scalar walk")
    void firstRayRule(long cameraRays) {
        assumeTrue(Vectorization.walk() != null, "no vector walk in this JVM: " + Bvh.walkDescription());
        Bvh large = Bvh.build(new Geometries(BvhTest.gridMesh(60)));
        Bvh small = Bvh.build(new Geometries(new Sphere(new Point(0, 0, 0), 1), new Sphere(new Point(3, 0, 0), 1)));
        assertThat(large.primitiveTotal()).isGreaterThanOrEqualTo(Vectorization.MIN_PRIMITIVES);
        large.expectCameraRays(cameraRays);
        small.expectCameraRays(cameraRays);
        boolean wide = cameraRays >= Vectorization.FIRST_RAY_CAMERA_RAYS;
        assertThat(large.wideNodes() != null).as("the large tree widened").isEqualTo(wide);
        assertThat(small.wideNodes()).as("a tree below the walk's size").isNull();
        if (wide) assertThat(large.describeWalk()).matches("[48]-wide vector walk \\(trees of \\d+ primitives or more\\)");
        else assertThat(large.describeWalk()).isEqualTo(Bvh.walkDescription());
    }

    @ParameterizedTest(name = "{0} → {1}")
    @CsvSource(delimiter = '|', value = {
            "''|scalar walk (no jdk.incubator.vector)",
            "--add-modules jdk.incubator.vector|scalar walk (the vector walk is not compiled: a short render or a JVM without the optimizing compiler)",
            "--add-modules jdk.incubator.vector -XX:TieredStopAtLevel=1|scalar walk (the vector walk is not compiled: a short render or a JVM without the optimizing compiler)",
            "--add-modules jdk.incubator.vector -Draytracer.simd=true|-wide vector walk",
            "--add-modules jdk.incubator.vector -Draytracer.simd=false|scalar walk (-Draytracer.simd=false)",
            "-Draytracer.simd=true|scalar walk (no jdk.incubator.vector)"})
    void walkOfTheJvm(String options, String expected) throws IOException, InterruptedException {
        List<String> jvmOptions = new ArrayList<>();
        for (String o : options.split(" ")) if (!o.isEmpty()) jvmOptions.add(o);
        String out = FreshJvm.run(VectorizationTest.class, jvmOptions);
        assertThat(out).as("the summary line's last words, after its last comma").doesNotContain(",");
        if (expected.startsWith("-wide")) assertThat(out).matches("[48]" + expected + " \\(trees of \\d+ primitives or more\\)");
        else assertThat(out).isEqualTo(expected);
    }

    @ParameterizedTest(name = "{0} → {1}")
    @CsvSource(delimiter = '|', value = { "-Draytracer.simd=true|true false", "''|false false" })
    @DisplayName("asked for with -Draytracer.simd=true, the vector walk takes trees from 512 primitives at their build;"
            + " unasked, a tree below 4096 keeps the scalar walk")
    void askedTakesSmallerTrees(String option, String expected) throws IOException, InterruptedException {
        assumeTrue(Vectorization.walk() != null, "no vector walk in this JVM: " + Bvh.walkDescription());
        assertThat(2 * 18 * 18).isBetween(Vectorization.ASKED_MIN_PRIMITIVES, Vectorization.MIN_PRIMITIVES - 1);
        assertThat(2 * 15 * 15).isLessThan(Vectorization.ASKED_MIN_PRIMITIVES);
        String out = FreshJvm.run(VectorizationTest.class, option.isEmpty() ? FreshJvm.withVectorModule()
                : FreshJvm.withVectorModule(option), "trees");
        assertThat(out).isEqualTo(expected);
    }
}
