package geometries;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Intersectable.GeoPoint;
import geometries.Intersectable.Intersection;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * What every course year's "a user's own geometry" must do, whichever year's hook it overrides:
 * every year's query finds it (the distance bound and the flat list included), and the tracer
 * renders it like the library's sphere ({@link UserGeometryScenes}). Each course-year test class
 * implements it with its own year's shape: the surface of a sphere at
 * {@link UserGeometryScenes#CENTER} with {@link UserGeometryScenes#RADIUS}.
 */
interface UserShapeContract {
    /** @return a new shape as a student of the year writes it: one hook, no bounding box */
    Geometry newShape();

    @Test
    @DisplayName("every year's query finds it, within a distance bound, alone and in a list")
    default void everyQueryFindsIt() {
        Geometry shape = newShape();
        Ray through = new Ray(new Point(0, 0, 50), new Vector(0, 0, -1));
        Point near = new Point(0, 0, 10), far = new Point(0, 0, -10);
        assertThat(shape.findIntersections(through)).containsExactlyInAnyOrder(near, far);
        assertThat(shape.findGeoIntersections(through, 45)).containsExactly(new GeoPoint(shape, near));
        assertThat(shape.calculateIntersections(through)).containsExactlyInAnyOrder(new Intersection(shape, near),
                new Intersection(shape, far));
        assertThat(shape.calcIntersections(through, 45)).containsExactly(new Intersection(shape, near));
        assertThat(new Geometries(shape).findGeoIntersections(through, 30)).as("nothing within 30").isNull();
        assertThat(new Geometries(shape, new Sphere(new Point(0, 0, -100), 1)).calcIntersections(through)).hasSize(4);
        assertThat(shape.findIntersections(new Ray(new Point(0, 0, 50), new Vector(0, 0, 1)))).as("looking away").isNull();
    }

    @Test
    @DisplayName("the tracer renders it like the library's sphere, beside the BVH, with its shadow")
    default void rendered() {
        UserGeometryScenes.assertRendersLikeTheLibrarySphere(newShape());
    }
}
