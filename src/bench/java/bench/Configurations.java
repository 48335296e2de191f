package bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.PrimaryRayTracer;
import renderer.RayTracerBasic;
import scene.Scene;
import scene.samples.GlossyScene;
import scene.samples.ScalingScene;
import scene.samples.Showcase;
import scene.samples.TeapotScene;

/**
 * The benchmark's configurations, group by group, as PERFORMANCE.md lists them; {@code --quick}
 * keeps every configuration but shrinks images (and the heaviest sample counts) so that the
 * whole list renders in seconds.
 */
final class Configurations {
    private Configurations() {
    }

    static List<Configuration> of(Options o) {
        List<Configuration> list = new ArrayList<>();
        if (o.groups().contains("teapot")) teapot(o, list);
        if (o.groups().contains("glossy")) glossy(o, list);
        if (o.groups().contains("showcase")) showcase(o, list);
        if (o.groups().contains("aa")) antiAliasing(o, list);
        if (o.groups().contains("scaling")) scaling(o, list);
        if (o.match() != null) list.removeIf(c -> !o.match().matcher(c.describe()).find());
        return list;
    }

    /** The course benchmark: 1 ray per pixel, BVH off and on, 1 and 2 threads. */
    private static void teapot(Options o, List<Configuration> list) {
        int side = o.quick() ? 100 : 1000;
        for (boolean bvh : new boolean[] { false, true })
            for (int threads : new int[] { 1, 2 })
                list.add(new Configuration("teapot", "teapot", TeapotScene::create, "teapot (992 tri + 400 spheres)",
                        bvh ? "BVH" : "flat (no BVH)", side, side, threads, bvh, 0, 1,
                        scene -> TeapotScene.camera().setRayTracer(new RayTracerBasic(scene).setBvh(bvh))));
        // The tracing core alone (camera rays through the BVH, closest hit, no shading): the
        // figure comparable with Embree's primary-ray rate.
        for (int threads : new int[] { 1, 2 })
            list.add(new Configuration("teapot", "teapot", TeapotScene::create, "teapot (992 tri + 400 spheres)",
                    "primary rays only (closest hit, no shading)", side, side, threads, true, 0, 1,
                    scene -> TeapotScene.camera().setRayTracer(new PrimaryRayTracer(scene))));
    }

    /**
     * The second report's glossy wall with beams of 1, 5, 10 and 50 rays, 2 threads, then the same
     * on 1 thread for the second thread's speed-up.
     */
    private static void glossy(Options o, List<Configuration> list) {
        int side = o.quick() ? 100 : 1000;
        for (int threads : new int[] { 2, 1 })
            for (int beam : new int[] { 1, 5, 10, 50 })
                list.add(new Configuration("glossy", "glossy", GlossyScene::create,
                        "glossy (8 spheres + 64 polygons, spread " + GlossyScene.DEFAULT_WALL_SPREAD + ")",
                        "beam " + beam, side, side, threads, true, 0, beam > 10 ? 0.25 : 1,
                        scene -> GlossyScene.camera().setRayTracer(new RayTracerBasic(scene).setBeamSize(beam))));
    }

