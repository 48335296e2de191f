package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Sphere;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/** {@link RayTracerBasic#traceRay(Ray)} called directly, outside a render (as course tests do). */
class RayTracerBasicTest {
    private static final Ray DOWN_Z = new Ray(new Point(0, 0, 10), new Vector(0, 0, -1));

    @Test
    @DisplayName("a geometry added after the first call is seen by the next call")
    void seesGeometryAddedAfterFirstCall() {
        Scene scene = new Scene("grows").setBackground(new Color(1, 2, 3));
        RayTracerBasic tracer = new RayTracerBasic(scene);
        assertThat(tracer.traceRay(DOWN_Z).toRgb()).isEqualTo(new Color(1, 2, 3).toRgb());

        scene.geometries.add(new Sphere(Point.ZERO, 1).setEmission(new Color(200, 0, 0)));
        assertThat(tracer.traceRay(DOWN_Z).toRgb()).isEqualTo(new Color(200, 0, 0).toRgb());
    }

    @Test
    @DisplayName("random effects are keyed by the ray: the same ray gives the same colour, another ray other noise")
    void randomEffectsKeyedByTheRay() {
        Scene scene = new Scene("soft");
        scene.geometries.add(new Sphere(new Point(0, 0, -5), 1).setMaterial(new Material().setKd(0)),
                new geometries.Plane(new Point(0, 0, -10), new Vector(0, 0, 1)).setMaterial(new Material().setKd(1)));
        scene.lights.add(new PointLight(new Color(255, 255, 255), new Point(0, 0, 20)).setRadius(3));
        RayTracerBasic tracer = new RayTracerBasic(scene).setShadowSamples(3);
        // A ray into the penumbra of the sphere on the plane: its colour depends on the shadow samples.
        Ray penumbra = new Ray(new Point(1.1, 0, 10), new Vector(0, 0, -1));
        Color first = tracer.traceRay(penumbra);
        assertThat(tracer.traceRay(penumbra).toRgb()).isEqualTo(first.toRgb());
        boolean anyDifferent = false;
        for (int i = 1; i <= 20 && !anyDifferent; ++i)
            anyDifferent = tracer.traceRay(new Ray(new Point(1.1, i * 1e-9, 10), new Vector(0, 0, -1))).toRgb() != first.toRgb();
        assertThat(anyDifferent).as("nearby rays draw other shadow samples").isTrue();
    }
}
