package geometries;

import primitives.Point;
import primitives.Vector;

public abstract class Geometry extends Intersectable {
    public abstract Vector getNormal(Point point);
}
