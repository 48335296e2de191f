package app.cli;

/**
 * The jar's entry point: {@code java -jar target/raytracer.jar [SCENE] [options]}; see
 * {@link RenderCommand} and {@code --help}. The package {@code app} holds the entry points, the
 * top layer: it uses the library, and nothing in the library uses it.
 */
public final class Main {
    private Main() {
    }

    /**
     * Renders a scene file (or the built-in showcase) and exits with the command's code: 0 done,
     * 1 failure while rendering, 2 bad input.
     *
     * @param args the command line; {@code --help} lists it
     */
    public static void main(String[] args) {
        System.exit(RenderCommand.run(args));
    }
}
