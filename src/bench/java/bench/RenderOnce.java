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
        long t0 = System.nanoTime();
        Scene scene = TeapotScene.create();
        long t1 = System.nanoTime();
        Camera camera = TeapotScene.camera()
                .setImageWriter(new ImageWriter("bench/teapot-once", side, side))
                .setRayTracer(new RayTracerBasic(scene))
                .setMultithreading(threads)
                .setSummary(false)
                .build();
        RenderStats stats = camera.render();
        long t2 = System.nanoTime();
        camera.writeToImage();
        long t3 = System.nanoTime();
        // Where a cold process spends its time (the JVM start itself is the rest of the wall time).
        System.out.println(String.format(Locale.ROOT,
                "teapot %dx%d: scene %.3f s, render %.3f s (%.3f s in RenderStats), PNG %.3f s; %s", side, side,
                (t1 - t0) / 1e9, (t2 - t1) / 1e9, stats.seconds(), (t3 - t2) / 1e9, stats));
    }
}