    /** The first report's kind of picture with its four anti-aliasing settings, 2 threads. */
    private static void showcase(Options o, List<Configuration> list) {
        int side = o.quick() ? 60 : 600;
        int big = o.quick() ? 5 : 17, huge = o.quick() ? 9 : 33;
        String label = "showcase (" + Showcase.create().geometries.getItems().size() + " geometries)";
        list.add(showcase(label, "NONE", side, 1, scene -> showcaseCamera(scene).setAntiAliasing(AntiAliasing.NONE)));
        list.add(showcase(label, "ADAPTIVE depth 3 (≤8×8), threshold 8", side, 1,
                scene -> showcaseCamera(scene).setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 8)));
        list.add(showcase(label, "RANDOM " + big + "×" + big, side, 0.25,
                scene -> showcaseCamera(scene).setAntiAliasing(AntiAliasing.RANDOM, big, big)));
        list.add(showcase(label, "RANDOM " + huge + "×" + huge, side, 0.25,
                scene -> showcaseCamera(scene).setAntiAliasing(AntiAliasing.RANDOM, huge, huge)));
    }

    /**
     * Every anti-aliasing mode on the showcase, on 1 and 2 threads: wall time, rays and samples
     * per pixel of each mode, and the 2-thread speed-up (issue 3's report).
     */
    private static void antiAliasing(Options o, List<Configuration> list) {
        int side = o.quick() ? 60 : 600;
        String label = "showcase (" + Showcase.create().geometries.getItems().size() + " geometries)";
        for (int threads : new int[] { 1, 2 }) {
            list.add(aa(label, "NONE", side, threads, s -> showcaseCamera(s).setAntiAliasing(AntiAliasing.NONE)));
            list.add(aa(label, "CORNERS", side, threads, s -> showcaseCamera(s).setAntiAliasing(AntiAliasing.CORNERS)));
            list.add(aa(label, "RANDOM 4×4", side, threads, s -> showcaseCamera(s).setAntiAliasing(AntiAliasing.RANDOM, 4, 4)));
            list.add(aa(label, "RANDOM 8×8", side, threads, s -> showcaseCamera(s).setAntiAliasing(AntiAliasing.RANDOM, 8, 8)));
            list.add(aa(label, "ADAPTIVE depth 3 (≤8×8), threshold 8", side, threads,
                    s -> showcaseCamera(s).setAntiAliasing(AntiAliasing.ADAPTIVE).setAdaptive(3, 8)));
        }
    }

    private static Configuration aa(String label, String settings, int side, int threads, Configuration.CameraFactory camera) {
        return new Configuration("aa", "showcase", Showcase::create, label, settings, side, side, threads, true, 0,
                0.25, camera);
    }

    private static Configuration showcase(String label, String settings, int side, double warmupScale,
                                          Configuration.CameraFactory camera) {
        return new Configuration("showcase", "showcase", Showcase::create, label, settings, side, side, 2, true, 0,
                warmupScale, camera);
    }

    static Camera.Builder showcaseCamera(Scene scene) {
        return Camera.getBuilder()
                .setLocation(Showcase.CAMERA_LOCATION).setDirection(Showcase.CAMERA_TARGET, Vector.AXIS_Y)
                .setVpSize(Showcase.VP_SIZE, Showcase.VP_SIZE).setVpDistance(Showcase.VP_DISTANCE)
                .setRayTracer(new RayTracerBasic(scene));
    }

    /** n spheres + n triangles for n = 10², 10³, ...: with the BVH, and flat up to --flat-max. */
    private static void scaling(Options o, List<Configuration> list) {
        int side = o.quick() ? 60 : 600;
        int max = o.quick() ? Math.min(o.scalingMax(), 1000) : o.scalingMax();
        int flatMax = o.quick() ? Math.min(o.flatMax(), 1000) : o.flatMax();
        // Every BVH row before the flat ones: in one JVM, the flat walks make the JIT's profiles of
        // the shared call sites polymorphic, and the BVH rows after them ran about 10 % slower.
        for (boolean bvh : new boolean[] { true, false })
            for (int n = 100; n <= max; n *= 10) {
                int count = n;
                String label = "scaling (" + power(n) + " spheres + " + power(n) + " triangles)";
                if (!bvh && n > flatMax) continue;
                list.add(new Configuration("scaling", "scaling-" + n, () -> ScalingScene.create(count), label,
                        bvh ? "BVH" : "flat (no BVH)", side, side, 2, bvh, 2L * n, 1,
                        scene -> ScalingScene.camera().setRayTracer(new RayTracerBasic(scene).setBvh(bvh))));
            }
    }

    /** 10ⁿ with a superscript exponent when n is a power of ten, else the plain number. */
    static String power(long n) {
        int e = 0;
        long m = n;
        while (m >= 10 && m % 10 == 0) {
            m /= 10;
            ++e;
        }
        if (m != 1 || e < 2) return String.format(Locale.ROOT, "%,d", n);
        String sup = "⁰¹²³⁴⁵⁶⁷⁸⁹";
        StringBuilder s = new StringBuilder("10");
        for (char c : Integer.toString(e).toCharArray()) s.append(sup.charAt(c - '0'));
        return s.toString();
    }
}
