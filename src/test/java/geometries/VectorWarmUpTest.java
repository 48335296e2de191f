package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
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
    /**
     * Without arguments, prints whether this JVM compiles with the optimizing compiler; with
     * {@code gate}, starts the warm-up, waits for it (up to two minutes) and prints what the case
     * {@link #opensTheGate} checks, one fact a line.
     */
    public static void main(String[] args) throws InterruptedException {
        if (args.length == 0) {
            System.out.println(VectorWarmUp.optimizingCompiler());
            return;
        }
        VectorWarmUp.start();
        VectorWarmUp.start(); // once per JVM: a second call starts nothing
        long deadline = System.nanoTime() + TimeUnit.MINUTES.toNanos(2);
        while (!Vectorization.COMPILED.get() && System.nanoTime() < deadline) Thread.sleep(20);
        System.out.println("compiled: " + Vectorization.COMPILED.get());
        System.out.println("walk: " + Bvh.walkDescription());
        // A render's tree, large enough, gets its wide part when a long render says so; a small one never.
        Bvh large = Bvh.build(new Geometries(BvhTest.gridMesh(60)));
        Bvh small = Bvh.build(new Geometries(new Sphere(new Point(0, 0, 0), 1), new Sphere(new Point(3, 0, 0), 1)));
        System.out.println("large tree wide before a long render: " + (large.wideNodes() != null));
        large.expectLongWalk();
        small.expectLongWalk();
        System.out.println("large tree wide after: " + (large.wideNodes() != null));
        System.out.println("small tree wide after: " + (small.wideNodes() != null));
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
        String out = FreshJvm.run(VectorWarmUpTest.class, option.isEmpty() ? List.of() : List.of(option));
        assertThat(out).isEqualTo(String.valueOf(expected));
    }

    @Test
    @DisplayName("says so once the vector walk runs compiled, in a fresh JVM with the module")
    void opensTheGate() throws IOException, InterruptedException {
        assumeTrue(Vectorization.walk() != null, "no vector walk on this CPU or JVM: " + Bvh.walkDescription());
        assumeTrue(VectorWarmUp.optimizingCompiler(), "this JVM does not compile with C2");
        // In a JVM of its own (FreshJvm says why); COMPILED is once per JVM as well.
        List<String> facts = FreshJvm.run(VectorWarmUpTest.class, FreshJvm.withVectorModule(), "gate").lines().toList();
        assertThat(facts).hasSize(5);
        assertThat(facts.get(0)).isEqualTo("compiled: true");
        assertThat(facts.get(1)).matches("walk: [48]-wide vector walk \\(trees of \\d+ primitives or more\\)");
        assertThat(facts.subList(2, 5)).containsExactly("large tree wide before a long render: false",
                "large tree wide after: true", "small tree wide after: false");
    }
}
