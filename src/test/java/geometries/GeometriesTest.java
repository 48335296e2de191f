package geometries;

import static geometries.Hits.assertHits;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatNullPointerException;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * The flat composite. The equivalence classes are the course's: empty, none hit, some hit, all
 * hit; the scene is a sphere, a triangle and a plane stacked along the z axis.
 */
class GeometriesTest {
    private final Sphere sphere = new Sphere(new Point(0, 0, 5), 1); // z 4..6
    private final Triangle triangle = new Triangle(new Point(-1, -1, 2), new Point(3, -1, 2), new Point(-1, 3, 2)); // z 2
    private final Plane plane = new Plane(new Point(0, 0, 0), new Vector(0, 0, 1)); // z 0
    private final Geometries all = new Geometries(sphere, triangle, plane);
    private static final Vector DOWN = new Vector(0, 0, -1);

    @Nested
    @DisplayName("intersections")
    class Intersections {
        @Test
        @DisplayName("an empty collection: null")
        void empty() {
            assertHits(new Geometries(), new Ray(new Point(0, 0, 10), DOWN));
            assertThat(new Geometries().isEmpty()).isTrue();
        }

        @Test
        @DisplayName("no shape is hit: null")
        void noneHit() {
            assertHits(all, new Ray(new Point(0, 0, 10), new Vector(0, 0, 1)));
        }

        @Test
        @DisplayName("some shapes are hit (the sphere is missed)")
        void someHit() {
            assertHits(all, new Ray(new Point(2, -0.5, 10), DOWN), new Point(2, -0.5, 2), new Point(2, -0.5, 0));
        }

        @Test
        @DisplayName("a single shape is hit")
        void oneHit() {
            assertHits(all, new Ray(new Point(5, 5, 10), DOWN), new Point(5, 5, 0));
        }

        @Test
        @DisplayName("all shapes are hit")
        void allHit() {
            assertHits(all, new Ray(new Point(0, 0, 10), DOWN), new Point(0, 0, 6), new Point(0, 0, 4), new Point(0, 0, 2),
                    new Point(0, 0, 0));
        }

        @Test
        @DisplayName("nested collections contribute their hits")
        void nested() {
            Geometries nested = new Geometries(new Geometries(sphere), new Geometries(new Geometries(triangle), plane));
            assertHits(nested, new Ray(new Point(0, 0, 10), DOWN), new Point(0, 0, 6), new Point(0, 0, 4), new Point(0, 0, 2),
                    new Point(0, 0, 0));
        }

    }

    @Nested
    @DisplayName("composition")
    class Composition {
        @Test
        void addAppendsAndGetItemsIsReadOnly() {
            Geometries g = new Geometries(sphere);
            g.add(triangle, plane);
            assertThat(g.getItems()).containsExactly(sphere, triangle, plane);
            assertThat(g.isEmpty()).isFalse();
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> g.getItems().add(sphere))
                    .isInstanceOf(UnsupportedOperationException.class);
        }

        @Test
        @DisplayName("a null element is rejected naming its index")
        void nullIsRejected() {
            assertThatNullPointerException().isThrownBy(() -> new Geometries().add(sphere, null)).withMessageContaining("#1");
        }

        @Test
        @DisplayName("bounding box: union of the children, null when empty or when a child is unbounded")
        void boundingBox() {
            assertThat(new Geometries().getBoundingBox()).isNull();
            assertThat(all.getBoundingBox()).isNull();
            BoundingBox b = new Geometries(sphere, triangle).getBoundingBox();
            assertThat(new double[] { b.getMinX(), b.getMinY(), b.getMinZ(), b.getMaxX(), b.getMaxY(), b.getMaxZ() })
                    .containsExactly(-1, -1, 2, 3, 3, 6);
        }
    }

    /** The contract, for the flat list of several shapes (bounded ones only, so the box is checked). */
    @Nested
    @DisplayName("contract: a flat list of bounded shapes")
    class BoundedContract extends ContractScenes.SceneContract {
        private final Geometries scene = ContractScenes.bounded();

        @Override
        public Intersectable subject() {
            return scene;
        }
    }

    @Nested
    @DisplayName("contract: a flat list with planes and tubes")
    class MixedContract extends ContractScenes.SceneContract {
        private final Geometries scene = ContractScenes.mixed();

        @Override
        public Intersectable subject() {
            return scene;
        }

        @Override
        public boolean bounded() {
            return false;
        }
    }
}
