package scene.samples;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import scene.Scene;

/**
 * The built-in showcase, the kind of picture of the first student report: 133 geometries on a
 * reflective floor, a mirror ball, a glass ball with a coloured core, a ring of small spheres,
 * a tiled back wall and crystal pyramids, lit by a directional, a point and a spot light.
 * Best seen from {@link #CAMERA_LOCATION} toward {@link #CAMERA_TARGET} with a 200×200 view
 * plane at distance {@link #VP_DISTANCE}.
 */
public final class Showcase {
    /** Where the showcase camera stands. */
    public static final Point CAMERA_LOCATION = new Point(0, 140, 900);
    /** Where it looks. */
    public static final Point CAMERA_TARGET = new Point(0, 35, 0);
    /** The view-plane distance that frames the scene with a 200×200 view plane. */
    public static final double VP_DISTANCE = 560;
    /** The side of the square view plane. */
    public static final double VP_SIZE = 200;

    private Showcase() {
    }

    /** @return a new showcase scene (deterministic: the same every time) */
    public static Scene create() {
        Scene scene = new Scene("showcase")
                .setBackground(new Color(12, 14, 26))
                .setAmbientLight(new AmbientLight(new Color(255, 255, 255), 0.08));

        // A reflective floor (an unbounded plane: it stays beside the BVH).
        scene.geometries.add(new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(20, 20, 24))
                .setMaterial(new Material().setKd(0.4).setKs(0.3).setShininess(60).setKr(0.35)));

        // The back wall: 4 rows × 6 columns of tiles (24 polygons), alternating two tones.
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 6; ++col) {
                double x0 = -180 + col * 60, y0 = row * 40, z = -200;
                boolean dark = (row + col) % 2 == 0;
                scene.geometries.add(new Polygon(new Point(x0 + 1, y0 + 1, z), new Point(x0 + 59, y0 + 1, z),
                        new Point(x0 + 59, y0 + 39, z), new Point(x0 + 1, y0 + 39, z))
                        .setEmission(dark ? new Color(25, 18, 40) : new Color(45, 35, 60))
                        .setMaterial(new Material().setKd(0.5).setKs(0.2).setShininess(20)));
            }

        // The mirror ball and the glass ball with a coloured core.
        scene.geometries.add(new Sphere(new Point(-60, 45, -40), 45).setEmission(new Color(10, 10, 15))
                .setMaterial(new Material().setKd(0.1).setKs(0.6).setShininess(200).setKr(0.8)));
        scene.geometries.add(new Sphere(new Point(55, 35, 20), 35).setEmission(new Color(5, 15, 25))
                .setMaterial(new Material().setKd(0.1).setKs(0.7).setShininess(300).setKt(0.75)));
        scene.geometries.add(new Sphere(new Point(55, 35, 20), 14).setEmission(new Color(200, 40, 30))
                .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60)));

        // A ring of 96 small spheres in a spiral of hues.
        for (int i = 0; i < 96; ++i) {
            double a = 2 * Math.PI * i / 96;
            double radius = 125 + 10 * Math.sin(6 * a);
            double r = 4 + 2 * (i % 3);
            Color c = hue(i / 96.0);
            scene.geometries.add(new Sphere(new Point(radius * Math.cos(a), r, radius * Math.sin(a) - 20), r)
                    .setEmission(c.scale(0.6))
                    .setMaterial(new Material().setKd(0.5).setKs(0.4).setShininess(80).setKr(i % 4 == 0 ? 0.3 : 0)));
        }

        // Three crystal pyramids of 3 triangles each (9 triangles), partly transparent.
        double[][] pyramids = { { -130, 70 }, { 140, -60 }, { 0, 90 } };
        for (double[] p : pyramids) {
            Point apex = new Point(p[0], 45, p[1]);
            Point a = new Point(p[0] - 18, 0.5, p[1] + 12), b = new Point(p[0] + 18, 0.5, p[1] + 12),
                    c = new Point(p[0], 0.5, p[1] - 20);
            Material glass = new Material().setKd(0.2).setKs(0.6).setShininess(100).setKt(new Double3(0.5, 0.7, 0.6));
            Color e = new Color(10, 40, 30);
            scene.geometries.add(new Triangle(a, b, apex).setEmission(e).setMaterial(glass),
                    new Triangle(b, c, apex).setEmission(e).setMaterial(glass),
                    new Triangle(c, a, apex).setEmission(e).setMaterial(glass));
        }

        scene.lights.add(new DirectionalLight(new Color(60, 57, 54), new Vector(-1, -1.5, -1)));
        scene.lights.add(new PointLight(new Color(320, 270, 200), new Point(120, 160, 160)).setKl(0.0015).setKq(0.000012));
        scene.lights.add(new SpotLight(new Color(420, 360, 540), new Point(-150, 220, 150), new Vector(1, -1.6, -1))
                .setKl(0.001).setKq(0.00001).setNarrowBeam(6));
        return scene;
    }

    /** A saturated colour around the hue circle, h in [0, 1). */
    private static Color hue(double h) {
        double r = 0.5 + 0.5 * Math.cos(2 * Math.PI * h);
        double g = 0.5 + 0.5 * Math.cos(2 * Math.PI * (h - 1 / 3.0));
        double b = 0.5 + 0.5 * Math.cos(2 * Math.PI * (h - 2 / 3.0));
        return new Color(255 * r, 255 * g, 255 * b);
    }
}
