package renderer;

import renderer.cli.RenderCommand;

/**
 * The jar's entry point: {@code java -jar target/raytracer.jar [SCENE] [options]}; see
 * {@link RenderCommand} and {@code --help}.
 */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.exit(RenderCommand.run(args));
    }
}
