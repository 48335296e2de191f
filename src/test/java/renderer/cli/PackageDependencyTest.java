package renderer.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/**
 * The command line is the top layer: it uses the library (renderer, scene.io, ...), and no
 * package of the library uses it, so there is no cycle between {@code renderer} and
 * {@code renderer.cli}. Checked on the sources (the tests run from the project root).
 */
class PackageDependencyTest {
    private static final Path SOURCES = Path.of("src/main/java");
    private static final Path CLI = SOURCES.resolve("renderer/cli");
    /** A mention of the package in code: an import, or a qualified name. */
    private static final Pattern USES_CLI = Pattern.compile("\\brenderer\\.cli\\b");

    @Test
    @DisplayName("no source outside renderer.cli mentions renderer.cli")
    void nothingDependsOnTheCli() throws IOException {
        List<Path> library;
        try (Stream<Path> files = Files.walk(SOURCES)) {
            library = files.filter(f -> f.toString().endsWith(".java") && !f.startsWith(CLI)).toList();
        }
        assertThat(library).as("the library's sources").hasSizeGreaterThan(10);
        for (Path file : library)
            assertThat(USES_CLI.matcher(Files.readString(file)).find()).as("%s mentions renderer.cli", file).isFalse();
    }
}
