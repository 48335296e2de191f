package geometries;

import static geometries.Hits.assertHits;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatNullPointerException;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Arrays;
import java.util.List;

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

        /** {@code inner} inside {@code depth} − 1 lists, each within the next. */
        private Geometries nest(int depth, Intersectable inner) {
            Geometries list = new Geometries(inner);
            for (int i = 1; i < depth; ++i) list = new Geometries(list);
            return list;
        }

        @Test
        @DisplayName("10,000 levels deep: every year's query answers (a walk, not a recursion per level), in the items' order")
        void deepNest() {
            Geometries deep = new Geometries(plane, nest(10_000, sphere), nest(5_000, new Geometries(triangle)));
            Ray ray = new Ray(new Point(0, 0, 10), DOWN);
            List<Point> expected = List.of(new Point(0, 0, 0), new Point(0, 0, 6), new Point(0, 0, 4), new Point(0, 0, 2));
            assertThat(deep.findIntersections(ray)).containsExactlyElementsOf(expected);
            assertThat(deep.findGeoIntersections(ray)).extracting(gp -> gp.point).containsExactlyElementsOf(expected);
            assertThat(deep.calculateIntersections(ray)).extracting(gp -> gp.geometry)
                    .containsExactly(plane, sphere, sphere, triangle);
            assertThat(deep.calcIntersections(ray, 8)).extracting(gp -> gp.point) // within 8 of the head: not the plane
                    .containsExactly(new Point(0, 0, 6), new Point(0, 0, 4), new Point(0, 0, 2));
            assertThat(ray.findClosestPoint(deep.findIntersections(ray))).isEqualTo(new Point(0, 0, 6));
        }

        @Test
        @DisplayName("a list met twice (not within itself) gives its hits twice, as the course's recursion did")
        void sharedList() {
            Geometries shared = new Geometries(sphere);
            assertThat(new Geometries(shared, new Geometries(shared)).findIntersections(new Ray(new Point(0, 0, 10), DOWN)))
                    .containsExactly(new Point(0, 0, 6), new Point(0, 0, 4), new Point(0, 0, 6), new Point(0, 0, 4));
        }

        @Test
        @DisplayName("a list within itself: refused with its depth, not walked for ever")
        void cycle() {
            Geometries outer = new Geometries(sphere);
            Geometries inner = new Geometries(triangle);
            outer.add(new Geometries(inner));
            inner.add(outer);
            assertThatThrownBy(() -> outer.findIntersections(new Ray(new Point(0, 0, 10), DOWN)))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("the geometries contain themselves: a Geometries list is nested in itself, 3 levels down,"
                            + " so no query can walk them");
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

        @Test
        @DisplayName("the nesting depth counts the longest chain; a list shared by two parents is one list")
        void nestingDepth() {
            Geometries shared = new Geometries(new Geometries());
            Geometries root = new Geometries(shared, new Geometries(shared));
            assertThat(root.nestingDepth()).isEqualTo(4);
            assertThat(new Geometries(sphere).nestingDepth()).isEqualTo(1);
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

    @Nested
    @DisplayName("its face outside the library")
    class Face {
        @Test
        @DisplayName("completing scene.geometries. offers the course's methods, not the render's queries or checks")
        void courseMethodsOnly() {
            assertThat(Arrays.stream(Geometries.class.getDeclaredMethods())
                    .filter(m -> Modifier.isPublic(m.getModifiers()))
                    .map(Method::getName).distinct().sorted())
                    .containsExactly("add", "buildBVH", "enableBVH", "getItems", "isEmpty", "makeBVH");
        }
    }
}
