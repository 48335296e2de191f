package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import primitives.Point;

/**
 * The leaf layout of the vector leaf test ({@link TriangleLanes}): which leaves are laid out in
 * lanes, where each number goes, and that a tree marks exactly those leaves.
 */
@DisplayName("triangle leaves in lanes")
class TriangleLanesTest {
    private static final byte T = BvhLeaf.TRIANGLE, S = BvhLeaf.SPHERE, O = BvhLeaf.OWN;

    @Nested
    @DisplayName("which leaves")
    class Which {
        @Test
        @DisplayName("one to four triangles fit")
        void upToFourTriangles() {
            byte[] kind = { T, T, T, T, T };
            for (int count = 1; count <= 4; ++count) assertThat(TriangleLanes.fits(kind, 0, count)).as("%d", count).isTrue();
        }

        @Test
        @DisplayName("five triangles, or any sphere or shape of its own among them, do not")
        void notMoreNorOthers() {
            assertThat(TriangleLanes.fits(new byte[] { T, T, T, T, T }, 0, 5)).isFalse();
            assertThat(TriangleLanes.fits(new byte[] { T, S }, 0, 2)).isFalse();
            assertThat(TriangleLanes.fits(new byte[] { O, T }, 0, 2)).isFalse();
            assertThat(TriangleLanes.fits(new byte[] { O, T, T }, 1, 2)).as("only the leaf's own primitives count").isTrue();
        }
    }

    @Nested
    @DisplayName("where each number goes")
    class Where {
        /** Packed numbers that say where they came from: primitive k's number r is 100k + r. */
        private double[] numbered(int primitives) {
            double[] packed = new double[primitives * BvhLeaf.PACKED + TriangleLanes.PADDING];
            for (int k = 0; k < primitives; ++k)
                for (int r = 0; r < BvhLeaf.PACKED; ++r) packed[k * BvhLeaf.PACKED + r] = 100 * k + r;
            return packed;
        }

        @Test
        @DisplayName("a lane leaf holds number r of its triangle j at first·9 + r·count + j, in its own place; other leaves are untouched")
        void transposedInPlace() {
            // Leaves: [0, 3) triangles, [3, 5) a triangle and a sphere, [5, 9) triangles, [9, 10) a triangle.
            byte[] kind = { T, T, T, T, S, T, T, T, T, T };
            float[] node = BvhNodes.allocate(4);
            BvhNodes.writeLeaf(node, BvhNodes.at(0), 0, 3);
            BvhNodes.writeLeaf(node, BvhNodes.at(1), 3, 2);
            BvhNodes.writeLeaf(node, BvhNodes.at(2), 5, 4);
            BvhNodes.writeLeaf(node, BvhNodes.at(3), 9, 1);
            double[] packed = numbered(kind.length), before = packed.clone();
            TriangleLanes.arrange(node, 4, kind, packed);
            int[][] lanes = { { 0, 3 }, { 5, 4 }, { 9, 1 } };
            for (int[] leaf : lanes) {
                int first = leaf[0], count = leaf[1];
                for (int j = 0; j < count; ++j)
                    for (int r = 0; r < BvhLeaf.PACKED; ++r)
                        assertThat(packed[TriangleLanes.row(first, count, r) + j]).as("leaf from %d: triangle %d, number %d", first, j, r)
                                .isEqualTo(100 * (first + j) + r);
            }
            for (int i = 3 * BvhLeaf.PACKED; i < 5 * BvhLeaf.PACKED; ++i)
                assertThat(packed[i]).as("the mixed leaf's number %d", i).isEqualTo(before[i]);
        }

        @Test
        @DisplayName("a leaf of one triangle is the same numbers in the same places")
        void oneTriangleUnchanged() {
            double[] packed = numbered(1), before = packed.clone();
            float[] node = BvhNodes.allocate(1);
            BvhNodes.writeLeaf(node, BvhNodes.at(0), 0, 1);
            TriangleLanes.arrange(node, 1, new byte[] { T }, packed);
            assertThat(packed).containsExactly(before);
        }
    }

    @Nested
    @DisplayName("the tree")
    class Tree {
        @Test
        @DisplayName("marks the lane leaves and only those: a mesh's in lanes, a scene of spheres and triangles in scalar leaves where they mix")
        void marksWhatFits() {
            Geometries g = new Geometries(BvhTest.gridMesh(12));
            for (int i = 0; i < 40; ++i) g.add(new Sphere(new Point(i * 0.3, 1.5, 6), 0.2));
            Bvh tree = Bvh.build(g, 1, 4096, true, VectorWalk.anyCpu());
            WideNodes wide = tree.wideNodes();
            int shift = Integer.numberOfTrailingZeros(wide.width), lanes = 0, scalar = 0;
            for (int item = 0; item < wide.count * wide.width; ++item) {
                int count = WideNodes.count(wide.node, item, shift);
                if (count < 0) ++lanes;
                if (count > 0) ++scalar;
            }
            assertThat(lanes).as("leaves of the mesh's triangles").isPositive();
            assertThat(scalar).as("leaves with spheres").isPositive();
        }

        @Test
        @DisplayName("lays them out in a copy, beside the scalar layout: 72 bytes a primitive more, and the wide nodes")
        void copyBytes() {
            Geometries g = new Geometries(BvhTest.gridMesh(20));
            Bvh scalar = Bvh.build(g, 1, 4096, true, null), vector = Bvh.build(g, 1, 4096, true, VectorWalk.anyCpu());
            assertThat(vector.indexBytes() - scalar.indexBytes())
                    .isEqualTo(vector.wideNodes().bytes() + scalar.primitiveTotal() * (long) BvhLeaf.PACKED * Double.BYTES);
        }
    }
}
