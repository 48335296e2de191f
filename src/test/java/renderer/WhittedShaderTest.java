package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.offset;
import static renderer.RayTracerBasic.MAX_CALC_COLOR_LEVEL;
import static renderer.RayTracerBasic.MIN_CALC_COLOR_K;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Geometry;
import geometries.Plane;
import lighting.AmbientLight;
import lighting.LightSource;
import lighting.PointLight;
import primitives.Color;
import primitives.Material;
import primitives.Point;
import primitives.Rgb;
import primitives.Vector;
import scene.Scene;

/**
 * The shader under {@link RayTracerBasic}, driven as the render loop drives it: a camera ray in a
 * worker's context, the colour back as the context's {@link Rgb}, the rays it cost in the
 * context's counters. The camera ray runs straight down the z axis from z = 10.
 */
class WhittedShaderTest {
    private static final Color EMISSION = new Color(3, 5, 7);
    private final TraceContext ctx = new TraceContext(MAX_CALC_COLOR_LEVEL, MIN_CALC_COLOR_K);

    /** A floor z = 0 facing up, with {@code material}. */
    private static Scene floor(Material material) {
        Scene scene = new Scene("floor").setBackground(new Color(40, 80, 120));
        scene.geometries.add(new Plane(Point.ZERO, new Vector(0, 0, 1)).setEmission(EMISSION).setMaterial(material));
        return scene;
    }

    /** Shades the camera ray straight down in {@code scene} with beams of {@code beamSize} rays. */
    private Rgb shade(Scene scene, int beamSize) {
        WhittedShader shader = new WhittedShader(scene.background, scene.ambientLight.getIntensity(), scene.geometries, scene.lights.toArray(new LightSource[0]),
                beamSize, 1);
        ctx.random.reset(7, 0, 0, 0);
        ctx.cameraRay().ray(0, 0, 10, 0, 0, -1);
        return shader.traceRay(ctx);
    }

    @Test
    @DisplayName("the colour comes back in the context's camera colour: no object per camera ray")
    void colourInTheContext() {
        Scene scene = floor(new Material().setKr(0.5));
        assertThat(shade(scene, 4)).isSameAs(ctx.cameraColour());
        assertThat(shade(new Scene("empty"), 4)).isSameAs(ctx.cameraColour());
    }

    @Test
    @DisplayName("a mirror: emission, plus kR times the background it reflects, plus the ambient light times kA, summed as Color sums")
    void mirrorAsColorArithmetic() {
        Material material = new Material().setKr(0.3).setKA(0.6);
        Scene scene = floor(material).setAmbientLight(new AmbientLight(new Color(90, 30, 10), 0.7));
        Color expected = EMISSION.add(Color.BLACK.add(scene.background.scale(material.kR)))
                .add(scene.ambientLight.getIntensity().scale(material.kA));
        Rgb seen = shade(scene, 4);
        assertThat(new double[] { seen.r(), seen.g(), seen.b() })
                .containsExactly(expected.getR(), expected.getG(), expected.getB());
    }

    @Test
    @DisplayName("a ray that hits nothing sees the background, and traces nothing more")
    void background() {
        Rgb seen = shade(new Scene("empty").setBackground(new Color(1, 2, 3)), 4);
        assertThat(new double[] { seen.r(), seen.g(), seen.b() }).containsExactly(1, 2, 3);
        assertThat(ctx.secondaryRays).isZero();
    }

    @Nested
    @DisplayName("which bounces are traced")
    class Bounces {
        @Test
        @DisplayName("a bounce is traced while the path weight stays at MIN_CALC_COLOR_K or above, and not below")
        void weightThreshold() {
            shade(floor(new Material().setKr(MIN_CALC_COLOR_K)), 4);
            assertThat(ctx.secondaryRays).as("kR = MIN_CALC_COLOR_K").isEqualTo(1);
            ctx.secondaryRays = 0;
            shade(floor(new Material().setKr(Math.nextDown(MIN_CALC_COLOR_K))), 4);
            assertThat(ctx.secondaryRays).as("kR just below").isZero();
        }

        @ParameterizedTest(name = "beam of {0}")
        @ValueSource(ints = { 1, 4, 16 })
        @DisplayName("the first spread bounce traces the whole beam; every bounce below it traces one ray")
        void beamThenOneRay(int beamSize) {
            // A glossy floor under a glossy ceiling: floor (weight 1 · 0.5), ceiling (0.5 · 0.003 =
            // 0.0015), then the floor again, whose bounce (0.00075) falls below the threshold.
            Scene scene = floor(new Material().setKr(0.5).setReflectionSpread(0.1));
            scene.geometries.add(new Plane(new Point(0, 0, 20), new Vector(0, 0, -1))
                    .setMaterial(new Material().setKr(0.003).setReflectionSpread(0.1)));
            shade(scene, beamSize);
            assertThat(ctx.secondaryRays).isEqualTo(2L * beamSize);
        }

        @Test
        @DisplayName("a material that neither reflects nor transmits traces no secondary ray")
        void none() {
            shade(floor(new Material().setKd(0.5).setKs(0.5)), 16);
            assertThat(ctx.secondaryRays).isZero();
        }
    }

    @Nested
    @DisplayName("the Phong term of a light")
    class Phong {
        /** A floor z = 0 as a user could write it, whose normal is (0, 0, 4): not of unit length. */
        private static Geometry longNormalFloor() {
            return new UserShape(new Plane(Point.ZERO, new Vector(0, 0, 1)), p -> new Vector(0, 0, 4));
        }

