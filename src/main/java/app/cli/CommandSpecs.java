package app.cli;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;
import picocli.CommandLine.TypeConversionException;

/**
 * The pieces both commands build their picocli models from, in picocli's programmatic API rather
 * than its annotations: a fresh JVM reads annotations by reflection and makes a proxy class for
 * each annotation type it meets (picocli's own and their meta-annotations), 35-80 ms of every
 * launch on JDK 17 and 25, before the first line of a scene file is read (BENCHMARKS.md, issue 50,
 * eighth session of 2026-11-29). Nothing here reads by reflection: a command takes its values from
 * the parse by name ({@link #value}).
 */
final class CommandSpecs {
    private CommandSpecs() {
    }

    /** An option of one value: its one name, type, label and description. */
    static OptionSpec.Builder option(String name, Class<?> type, String label, String description) {
        return OptionSpec.builder(name).type(type).paramLabel(label).description(description);
    }

    /** An option without a value: true when given. */
    static OptionSpec flag(String name, String description) {
        return OptionSpec.builder(name).type(boolean.class).description(description).build();
    }

    /** {@code -h/--help} and {@code -V/--version}, as picocli's standard help options word them. */
    static void addHelpOptions(CommandSpec spec) {
        spec.addOption(OptionSpec.builder("-h", "--help").usageHelp(true).description("Show this help message and exit.").build());
        spec.addOption(OptionSpec.builder("-V", "--version").versionHelp(true)
                .description("Print version information and exit.").build());
    }

    /** Exit codes and their meanings, in the order given: code, meaning, code, meaning... */
    static Map<String, String> exitCodes(String... codesAndMeanings) {
        Map<String, String> codes = new LinkedHashMap<>();
        for (int i = 0; i < codesAndMeanings.length; i += 2) codes.put(codesAndMeanings[i], codesAndMeanings[i + 1]);
        return codes;
    }

    /**
     * The parsed value of the option or the positional parameter (by its label) {@code name}; an
     * option's initial value, null for most, when it was not given.
     */
    @SuppressWarnings("unchecked")
    static <T> T value(CommandSpec spec, String name) {
        OptionSpec option = spec.findOption(name);
        if (option != null) return (T) option.getValue();
        for (PositionalParamSpec p : spec.positionalParameters())
            if (p.paramLabel().equals(name)) return (T) p.getValue();
        throw new IllegalArgumentException("no option or parameter " + name + " in " + spec.name());
    }

    /** Whether the option without a value {@code name} was given. */
    static boolean given(CommandSpec spec, String name) {
        return Boolean.TRUE.equals(value(spec, name));
    }

    /**
     * A file name as picocli's own Path converter reads it, word for word in its message too; that
     * converter calls Paths.get by reflection, whose first call took JDK 25 about 8 ms of every
     * launch to set up.
     */
    static Path path(String name) {
        try {
            return Path.of(name);
        } catch (InvalidPathException e) {
            throw new TypeConversionException("cannot convert '" + name + "' to " + Path.class + " (" + e + ")");
        }
    }
}
