package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

@DisplayName("BuildBoxes: the build's boxes as six doubles, bounds as a box and a centroids' box")
class BuildBoxesTest {
    @Nested
    @DisplayName("an empty box")
    class Empty {
        @Test
        @DisplayName("becomes the box of the first point it grows by")
        void growsToPoint() {
            double[] b = new double[BuildBoxes.BOX_SIZE];
            BuildBoxes.empty(b, 0);
            BuildBoxes.growToPoint(b, 0, new double[] { 1, -2, 3 }, 0);
            assertThat(b).containsExactly(1, -2, 3, 1, -2, 3);
        }

        @Test
        @DisplayName("leaves a box it grows by unchanged")
        void growsToBox() {
            double[] b = new double[1 + BuildBoxes.BOX_SIZE];
            BuildBoxes.empty(b, 1);
            BuildBoxes.grow(b, 1, new double[] { 9, 0, 1, 2, 3, 4, 5 }, 1);
            assertThat(b).containsExactly(0, 0, 1, 2, 3, 4, 5);
        }
    }

    @Test
    @DisplayName("bounds unite box with box and centroids' box with centroids' box, at their named offsets")
    void boundsUnite() {
        double[] a = new double[BuildBoxes.BOUNDS], b = new double[BuildBoxes.BOUNDS];
        BuildBoxes.set(a, BuildBoxes.BOX, 0, 0, 0, 1, 1, 1);
        BuildBoxes.set(a, BuildBoxes.CENTROIDS, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5);
        BuildBoxes.set(b, BuildBoxes.BOX, -1, 2, 0, 0, 3, 4);
        BuildBoxes.set(b, BuildBoxes.CENTROIDS, -0.5, 2.5, 2, -0.5, 2.5, 2);
        BuildBoxes.growBounds(a, 0, b, 0);
        assertThat(a).containsExactly(-1, 0, 0, 1, 3, 4, -0.5, 0.5, 0.5, 0.5, 2.5, 2);
    }

    @Test
    @DisplayName("the half area is the sum of the three face areas, of a box or of extents")
    void halfArea() {
        double[] b = { 1, 1, 1, 3, 4, 5 };
        assertThat(BuildBoxes.halfArea(b, 0)).isEqualTo(2 * 3 + 3 * 4 + 4 * 2).isEqualTo(BuildBoxes.halfArea(2, 3, 4));
        assertThat(BuildBoxes.extent(b, 0, 2)).isEqualTo(4);
    }
}
