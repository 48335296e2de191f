package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link BvhNodes}: what the builder writes into a node record the walks read back, unchanged,
 * for links as large as a tree can have, and records never overlap.
 */
class BvhNodesTest {
    /** The largest link a tree of fewer than 2³⁰ nodes writes; its bits are no NaN pattern. */
    private static final int LARGEST = (1 << 30) - 1;

    @ParameterizedTest(name = "first {0}")
    @ValueSource(ints = { 0, 1, 12345, LARGEST })
    @DisplayName("a leaf: its first primitive and count (> 0), and the node after it is the next one")
    void leaf(int first) {
        float[] nd = BvhNodes.allocate(3);
        int at = BvhNodes.at(1);
        BvhNodes.writeLeaf(nd, at, first, 4);
        assertThat(BvhNodes.count(nd, at)).isEqualTo(4);
        assertThat(BvhNodes.first(nd, at)).isEqualTo(first);
        assertThat(BvhNodes.skip(BvhNodes.count(nd, at), 1)).isEqualTo(2);
    }

    @ParameterizedTest(name = "right child {0}")
    @ValueSource(ints = { 2, 7, 12345, LARGEST })
    @DisplayName("an inner node: no positive count, its right child, and its skip link past its subtree")
    void inner(int right) {
        float[] nd = BvhNodes.allocate(3);
        int at = BvhNodes.at(0);
        BvhNodes.writeInner(nd, at, right, right + 5);
        assertThat(BvhNodes.count(nd, at)).isNotPositive();
        assertThat(BvhNodes.right(nd, at)).isEqualTo(right);
        assertThat(BvhNodes.skip(BvhNodes.count(nd, at), 0)).isEqualTo(right + 5);
    }

    @Test
    @DisplayName("the box reads back per axis, and writing one record leaves its neighbours alone")
    void boxesAndNeighbours() {
        float[] nd = BvhNodes.allocate(3);
        BvhNodes.writeLeaf(nd, BvhNodes.at(0), 1, 2);
        BvhNodes.writeInner(nd, BvhNodes.at(2), 3, 4);
        float[] box = { -1, -2, -3, 4, 5, 6 };
        BvhNodes.writeBox(nd, BvhNodes.at(1), box, 0);
        BvhNodes.writeLeaf(nd, BvhNodes.at(1), 9, 1);
        int at = BvhNodes.at(1);
        assertThat(new float[] { BvhNodes.min(nd, at, BvhNodes.X), BvhNodes.min(nd, at, BvhNodes.Y),
                BvhNodes.min(nd, at, BvhNodes.Z), BvhNodes.max(nd, at, BvhNodes.X), BvhNodes.max(nd, at, BvhNodes.Y),
                BvhNodes.max(nd, at, BvhNodes.Z) }).containsExactly(box);
        assertThat(BvhNodes.first(nd, BvhNodes.at(0))).isEqualTo(1);
        assertThat(BvhNodes.count(nd, BvhNodes.at(0))).isEqualTo(2);
        assertThat(BvhNodes.right(nd, BvhNodes.at(2))).isEqualTo(3);
        assertThat(BvhNodes.skip(BvhNodes.count(nd, BvhNodes.at(2)), 2)).isEqualTo(4);
        assertThat(BvhNodes.bytes(3)).as("32 bytes a node").isEqualTo(96);
    }
}
