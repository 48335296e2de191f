package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The builder's product, node by node: every box is the exact union of the padded boxes of the
 * primitives under it, rounded outward to floats, and no more. The builder takes a split's two
 * boxes from its search's bin sweeps rather than from the partition; this holds it to the boxes a
 * primitive-by-primitive union gives.
 */
@DisplayName("BvhBuilder: each node's box is its primitives' union")
class BvhBuilderTest {

    static Stream<Arguments> builds() {
        // Every search scene on one thread and with a task per node, with and without the direct
        // search of pairs: the boxes come from the binned sweeps, the pair search and the halving
        // of coincident centroids.
        return BvhTest.searchScenes().flatMap(scene -> Stream.of(
                Arguments.of(scene.get()[0], 1, 1 << 20, true),
                Arguments.of(scene.get()[0], 2, 1, true),
                Arguments.of(scene.get()[0], 1, 1 << 20, false)));
    }

    @ParameterizedTest(name = "{0}, {1} thread(s), tasks above {2}, pairs {3}")
    @MethodSource("builds")
    @DisplayName("every node's box is the union of its primitives' padded boxes, rounded outward, exactly")
    void nodeBoxesAreExactUnions(BvhTest.Scene scene, int threads, int forkAbove, boolean pairs) {
        List<Intersectable> leaves = new ArrayList<>();
        scene.geometries().collectLeaves(leaves);
        BvhBuilder built = BvhBuilder.index(leaves.toArray(new Intersectable[0]), threads, forkAbove, pairs);
        assertThat(built.nodes).isGreaterThan(1);
        int[] checked = new int[1];
        checkSubtree(built, 0, checked);
        assertThat(checked[0]).as("nodes checked").isEqualTo(built.nodes);
    }

    /**
     * Checks node {@code n} and its subtree.
     *
     * @return the exact union of the subtree's primitives' padded boxes
     */
    private static BoundingBox checkSubtree(BvhBuilder built, int n, int[] checked) {
        float[] nd = built.node;
        int at = BvhNodes.at(n);
        BoundingBox union;
        if (BvhNodes.count(nd, at) > 0) {
            int first = BvhNodes.first(nd, at);
            union = null;
            for (int k = first; k < first + BvhNodes.count(nd, at); ++k) {
                BoundingBox box = primitiveBox(built.owner[k], built.prim[k]);
                union = union == null ? box : union.union(box);
            }
        } else {
            union = checkSubtree(built, n + 1, checked).union(checkSubtree(built, BvhNodes.right(nd, at), checked));
        }
        double[] low = { union.getMinX(), union.getMinY(), union.getMinZ() };
        double[] high = { union.getMaxX(), union.getMaxY(), union.getMaxZ() };
        for (int a = 0; a < 3; ++a) {
            assertThat(BvhNodes.min(nd, at, a)).as("node %d, low bound on axis %d", n, a).isEqualTo(BvhNodes.floatBelow(low[a]));
            assertThat(BvhNodes.max(nd, at, a)).as("node %d, high bound on axis %d", n, a).isEqualTo(BvhNodes.floatAbove(high[a]));
        }
        ++checked[0];
        return union;
    }

    /** The padded box the builder starts from: a one-primitive shape's own box, or one primitive's of a mesh. */
    private static BoundingBox primitiveBox(Intersectable owner, int index) {
        BoundingBox box = owner.primitiveCount() == 1 ? owner.getBoundingBox() : owner.primitiveBounds(index);
        return box.padded();
    }
}
