package geometries;

import java.util.Random;

import primitives.Point;
import primitives.Ray;
import primitives.Vector;

/** The fixed composite scenes the geometry contract runs on, flat and inside a {@link Bvh}. */
final class ContractScenes {
    private ContractScenes() {
    }

    static final Point FOCUS = Point.ZERO;
    static final double EXTENT = 6;
    /** Straight down onto the sphere at the origin that every scene holds. */
    static final Ray HIT = new Ray(new Point(0, 0, 20), new Vector(0, 0, -1));
    /** Far away and going farther. */
    static final Ray MISS = new Ray(new Point(100, 100, 100), new Vector(1, 1, 1));

    /** A sphere at the origin and 24 random bounded shapes of every kind around it. */
    static Geometries bounded() {
        Geometries g = new Geometries(new Sphere(Point.ZERO, 0.5));
        for (Geometry shape : RandomScenes.boundedShapes(new Random(0xC0FFEE), 24, FOCUS, EXTENT, 2)) g.add(shape);
        return g;
    }

    /** {@link #bounded()} in nested lists, plus a floor plane and a tube beside them. */
    static Geometries mixed() {
        Geometries inner = bounded();
        return new Geometries(new Geometries(inner), new Plane(new Point(0, 0, -10), new Vector(0, 0, 1)),
                new Tube(1, new Ray(new Point(0, 9, 0), new Vector(1, 0, 0.2))));
    }

    /**
     * The geometry contract over one of these scenes: the rays and sizes are the scenes', only
     * the subject (the flat list, or a tree built from it) differs between implementations.
     */
    abstract static class SceneContract implements GeometryContract {
        @Override
        public Ray knownHit() {
            return HIT;
        }

        @Override
        public Ray knownMiss() {
            return MISS;
        }

        @Override
        public Point focus() {
            return FOCUS;
        }

        @Override
        public double extent() {
            return EXTENT;
        }
    }
}
