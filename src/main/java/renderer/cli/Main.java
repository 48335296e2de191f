package renderer.cli;

/**
 * The jar's entry point: {@code java -jar target/raytracer.jar [SCENE] [options]}; see
 * {@link RenderCommand} and {@code --help}. It lives beside the command, so that the package
 * {@code renderer} does not depend on {@code renderer.cli}, which depends on it.
 */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.exit(RenderCommand.run(args));
    }
}
