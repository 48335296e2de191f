package geometries;

import java.util.List;
import primitives.Point;
import primitives.Ray;

public abstract class Intersectable {
    public static class GeoPoint {
        public GeoPoint(Geometry geometry, Point point) { }
    }

    protected abstract List<GeoPoint> findGeoIntersectionsHelper(Ray ray, double maxDistance);
}
