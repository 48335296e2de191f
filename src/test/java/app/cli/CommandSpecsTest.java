package app.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/** The programmatic model's pieces: what a command reads back from a parse, by name. */
class CommandSpecsTest {
    /** A command of one positional, one valued option and one flag, parsed from {@code args}. */
    private static CommandSpec parsed(String... args) {
        CommandSpec spec = CommandSpec.wrapWithoutInspection((Callable<Integer>) () -> 0).name("test");
        spec.addPositional(PositionalParamSpec.builder().index("0").arity("0..1").paramLabel("FILE").type(Path.class).build());
        spec.addOption(CommandSpecs.option("--count", Integer.class, "N", "how many").build());
        spec.addOption(CommandSpecs.flag("--fast", "hurry"));
        CommandSpecs.addHelpOptions(spec);
        CommandLine cl = new CommandLine(spec);
        cl.registerConverter(Path.class, CommandSpecs::path);
        cl.parseArgs(args);
        return spec;
    }

    @Test
    @DisplayName("given values come back typed, by option name and by a positional's label")
    void givenValues() {
        CommandSpec spec = parsed("--count", "3", "--fast", "a.xml");
        assertThat(CommandSpecs.<Integer>value(spec, "--count")).isEqualTo(3);
        assertThat(CommandSpecs.given(spec, "--fast")).isTrue();
        assertThat(CommandSpecs.<Path>value(spec, "FILE")).isEqualTo(Path.of("a.xml"));
    }

    @Test
    @DisplayName("what was not given is null, and a flag not given is false")
    void absentValues() {
        CommandSpec spec = parsed();
        assertThat(CommandSpecs.<Integer>value(spec, "--count")).isNull();
        assertThat(CommandSpecs.<Path>value(spec, "FILE")).isNull();
        assertThat(CommandSpecs.given(spec, "--fast")).isFalse();
    }

    @Test
    @DisplayName("a name the model does not declare is a programming error that names it")
    void unknownName() {
        assertThatThrownBy(() -> CommandSpecs.value(parsed(), "--colour"))
                .isInstanceOf(IllegalArgumentException.class).hasMessage("no option or parameter --colour in test");
    }

    @Test
    @DisplayName("exit codes keep the order given")
    void exitCodeOrder() {
        assertThat(CommandSpecs.exitCodes("0", "done", "2", "bad input", "1", "failed").keySet()).containsExactly("0", "2", "1");
    }
}
