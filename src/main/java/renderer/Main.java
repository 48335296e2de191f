package renderer;

import primitives.Vector;
import scene.Scene;
import scene.samples.Showcase;

/** Temporary entry point: renders the showcase. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        Scene scene = Showcase.create();
        long t0 = System.nanoTime();
        Camera camera = Camera.getBuilder()
                .setLocation(Showcase.CAMERA_LOCATION).setDirection(Showcase.CAMERA_TARGET, Vector.AXIS_Y)
                .setVpSize(Showcase.VP_SIZE, Showcase.VP_SIZE).setVpDistance(Showcase.VP_DISTANCE)
                .setImageWriter(new ImageWriter("showcase", 600, 600))
                .setRayTracer(new RayTracerBasic(scene))
                .setAntiAliasing(args.length > 0 ? AntiAliasing.valueOf(args[0]) : AntiAliasing.ADAPTIVE)
                .setMultithreading(-2)
                .build();
        camera.renderImage().writeToImage();
        System.out.printf("wrote images/showcase.png in %.2f s%n", (System.nanoTime() - t0) / 1e9);
    }
}
