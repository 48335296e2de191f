package geometries;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/**
 * Reproducible random shapes and rays for the property tests. Every shape gets its own material
 * with a random transparency, so that shadow-transparency products tell geometries apart.
 */
final class RandomScenes {
    private RandomScenes() {
    }

    static Point point(Random rnd, Point centre, double half) {
        return new Point(centre.getX() + half * (2 * rnd.nextDouble() - 1), centre.getY() + half * (2 * rnd.nextDouble() - 1),
                centre.getZ() + half * (2 * rnd.nextDouble() - 1));
    }

    static Vector direction(Random rnd) {
        return new Vector(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalize();
    }

    /** A random material whose kT differs per channel, in (0.3, 1). */
    static <G extends Geometry> G withMaterial(Random rnd, G g) {
        g.setMaterial(new Material().setKd(0.5).setKt(new primitives.Double3(0.3 + 0.7 * rnd.nextDouble(),
                0.3 + 0.7 * rnd.nextDouble(), 0.3 + 0.7 * rnd.nextDouble())));
        return g;
    }

    static Sphere sphere(Random rnd, Point centre, double half, double size) {
        return withMaterial(rnd, new Sphere(point(rnd, centre, half), size * (0.2 + rnd.nextDouble())));
    }

    /** A random triangle; one in three lies in a plane z = const (a flat bounding box). */
    static Triangle triangle(Random rnd, Point centre, double half, double size) {
        while (true) {
            Point c = point(rnd, centre, half);
            Point a = point(rnd, c, size), b = point(rnd, c, size), d = point(rnd, c, size);
            if (rnd.nextInt(3) == 0) {
                a = new Point(a.getX(), a.getY(), c.getZ());
                b = new Point(b.getX(), b.getY(), c.getZ());
                d = new Point(d.getX(), d.getY(), c.getZ());
            }
            try {
                return withMaterial(rnd, new Triangle(a, b, d));
            } catch (IllegalArgumentException degenerate) {
                // almost collinear: draw again
            }
        }
    }

    /** A regular polygon of 4 to 7 vertices in a random plane. */
    static Polygon polygon(Random rnd, Point centre, double half, double size) {
        Point c = point(rnd, centre, half);
        Vector n = direction(rnd);
        Vector u = n.crossProduct(Math.abs(n.getX()) < 0.9 ? Vector.AXIS_X : Vector.AXIS_Y).normalize();
        Vector w = n.crossProduct(u);
        int count = 4 + rnd.nextInt(4);
        double r = size * (0.3 + rnd.nextDouble());
        double phase = rnd.nextDouble();
        Point[] vertices = new Point[count];
        for (int k = 0; k < count; ++k) {
            double a = 2 * Math.PI * (k + phase) / count;
            vertices[k] = c.add(u.scale(r * Math.cos(a)).add(w.scale(r * Math.sin(a))));
        }
        return withMaterial(rnd, new Polygon(vertices));
    }

    static Cylinder cylinder(Random rnd, Point centre, double half, double size) {
        return withMaterial(rnd, new Cylinder(size * (0.1 + 0.4 * rnd.nextDouble()),
                new Ray(point(rnd, centre, half), direction(rnd)), size * (0.3 + 1.5 * rnd.nextDouble())));
    }

    /** {@code count} bounded shapes, a quarter of each kind, in the cube of half-size {@code half}. */
    static List<Geometry> boundedShapes(Random rnd, int count, Point centre, double half, double size) {
        List<Geometry> shapes = new ArrayList<>(count);
        for (int i = 0; i < count; ++i) {
            shapes.add(switch (i % 4) {
            case 0 -> sphere(rnd, centre, half, size);
            case 1 -> triangle(rnd, centre, half, size);
            case 2 -> polygon(rnd, centre, half, size);
            default -> cylinder(rnd, centre, half, size);
            });
        }
        return shapes;
    }

    /** Rays from around the scene aimed into it, and rays from inside it. */
    static List<Ray> rays(Random rnd, int count, Point centre, double half) {
        List<Ray> rays = new ArrayList<>(count);
        while (rays.size() < count) {
            Point from = rays.size() % 3 == 0 ? point(rnd, centre, half) : point(rnd, centre, 2.5 * half);
            Point to = point(rnd, centre, half);
            if (from.distance(to) > 1e-6) rays.add(new Ray(from, to.subtract(from)));
        }
        return rays;
    }
}
