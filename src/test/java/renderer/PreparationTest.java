package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Sphere;
import lighting.PointLight;
import primitives.Color;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * A tracer is prepared for its scene one way ({@link RayTracerBase#prepareFor}): a render before
 * its workers start, a region renderer once, a direct {@link RayTracerBasic#traceRay(Ray)} when
 * the scene is no longer as it was prepared ({@link SceneStamp}), nested lists included.
 */
class PreparationTest {
    private static final Ray DOWN_Z = new Ray(new Point(0, 0, 10), new Vector(0, 0, -1));
    private static final Color BACKGROUND = new Color(1, 2, 3), RED = new Color(200, 0, 0);

    /** A scene with one empty nested list, and a tracer that has been called once on it. */
    private record Grown(Scene scene, Geometries nested, RayTracerBasic tracer) {
        static Grown called() {
            Geometries nested = new Geometries();
            Scene scene = new Scene("grows").setBackground(BACKGROUND);
            scene.geometries.add(nested);
            RayTracerBasic tracer = new RayTracerBasic(scene);
            assertThat(tracer.traceRay(DOWN_Z).toRgb()).as("the empty scene").isEqualTo(BACKGROUND.toRgb());
            return new Grown(scene, nested, tracer);
        }
    }

    @Test
    @DisplayName("a direct call sees a shape added inside a nested list after the previous call")
    void directCallSeesNestedAddition() {
        Grown g = Grown.called();
        g.nested.add(new Sphere(Point.ZERO, 1).setEmission(RED)); // the top list's size stays 1
        assertThat(g.tracer.traceRay(DOWN_Z).toRgb()).isEqualTo(RED.toRgb());
    }

    @Test
    @DisplayName("a direct call sees a light added after the previous call")
    void directCallSeesAddedLight() {
        Grown g = Grown.called();
        g.nested.add(new Sphere(Point.ZERO, 1).setMaterial(new primitives.Material().setKd(0.5)));
        Color unlit = g.tracer.traceRay(DOWN_Z);
        g.scene.lights.add(new PointLight(new Color(100, 100, 100), new Point(0, 0, 5)));
        assertThat(g.tracer.traceRay(DOWN_Z).toRgb()).isNotEqualTo(unlit.toRgb());
    }

    @Test
    @DisplayName("switching the BVH off after a direct call prepares again, with the same colour")
    void bvhSwitchedAfterACall() {
        Grown g = Grown.called();
        g.nested.add(new Sphere(Point.ZERO, 1).setEmission(RED));
        int withBvh = g.tracer.traceRay(DOWN_Z).toRgb();
        assertThat(g.tracer.setBvh(false).traceRay(DOWN_Z).toRgb()).isEqualTo(withBvh).isEqualTo(RED.toRgb());
    }
}
