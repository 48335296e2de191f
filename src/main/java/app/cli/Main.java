package app.cli;

/**
 * The jar's entry point: {@code java -jar target/raytracer.jar [SCENE] [options]}; see
 * {@link RenderCommand} and {@code --help}. The package {@code app} holds the entry points, the
 * top layer: it uses the library, and nothing in the library uses it.
 */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        System.exit(RenderCommand.run(args));
    }
}