        private double[] lit(Geometry floor, Material material) {
            Scene scene = new Scene("lit floor");
            scene.geometries.add(floor.setEmission(EMISSION).setMaterial(material));
            scene.lights.add(new PointLight(new Color(100, 200, 300), new Point(3, 4, 12)));
            Rgb seen = shade(scene, 1);
            return new double[] { seen.r(), seen.g(), seen.b() };
        }

        @ParameterizedTest(name = "shininess {0}")
        @ValueSource(ints = { 1, 20, 1_000_000 })
        @DisplayName("without kS the shininess changes nothing, to the bit: emission plus kD·|n·l| times the light")
        void noSpecularTerm(int shininess) {
            double[] seen = lit(new Plane(Point.ZERO, new Vector(0, 0, 1)), new Material().setKd(0.5).setShininess(shininess));
            assertThat(seen).containsExactly(lit(new Plane(Point.ZERO, new Vector(0, 0, 1)), new Material().setKd(0.5)));
            double nl = 12 / Math.sqrt(9 + 16 + 144); // the light's direction against the floor's normal
            assertThat(seen[1]).isCloseTo(5 + 0.5 * nl * 200, offset(1e-9));
        }

        @Test
        @DisplayName("without kS a power that overflows (a user's normal of length 4, shininess 1000) is not a NaN pixel")
        void overflowingPower() {
            // (n·l)·n grows with |n|², so the mirror term here is about 28.6 > 1, and 28.6^1000 = +∞;
            // kS·∞ with kS = 0 was NaN. The term is now the diffuse one alone, as at shininess 0.
            double[] seen = lit(longNormalFloor(), new Material().setKd(0.5).setShininess(1000));
            assertThat(seen).doesNotContain(Double.NaN)
                    .containsExactly(lit(longNormalFloor(), new Material().setKd(0.5)));
        }
    }

    @Nested
    @DisplayName("the lights' buffers for shadow rays")
    class LightBuffers {
        /** Opaque spheres and triangles over a floor plane (opaque: a product of kT is then the same in any order). */
        private Scene scene() {
            Scene scene = new Scene("buffers").setBackground(new Color(10, 20, 30));
            java.util.Random rnd = new java.util.Random(11);
            for (int i = 0; i < 40; ++i) {
                Point c = new Point(rnd.nextDouble(-8, 8), rnd.nextDouble(0.5, 6), rnd.nextDouble(-8, 8));
                Geometry g = i % 2 == 0 ? new geometries.Sphere(c, rnd.nextDouble(0.3, 1))
                        : new geometries.Triangle(c, c.add(new Vector(1.5, 0, 0.3)), c.add(new Vector(0, 1.5, 0.2)));
                scene.geometries.add(g.setMaterial(new Material().setKd(0.6).setKs(0.3).setShininess(20).setKr(0.2)));
            }
            scene.geometries.add(new Plane(Point.ZERO, new Vector(0, 1, 0)).setMaterial(new Material().setKd(0.5).setKr(0.3)));
            scene.lights.add(new PointLight(new Color(300, 300, 300), new Point(-4, 12, 6)).setKq(0.01));
            scene.lights.add(new lighting.SpotLight(new Color(200, 100, 50), new Point(5, 9, -3), new Vector(-1, -2, 1)).setKl(0.1));
            scene.lights.add(new lighting.DirectionalLight(new Color(80, 80, 80), new Vector(1, -3, -1)));
            scene.lights.add(new PointLight(new Color(50, 50, 50), new Point(0, 15, 0)).setRadius(1)); // soft: no buffer
            scene.lights.add(new PointLight(new Color(20, 20, 20), new Point(3, 10, 3)) { // a user's light: no buffer
            });
            return scene;
        }

        private static WhittedShader shader(Scene scene, geometries.Intersectable world) {
            return new WhittedShader(scene.background, scene.ambientLight.getIntensity(), world, scene.lights.toArray(new LightSource[0]), 1, 4);
        }

        @Test
        @DisplayName("point, spot and directional lights of radius 0 get one over a tree; a soft light, a user's light and the flat walk do not")
        void whichLights() {
            Scene scene = scene();
            WhittedShader tree = shader(scene, geometries.Bvh.build(scene.geometries));
            assertThat(new boolean[] { tree.shadowIndex(0) != null, tree.shadowIndex(1) != null, tree.shadowIndex(2) != null,
                    tree.shadowIndex(3) != null, tree.shadowIndex(4) != null }).containsExactly(true, true, true, false, false);
            WhittedShader flat = shader(scene, scene.geometries);
            for (int i = 0; i < 5; ++i)
                assertThat(flat.shadowIndex(i)).isNull();
        }

        @Test
        @DisplayName("the colours with buffers over the tree are the flat walk's, bit for bit, ray by ray")
        void sameColours() {
            Scene scene = scene();
            WhittedShader tree = shader(scene, geometries.Bvh.build(scene.geometries)), flat = shader(scene, scene.geometries);
            TraceContext other = new TraceContext(MAX_CALC_COLOR_LEVEL, MIN_CALC_COLOR_K);
            java.util.Random rnd = new java.util.Random(12);
            for (int i = 0; i < 3000; ++i) {
                double tx = rnd.nextDouble(-9, 9), tz = rnd.nextDouble(-9, 9);
                ctx.random.reset(5, i, 0, 0);
                other.random.reset(5, i, 0, 0);
                ctx.cameraRay().ray(0, 8, 20, tx, -8, tz - 20);
                other.cameraRay().ray(0, 8, 20, tx, -8, tz - 20);
                Rgb a = tree.traceRay(ctx), b = flat.traceRay(other);
                assertThat(new double[] { a.r(), a.g(), a.b() }).as("ray %d", i).containsExactly(b.r(), b.g(), b.b());
            }
        }
    }
}
