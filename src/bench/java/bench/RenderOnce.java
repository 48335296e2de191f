package bench;

import java.util.Locale;

import renderer.Camera;
import renderer.ImageWriter;
import renderer.RayTracerBasic;
import renderer.RenderStats;
import scene.Scene;
import scene.samples.TeapotScene;

/**
 * One cold render of the course teapot from JVM start to PNG, for timing the whole process
 * (see BENCHMARKS.md: {@code hyperfine} or {@code /usr/bin/time} around
 * {@code java -cp target/bench/classes bench.RenderOnce}). Renders 1000×1000, one ray per pixel,
 * with the BVH on all cores, into {@code images/bench/teapot-once.png}.
 *
 * <p>Arguments (optional): the image side in pixels (default 1000) and the thread count
 * (default -2: all cores).
 */
public final class RenderOnce {
    private RenderOnce() {
    }

    public static void main(String[] args) {
        int side = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        int threads = args.length > 1 ? Integer.parseInt(args[1]) : -2;
        Scene scene = TeapotScene.create();
        Camera camera = TeapotScene.camera()
                .setImageWriter(new ImageWriter("bench/teapot-once", side, side))
                .setRayTracer(new RayTracerBasic(scene))
                .setMultithreading(threads)
                .setSummary(false)
                .build();
        RenderStats stats = camera.render();
        camera.writeToImage();
        System.out.println(String.format(Locale.ROOT, "teapot %dx%d: render %.3f s (%s)", side, side, stats.seconds(),
                stats));
    }
}
