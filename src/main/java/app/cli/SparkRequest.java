package app.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.function.BiFunction;

import scene.Scene;
import scene.io.RenderSettings;

/**
 * What the command line asks of a Spark render.
 *
 * @param master       the Spark master URL ({@code local[2]}, {@code spark://host:7077},
 *                     {@code yarn}, {@code k8s://…}), or {@value #SUBMIT} for the master that
 *                     {@code spark-submit --master} configured
 * @param scenes       the scene files, at least one; several are frames of one job
 * @param settings     the command line's changes to each file's settings, given the file's scene
 *                     (its lights count in the ray budget); it may throw the command line's usage
 *                     error
 * @param output       the PNG to write, for a single scene; null: images/&lt;image name&gt;.png
 * @param progressStep percent between progress lines; 0: none
 * @param summary      whether to print the summary and the "wrote" lines
 * @param meshRoot     the folder the scenes' meshes may be read from; null: each scene file's own
 */
public record SparkRequest(String master, List<Path> scenes, BiFunction<RenderSettings, Scene, RenderSettings> settings,
                           Path output, double progressStep, boolean summary, Path meshRoot) {
    /** The master value that defers to spark-submit's {@code --master}. */
    public static final String SUBMIT = "submit";

    /**
     * Checks the request; the scene list is copied.
     *
     * @param master       the Spark master URL, or {@value #SUBMIT}
     * @param scenes       the scene files, at least one
     * @param settings     the changes to each file's settings
     * @param output       the PNG of a single scene; null for the default
     * @param progressStep percent between progress lines; 0: none
     * @param summary      whether to print the summary and the "wrote" lines
     * @param meshRoot     the folder the scenes' meshes may be read from; null: each scene file's own
     * @throws IllegalArgumentException for no scene, or an output with several scenes
     */
    public SparkRequest {
        Objects.requireNonNull(master, "master");
        scenes = List.copyOf(scenes);
        Objects.requireNonNull(settings, "settings");
        if (scenes.isEmpty()) throw new IllegalArgumentException("a Spark render needs at least one scene file");
        if (output != null && scenes.size() > 1)
            throw new IllegalArgumentException("one output file for " + scenes.size()
                    + " scenes: several frames are written to images/<image name>.png each");
    }

    /**
     * A request whose meshes lie in each scene file's own folder.
     *
     * @param master       the Spark master URL, or {@value #SUBMIT}
     * @param scenes       the scene files, at least one
     * @param settings     the changes to each file's settings
     * @param output       the PNG of a single scene; null for the default
     * @param progressStep percent between progress lines; 0: none
     * @param summary      whether to print the summary and the "wrote" lines
     * @throws IllegalArgumentException for no scene, or an output with several scenes
     */
    public SparkRequest(String master, List<Path> scenes, BiFunction<RenderSettings, Scene, RenderSettings> settings,
                        Path output, double progressStep, boolean summary) {
        this(master, scenes, settings, output, progressStep, summary, null);
    }
}
