package renderer;

import primitives.Point;
import primitives.Vector;

public class PixelHelper {
    public static Vector between(Point a, Point b) { return b.subtract(a); }
}
