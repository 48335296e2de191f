package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Plane;
import geometries.Polygon;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import scene.Scene;

/**
 * Refraction with an index ({@link Material#ior}), on the flat interface z = 0 between air
 * (z &gt; 0, the normal's side) and glass (z &lt; 0), with no lights: every colour seen is an
 * emission times the reflection or transmission weights, so it can be worked out by hand.
 */
@DisplayName("refraction with an index of refraction")
class RefractionTest {
    private static final double KR = 0.1, KT = 0.9, GLASS = 1.5;
    /** Emission of the wall above the interface (z = 100), seen by reflection from above. */
    private static final Color ABOVE = new Color(200, 0, 0);
    /** Emission of the wall below it (z = −100), inside the glass. */
    private static final Color BELOW = new Color(0, 0, 150);

    /** The interface, a wall on each side, and (optionally) a small target on the lower wall. */
    private static RayTracerBasic tracer(double ior, Polygon target) {
        return tracer(new Material().setKr(KR).setKt(KT).setIor(ior), target);
    }

    private static RayTracerBasic tracer(Material glass, Polygon target) {
        Scene scene = new Scene("interface");
        scene.geometries.add(
                new Plane(Point.ZERO, Vector.AXIS_Z).setMaterial(glass),
                new Plane(new Point(0, 0, 100), Vector.AXIS_Z).setEmission(ABOVE),
                new Plane(new Point(0, 0, -100), Vector.AXIS_Z).setEmission(target == null ? BELOW : Color.BLACK));
        if (target != null) scene.geometries.add(target);
        return new RayTracerBasic(scene);
    }

    /** A ray toward the interface's origin at {@code degrees} from its normal, from above or below. */
    private static Ray toward(double degrees, boolean fromAbove) {
        double a = Math.toRadians(degrees);
        Vector d = new Vector(Math.sin(a), 0, fromAbove ? -Math.cos(a) : Math.cos(a));
        return new Ray(Point.ZERO.add(d.scale(-50)), d);
    }

    /** Schlick's reflectance for glass 1.5 against air, with the cosine on the air side. */
    private static double schlick(double cosAir) {
        double r0 = Math.pow((GLASS - 1) / (GLASS + 1), 2);
        return r0 + (1 - r0) * Math.pow(1 - cosAir, 5);
    }

    @Nested
    @DisplayName("entering the glass from above (against the normal)")
    class Entering {
        @ParameterizedTest(name = "{0}° from the normal")
        @ValueSource(doubles = { 0, 60 })
        @DisplayName("the reflection gains the Fresnel share of kT (Schlick); the glass below is black")
        void fresnel(double degrees) {
            Color c = tracer(GLASS, null).traceRay(toward(degrees, true));
            double expected = (KR + KT * schlick(Math.cos(Math.toRadians(degrees)))) * 200;
            assertThat(c.getR()).isCloseTo(expected, within(1e-9));
            // 0° sees 4 % more than kR: r0 = ((1.5 − 1) / (1.5 + 1))² = 0.04.
            if (degrees == 0) assertThat(c.getR()).isCloseTo((0.1 + 0.9 * 0.04) * 200, within(1e-9));
        }

        @Test
        @DisplayName("diffuse glass with an index: the whole beam goes into the glass, with weight kT·(1 − F)")
        void diffuseGlass() {
            Material frosted = new Material().setKr(KR).setKt(KT).setIor(GLASS).setTransmissionSpread(0.5);
            Color c = tracer(frosted, null).setBeamSize(64).traceRay(toward(60, true));
            double f = schlick(0.5);
            assertThat(c.getB()).as("the floor inside the glass").isCloseTo(KT * (1 - f) * 150, within(1e-9));
            assertThat(c.getR()).as("the wall above: by reflection only").isCloseTo((KR + KT * f) * 200, within(1e-9));
        }

        @Test
        @DisplayName("index 1 keeps the course's weights: kR exactly, no Fresnel")
        void indexOne() {
            assertThat(tracer(1, null).traceRay(toward(60, true)).getR()).isCloseTo(KR * 200, within(1e-9));
        }

        @Test
        @DisplayName("the transmitted ray bends by Snell's law: at 45° it meets the floor 100 below at x = 100·tan(asin(sin 45° / 1.5))")
        void snell() {
            double x = 100 * Math.tan(Math.asin(Math.sin(Math.toRadians(45)) / GLASS)); // 53.5
            Polygon target = new Polygon(new Point(x - 1, -1, -99), new Point(x + 1, -1, -99), new Point(x + 1, 1, -99),
                    new Point(x - 1, 1, -99));
            target.setEmission(new Color(0, 255, 0));
            double expected = KT * (1 - schlick(Math.cos(Math.toRadians(45)))) * 255;
            assertThat(tracer(GLASS, target).traceRay(toward(45, true)).getG()).isCloseTo(expected, within(1e-9));
            assertThat(tracer(1, target).traceRay(toward(45, true)).getG())
                    .as("straight through (index 1) the ray lands at x = 100, beside the target").isZero();
        }
    }

    @Nested
    @DisplayName("leaving the glass from below (along the normal)")
    class Leaving {
        @Test
        @DisplayName("beyond the critical angle asin(1/1.5) = 41.8°: total internal reflection, kR + kT of the floor")
        void totalInternalReflection() {
            for (double degrees : new double[] { 42, 60, 85 }) {
                Color c = tracer(GLASS, null).traceRay(toward(degrees, false));
                assertThat(c.getB()).as("%s°", degrees).isCloseTo((KR + KT) * 150, within(1e-9));
                assertThat(c.getR()).as("%s°: nothing from above", degrees).isZero();
            }
        }

        @Test
        @DisplayName("within it: transmitted with 1 − F, F taken with the cosine on the air side")
        void transmitted() {
            double sinAir = GLASS * Math.sin(Math.toRadians(20));
            double f = schlick(Math.sqrt(1 - sinAir * sinAir));
            Color c = tracer(GLASS, null).traceRay(toward(20, false));
            assertThat(c.getR()).isCloseTo(KT * (1 - f) * 200, within(1e-9));
            assertThat(c.getB()).isCloseTo((KR + KT * f) * 150, within(1e-9));
        }

        @Test
        @DisplayName("index 1: straight through at any angle, no total reflection")
        void indexOne() {
            assertThat(tracer(1, null).traceRay(toward(60, false)).getR()).isCloseTo(KT * 200, within(1e-9));
        }
    }
}
