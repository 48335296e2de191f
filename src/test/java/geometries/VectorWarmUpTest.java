package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import primitives.Point;

/**
 * The warm-up that finds the vector walk compiled ({@link Vectorization#COMPILED}): its tree
 * takes every path of the walks, it is not run where the vector code would never be compiled, and
 * it finds the walk compiled in a JVM that compiles it.
 */
@DisplayName("the vector walk's warm-up")
class VectorWarmUpTest {
    /** Prints whether this JVM compiles with the optimizing compiler, for the case below. */
    public static void main(String[] args) {
        System.out.println(VectorWarmUp.optimizingCompiler());
    }

    @ParameterizedTest(name = "at least {0} primitives")
    @ValueSource(ints = { 0, 128, 4096 })
    @DisplayName("warms on a tree of wide nodes over a mesh (leaves in lanes) and spheres (the scalar leaf loop)")
    void everyPath(int minimum) {
        Geometries shapes = VectorWarmUp.shapes(minimum);
        Bvh tree = Bvh.build(shapes, 1, 4096, true, VectorWalk.anyCpu());
        assertThat(tree.wideNodes()).as("wide nodes").isNotNull();
        List<Intersectable> leaves = new ArrayList<>();
        shapes.collectLeaves(leaves);
        assertThat(leaves).as("a mesh and spheres").hasAtLeastOneElementOfType(TriangleMesh.class)
                .hasAtLeastOneElementOfType(Sphere.class);
        assertThat(leaves.stream().filter(TriangleMesh.class::isInstance).mapToInt(m -> ((TriangleMesh) m).triangleCount()).sum())
                .as("triangles").isGreaterThanOrEqualTo(minimum);
    }

    @ParameterizedTest(name = "{0} → {1}")
    @CsvSource(delimiter = '|', value = { "''|true", "-XX:TieredStopAtLevel=1|false", "-Xint|false",
            "-XX:-TieredCompilation|true" })
    @DisplayName("runs only in a JVM whose optimizing compiler compiles vector code")
    void optimizingCompilerOnly(String option, boolean expected) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xshare:off", "-cp", System.getProperty("java.class.path")));
        if (!option.isEmpty()) command.add(option);
        command.add(VectorWarmUpTest.class.getName());
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(out).isZero();
        assertThat(out).isEqualTo(String.valueOf(expected));
    }

    @Test
    @DisplayName("says so once the vector walk runs compiled (this test JVM has the module)")
    void opensTheGate() throws InterruptedException {
        assumeTrue(Vectorization.walk() != null, "no vector walk in this JVM: " + Bvh.walkDescription());
        assumeTrue(VectorWarmUp.optimizingCompiler(), "this JVM does not compile with C2");
        VectorWarmUp.start();
        VectorWarmUp.start(); // once per JVM: a second call starts nothing
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (!Vectorization.COMPILED.get() && System.nanoTime() < deadline) Thread.sleep(20);
        assertThat(Vectorization.COMPILED.get()).as("compiled, within two minutes").isTrue();
        assertThat(Bvh.walkDescription()).matches("[48]-wide vector walk \\(trees of \\d+ primitives or more\\)");

        // A render's tree, large enough, gets its wide part when a long render says so (from JDK
        // 25 on, Vectorization.SWITCHES; before, never); a small one never.
        Bvh large = Bvh.build(new Geometries(BvhTest.gridMesh(60)));
        Bvh small = Bvh.build(new Geometries(new Sphere(new Point(0, 0, 0), 1), new Sphere(new Point(3, 0, 0), 1)));
        assertThat(large.wideNodes()).as("before a long render").isNull();
        large.expectLongWalk();
        small.expectLongWalk();
        if (Runtime.version().feature() >= 25) assertThat(large.wideNodes()).as("after").isNotNull();
        else assertThat(large.wideNodes()).as("after, on JDK %d", Runtime.version().feature()).isNull();
        assertThat(small.wideNodes()).as("a tree below the walk's size").isNull();
    }
}
