package primitives;

public class Point {
    protected final double x, y, z;
    public Point(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }
    public Vector subtract(Point p) { return new Vector(x - p.x, y - p.y, z - p.z); }
}
