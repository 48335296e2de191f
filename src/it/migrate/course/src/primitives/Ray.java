package primitives;

public class Ray {
    public Ray(Point head, Vector direction) { }
}
