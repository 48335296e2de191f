package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

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
        @ParameterizedTest(name = "{0} lanes")
        @ValueSource(ints = { 4, 8 })
        @DisplayName("one triangle up to as many as the lanes fit")
        void upToTheLanes(int lanes) {
            byte[] kind = { T, T, T, T, T, T, T, T, T };
            for (int count = 1; count <= lanes; ++count) assertThat(TriangleLanes.fits(kind, 0, count, lanes)).as("%d", count).isTrue();
            assertThat(TriangleLanes.fits(kind, 0, lanes + 1, lanes)).as("one more").isFalse();
        }

        @Test
        @DisplayName("any sphere or shape of its own among them does not")
        void notOthers() {
            assertThat(TriangleLanes.fits(new byte[] { T, S }, 0, 2, 4)).isFalse();
            assertThat(TriangleLanes.fits(new byte[] { O, T }, 0, 2, 4)).isFalse();
            assertThat(TriangleLanes.fits(new byte[] { O, T, T }, 1, 2, 4)).as("only the leaf's own primitives count").isTrue();
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

        @ParameterizedTest(name = "{0} triangles")
        @ValueSource(ints = { 2, 3, 4, 5, 8 })
        @DisplayName("a lane leaf holds number r of its triangle j at first·9 + r·count + j, in its own place; the rest is untouched")
        void transposedInPlace(int count) {
            int first = 2;
            double[] packed = numbered(first + count + 1), before = packed.clone();
            TriangleLanes.arrange(packed, first, count, new double[TriangleLanes.MAX_LANES * BvhLeaf.PACKED]);
            for (int j = 0; j < count; ++j)
                for (int r = 0; r < BvhLeaf.PACKED; ++r)
                    assertThat(packed[TriangleLanes.row(first, count, r) + j]).as("triangle %d, number %d", j, r)
                            .isEqualTo(100 * (first + j) + r);
            for (int i = 0; i < packed.length; ++i)
                if (i < first * BvhLeaf.PACKED || i >= (first + count) * BvhLeaf.PACKED)
                    assertThat(packed[i]).as("number %d, outside the leaf", i).isEqualTo(before[i]);
        }

        @Test
        @DisplayName("a leaf of one triangle is the same numbers in the same places")
        void oneTriangleUnchanged() {
            double[] packed = numbered(1), before = packed.clone();
            TriangleLanes.arrange(packed, 0, 1, new double[TriangleLanes.MAX_LANES * BvhLeaf.PACKED]);
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
            int lanes = 0, scalar = 0;
            for (int item = 0; item < wide.count * wide.width; ++item) {
                int count = WideNodes.count(wide.node, wide.slot(item), wide.width);
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

        @ParameterizedTest(name = "{0} lanes")
        @ValueSource(ints = { 4, 8 })
        @DisplayName("a lane leaf is a whole subtree of at most that many triangles: each triangle in exactly one, larger than the builder's leaves")
        void wholeSubtrees(int lanes) {
            Bvh tree = Bvh.build(new Geometries(BvhTest.gridMesh(20)), 1, 4096, true, new Lanes(lanes));
            WideNodes wide = tree.wideNodes();
            int[] seen = new int[tree.primitiveTotal()];
            int leaves = 0, triangles = 0, largest = 0;
            for (int item = 0; item < wide.count * wide.width; ++item) {
                int count = -WideNodes.count(wide.node, wide.slot(item), wide.width), first = WideNodes.link(wide.node, wide.slot(item), wide.width);
                if (count <= 0) continue;
                ++leaves;
                triangles += count;
                largest = Math.max(largest, count);
                for (int j = 0; j < count; ++j) ++seen[first + j];
            }
            assertThat(seen).as("every triangle in exactly one lane leaf").containsOnly(1);
            assertThat(largest).as("the largest lane leaf").isLessThanOrEqualTo(lanes);
            // The builder's leaves hold about two triangles (BENCHMARKS.md): whole subtrees hold more.
            assertThat((double) triangles / leaves).as("triangles per lane leaf").isGreaterThan(lanes / 2.0);
        }
    }

    /** A wide walk that only says its widths: for the layout, never walked. */
    private record Lanes(int leafLanes) implements WideWalk {
        @Override
        public int width() {
            return 4;
        }

        @Override
        public int minPrimitives() {
            return 0;
        }

        @Override
        public String description() {
            return "lanes " + leafLanes;
        }

        @Override
        public boolean closestHit(Bvh tree, float[] node, double[] lanes, Hit hit, int[] stack, double[] stackT) {
            throw new UnsupportedOperationException();
        }

        @Override
        public boolean visitHits(Bvh tree, float[] node, double[] lanes, Hit query, double limit, double maxDistance,
                                 HitVisitor visitor, int[] stack) {
            throw new UnsupportedOperationException();
        }
    }
}
