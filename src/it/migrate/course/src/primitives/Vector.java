package primitives;

public class Vector extends Point {
    public static final Vector Z = new Vector(0, 0, 1);
    public Vector(double x, double y, double z) { super(x, y, z); }
    public double length() { return Math.sqrt(x * x + y * y + z * z); }
    public Vector rotate(int degrees) { return this; }
}
