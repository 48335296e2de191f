package scene.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** {@link Messages#reason(IOException)}: why a file could not be read, in a few words. */
class MessagesTest {
    static Stream<Arguments> failures() {
        return Stream.of(
                Arguments.of("missing file", new NoSuchFileException("/tmp/a.xml"), "no such file"),
                Arguments.of("unreadable file", new AccessDeniedException("/tmp/a.xml"), "access denied"),
                Arguments.of("file system reason", new FileSystemException("/tmp/a.xml", null, "Is a directory"),
                        "Is a directory"),
                Arguments.of("file system exception without a reason", new NotDirectoryException("/tmp/a"),
                        "/tmp/a"),
                Arguments.of("other exception with a message", new IOException("disk on fire"), "disk on fire"),
                Arguments.of("other exception without a message", new IOException(), "IOException"),
                Arguments.of("other exception with a blank message", new IOException(" "), "IOException"));
    }

    @ParameterizedTest(name = "{0} → \"{2}\"")
    @MethodSource("failures")
    void reason(String name, IOException failure, String expected) {
        assertThat(Messages.reason(failure)).isEqualTo(expected);
    }
}
