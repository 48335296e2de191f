package renderer.golden;

import static java.awt.Color.WHITE;
import static org.assertj.core.api.Assertions.assertThat;
import static renderer.golden.Golden.assertPixel;
import static renderer.golden.Golden.blue;
import static renderer.golden.Golden.luma;
import static renderer.golden.Golden.lumaAt;
import static renderer.golden.Golden.red;
import static renderer.golden.Golden.transitionWidth;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Vector;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import scene.Scene;

/**
 * The picture improvements of the student reports, each switched on with one line: depth of
 * field, glossy reflection, diffuse glass and soft shadows. Each test checks the effect is
 * really there (blur where it belongs, sharpness where it does not); the measurements in depth
 * are in {@code renderer.effects}.
 */
@DisplayName("Golden renders: picture improvements")
class ImprovementsGoldenTest {
    /** The floor-and-sphere view of the course classics. */
    private static final Golden.View FLOOR_VIEW = FloorScene.VIEW;
    private static final int FLOOR_SIZE = FloorScene.SIZE;

    @Test
    @DisplayName("depth of field: the sphere at the focal distance is sharp, the near and far ones blurred")
    void depthOfField() {
        // Emission only, so each sphere is one flat colour and its silhouette a clean edge.
        Scene scene = new Scene("depth of field");
        Point near = new Point(-30, 25, 100), focused = Point.ZERO, far = new Point(50, -40, -200);
        scene.geometries.add(new Sphere(near, 12).setEmission(new Color(255, 70, 60)),
                new Sphere(focused, 15).setEmission(new Color(70, 230, 70)),
                new Sphere(far, 30).setEmission(new Color(90, 110, 255)));
        Golden.View view = new Golden.View(new Point(0, 0, 300), Point.ZERO, 150, 300);
        ImageWriter image = Golden.image("depth-of-field", 150, 150);
        view.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene))
                .setDepthOfField(300, 10).setDepthOfFieldSamples(32)
                .build().renderImage().writeToImage();

        // Thin lens, aperture radius a: a point at depth d blurs into a disc of radius
        // a·|1 − d/f|·vpDistance/d on the view plane (one pixel per unit here): 5 px near, 4 px far.
        assertThat(edgeWidth(image, view, near, 12, -1)).as("near sphere's left edge").isGreaterThanOrEqualTo(4);
        assertThat(edgeWidth(image, view, far, 30, +1)).as("far sphere's right edge").isGreaterThanOrEqualTo(3);
        assertThat(edgeWidth(image, view, focused, 15, +1)).as("focused sphere's right edge").isLessThanOrEqualTo(1);
    }

    /**
     * The 10 %–90 % width of a sphere's silhouette along the row of its centre, on the left
     * ({@code side} −1) or right (+1), from the centre pixel to 10 pixels past the edge.
     */
    private static int edgeWidth(ImageWriter image, Golden.View view, Point centre, double radius, int side) {
        int[] c = view.pixelOf(centre, image.getNx());
        int[] edge = view.pixelOf(centre.add(new Vector(side * radius, 0, 0)), image.getNx());
        return transitionWidth(image, c[1], c[0], edge[0] + side * 10);
    }

    /** A sphere floating over a floor mirror; the floor's roughness is the test's parameter. */
    private static Scene sphereOverMirror(String name, double spread) {
        Scene scene = new Scene(name).setBackground(new Color(20, 30, 60))
                .setAmbientLight(new AmbientLight(new Color(WHITE), 0.1));
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Y).setEmission(new Color(8, 8, 10))
                        .setMaterial(new Material().setKd(0.2).setKr(0.8).setReflectionSpread(spread)),
                new Sphere(new Point(0, 35, 0), 30).setEmission(new Color(150, 20, 20))
                        .setMaterial(new Material().setKd(0.5).setKs(0.5).setShininess(60)));
        scene.lights.add(new DirectionalLight(new Color(150, 150, 150), new Vector(-1, -2, -1)));
        return scene;
    }

    @Test
    @DisplayName("glossy reflection: the floor's reflection of the sphere is blurred, the sphere itself sharp")
    void glossyReflection() {
        ImageWriter image = Golden.image("glossy", FLOOR_SIZE, FLOOR_SIZE);
        FLOOR_VIEW.builder().setImageWriter(image)
                .setRayTracer(new RayTracerBasic(sphereOverMirror("glossy", 0.1)).setBeamSize(32))
                .build().renderImage().writeToImage();

        Point mirrored = new Point(0, -35, 0);
        int[] reflection = FLOOR_VIEW.pixelOf(mirrored, FLOOR_SIZE);
        int seen = image.getRgb(reflection[0], reflection[1]);
        assertThat(red(seen)).as("the reflection is still red, " + Golden.rgb(seen)).isGreaterThan(2 * blue(seen));
        int reflectedEdge = FLOOR_VIEW.pixelOf(mirrored.add(new Vector(30, 0, 0)), FLOOR_SIZE)[0];
        int directEdge = FLOOR_VIEW.pixelOf(new Point(30, 35, 0), FLOOR_SIZE)[0];
        int[] direct = FLOOR_VIEW.pixelOf(new Point(0, 35, 0), FLOOR_SIZE);
        assertThat(transitionWidth(image, reflection[1], reflection[0], reflectedEdge + 12))
                .as("reflection's right edge").isGreaterThanOrEqualTo(3);
        assertThat(transitionWidth(image, direct[1], direct[0] + 10, directEdge + 8))
                .as("sphere's own right edge").isLessThanOrEqualTo(1);
    }

    @Test
    @DisplayName("glossy reflection off (spread 0): the same floor mirrors the sphere with a sharp edge")
    void glossyReflectionOff() {
        ImageWriter image = Golden.image("glossy-off", FLOOR_SIZE, FLOOR_SIZE);
        FLOOR_VIEW.builder().setImageWriter(image)
                .setRayTracer(new RayTracerBasic(sphereOverMirror("glossy off", 0)).setBeamSize(32))
                .build().renderImage().writeToImage();

        Point mirrored = new Point(0, -35, 0);
        int[] reflection = FLOOR_VIEW.pixelOf(mirrored, FLOOR_SIZE);
        int reflectedEdge = FLOOR_VIEW.pixelOf(mirrored.add(new Vector(30, 0, 0)), FLOOR_SIZE)[0];
        assertThat(transitionWidth(image, reflection[1], reflection[0], reflectedEdge + 12))
                .as("reflection's right edge, perfect mirror").isLessThanOrEqualTo(1);
    }

    @Test
    @DisplayName("diffuse glass: stripes behind a frosted pane smear, behind a clear pane they stay sharp")
    void diffuseGlass() {
        Scene scene = new Scene("diffuse glass").setAmbientLight(new AmbientLight(new Color(WHITE), 0.05));
        // White stripes 8 units wide every 16 units on a wall 60 units behind the panes.
        for (int x = -72; x <= 64; x += 16)
            scene.geometries.add(new Polygon(new Point(x, -70, -60), new Point(x + 8, -70, -60),
                    new Point(x + 8, 70, -60), new Point(x, 70, -60)).setEmission(new Color(230, 230, 230)));
        Material glass = new Material().setKd(0.1).setKt(0.9);
        scene.geometries.add(
                new Polygon(new Point(-70, -40, 0), new Point(-1, -40, 0), new Point(-1, 40, 0), new Point(-70, 40, 0))
                        .setEmission(new Color(5, 5, 15)).setMaterial(new Material().setKd(0.1).setKt(0.9)
                                .setTransmissionSpread(0.25)),
                new Polygon(new Point(1, -40, 0), new Point(70, -40, 0), new Point(70, 40, 0), new Point(1, 40, 0))
                        .setEmission(new Color(5, 5, 15)).setMaterial(glass));
        scene.lights.add(new DirectionalLight(new Color(100, 100, 100), new Vector(0, 0, -1)));
        Golden.View view = new Golden.View(new Point(0, 0, 200), Point.ZERO, 100, 200);
        ImageWriter image = Golden.image("diffuse-glass", 150, 150);
        view.builder().setImageWriter(image).setRayTracer(new RayTracerBasic(scene).setBeamSize(64))
                .build().renderImage().writeToImage();

        // Behind the frosted pane each point averages a disc of radius 0.25 × 60 = 15 units of
        // wall, about one stripe period: the stripes all but vanish (what is left is mostly the
        // beam's sampling noise).
        int row = view.pixelOf(new Point(0, 0, 0), 150)[1];
        double frosted = contrast(image, row, view.pixelOf(new Point(-45, 0, 0), 150)[0],
                view.pixelOf(new Point(-5, 0, 0), 150)[0]);
        double clear = contrast(image, row, view.pixelOf(new Point(5, 0, 0), 150)[0],
                view.pixelOf(new Point(45, 0, 0), 150)[0]);
        assertThat(clear).as("stripe contrast behind the clear pane").isGreaterThan(150);
        assertThat(frosted).as("stripe contrast behind the frosted pane").isLessThan(clear / 3);
    }

    /** The difference between the brightest and the darkest pixel of a row segment. */
    private static double contrast(ImageWriter image, int row, int from, int to) {
        double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
        for (int x = from; x <= to; ++x) {
            double v = luma(image.getRgb(x, row));
            min = Math.min(min, v);
            max = Math.max(max, v);
        }
        return max - min;
    }

    @Test
    @DisplayName("soft shadows: a light of radius 12 leaves the umbra dark and half-lights the hard shadow's edge")
    void softShadows() {
        Point light = new Point(-90, 110, 0);
        Point centre = FloorScene.SPHERE_CENTRE;
        double radius = FloorScene.SPHERE_RADIUS;
        Scene scene = FloorScene.create("soft shadows",
                new PointLight(new Color(300, 300, 300), light).setKl(0.002).setRadius(12));
        ImageWriter image = Golden.image("soft-shadows", FLOOR_SIZE, FLOOR_SIZE);
        FLOOR_VIEW.builder().setImageWriter(image)
                .setRayTracer(new RayTracerBasic(scene).setShadowSamples(32))
                .build().renderImage().writeToImage();

        // The hard shadow's centre: the light's centre projected through the sphere's centre.
        Point umbra = Golden.onFloor(light, centre);
        // Across the shadow, sideways to the light: the hard edge is where the line to the light's
        // centre grazes the sphere.
        Vector across = Vector.AXIS_Z; // ⟂ to the light's horizontal offset (90, 0, 0), toward the camera
        double lo = 0, hi = 200;
        for (int i = 0; i < 60; ++i) {
            double mid = (lo + hi) / 2;
            if (distanceToLine(centre, light, umbra.add(across.scale(mid))) < radius) lo = mid;
            else hi = mid;
        }
        Point hardEdge = umbra.add(across.scale(lo));
        Point lit = umbra.add(across.scale(lo + 25));

        int dark = (int) FloorScene.FLOOR_BASE;
        assertPixel(image, FLOOR_VIEW.pixelOf(umbra, FLOOR_SIZE), dark, dark, dark, 0, "umbra");
        int[] edge = FLOOR_VIEW.pixelOf(hardEdge, FLOOR_SIZE), bright = FLOOR_VIEW.pixelOf(lit, FLOOR_SIZE);
        double litLuma = lumaAt(image, bright);
        double share = (lumaAt(image, edge) - dark) / (litLuma - dark);
        assertThat(share).as("share of the light reaching the hard shadow's edge (lit floor %.1f)", litLuma)
                .isBetween(0.25, 0.75);
    }

    /** The distance from {@code c} to the line through {@code a} and {@code b}. */
    private static double distanceToLine(Point c, Point a, Point b) {
        Vector ab = b.subtract(a).normalize();
        Vector ac = c.subtract(a);
        return ac.subtract(ab.scale(ac.dotProduct(ab))).length();
    }
}
