package app.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import app.Project;

/**
 * The launcher's list of methods for the quick compiler to inline
 * ({@code scripts/quick-tier.compilecommands}): the JVM ignores a name that matches nothing without
 * a word, and refuses a line it cannot parse, so a renamed method or a stray comment would quietly
 * cost the short renders their speed. This holds the list to the classes as they are.
 */
class QuickTierInliningTest {
    private static final Pattern INLINE = Pattern.compile("inline ([a-z]+(?:\\.[A-Za-z][A-Za-z0-9]*)+)::([A-Za-z][A-Za-z0-9]*)");

    /** The file's commands: its lines without blank lines and whole-line comments. */
    static List<String> commands() throws IOException {
        try (Stream<String> lines = Files.lines(Project.file("scripts", "quick-tier.compilecommands"))) {
            return lines.filter(l -> !l.isBlank() && !l.startsWith("#")).toList();
        }
    }

    static Stream<String> inlines() throws IOException {
        return commands().stream().skip(1);
    }

    @Test
    void quietComesFirstSoThatTheJvmPrintsNothingOnStandardOutput() throws IOException {
        assertThat(commands()).first().isEqualTo("quiet");
    }

    @ParameterizedTest
    @MethodSource("inlines")
    void everyOtherLineInlinesAMethodThatExists(String line) throws ClassNotFoundException {
        Matcher m = INLINE.matcher(line);
        assertThat(m.matches()).as("'%s' is 'inline package.Class::method', nothing after it", line).isTrue();
        Class<?> type = Class.forName(m.group(1), false, getClass().getClassLoader());
        assertThat(Arrays.stream(type.getDeclaredMethods()).map(Method::getName))
                .as("%s declares %s", type.getName(), m.group(2)).contains(m.group(2));
    }
}
