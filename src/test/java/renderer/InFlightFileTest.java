package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The temporary file an image is written into before it is moved into place. */
class InFlightFileTest {
    @Nested
    @DisplayName("createBeside")
    class CreateBeside {
        @TempDir
        Path folder;

        @Test
        @DisplayName("makes an empty hidden file in the target's folder, named after the target")
        void besideTheTarget() throws IOException {
            Path target = folder.resolve("sphere.png");

            Path tmp = InFlightFile.createBeside(target);

            assertThat(tmp.getParent()).isEqualTo(folder);
            assertThat(tmp.getFileName().toString()).startsWith(".sphere.png.").endsWith(".tmp");
            assertThat(tmp).isEmptyFile();
            assertThat(target).doesNotExist();
        }

        @Test
        @DisplayName("gives a new file on every call, never one that exists")
        void distinct() throws IOException {
            Path target = folder.resolve("sphere.png");
            Set<Path> made = new HashSet<>();
            for (int i = 0; i < 200; ++i) made.add(InFlightFile.createBeside(target));

            assertThat(made).hasSize(200).allSatisfy(p -> assertThat(p).isEmptyFile());
        }

        @Test
        @DisplayName("a missing folder fails with the file system's exception, naming the path")
        void missingFolder() {
            Path target = folder.resolve("missing").resolve("sphere.png");

            assertThatThrownBy(() -> InFlightFile.createBeside(target)).isInstanceOf(NoSuchFileException.class)
                    .hasMessageContaining(folder.resolve("missing").toString());
            assertThat(folder.resolve("missing")).doesNotExist();
            assertThat(Files.exists(target)).isFalse();
        }
    }
}
