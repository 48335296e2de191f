package app.cli;

import static app.cli.CommandSpecs.addHelpOptions;
import static app.cli.CommandSpecs.exitCodes;
import static app.cli.CommandSpecs.flag;
import static app.cli.CommandSpecs.given;
import static app.cli.CommandSpecs.option;
import static app.cli.CommandSpecs.value;

import java.io.PrintStream;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import app.migrate.Migration;
import app.migrate.MigrationException;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.PositionalParamSpec;

/**
 * {@code raytracer migrate DIR}: a course project onto the library (see {@link Migration}). Exit
 * codes: 0 migrated (or nothing to do), 2 refused before anything changed (not a course project,
 * does not compile as it is, read-only, an earlier backup in the way, uncommitted git changes),
 * 1 failed part-way and taken back.
 */
final class MigrateCommand implements Callable<Integer> {
    private static final String DIR = "DIR", UNDO = "--undo", DRY_RUN = "--dry-run", ALLOW_DIRTY = "--allow-dirty",
            ENCODING = "--encoding";

    private final PrintStream out;
    private final PrintStream err;

    private final CommandSpec spec;

    MigrateCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
        this.spec = model(this);
    }

    /** The subcommand's model for picocli, in its programmatic API (see {@link CommandSpecs} for why). */
    private static CommandSpec model(MigrateCommand command) {
        CommandSpec spec = CommandSpec.wrapWithoutInspection(command).name("migrate");
        spec.usageMessage().sortOptions(false).autoWidth(true)
                .description("Moves a course project (an IntelliJ module with src/ and unittests/, an Eclipse, plain or"
                        + " Maven project) onto the library, with nothing lost: the course classes the library provides go"
                        + " to DIR/course-backup/, your own classes stay, a pom.xml builds the project where it stands, and"
                        + " every test that does not compile against the library is left out of the build with its reason.",
                        "Nothing is deleted; --undo takes the whole migration back.")
                .exitCodeListHeading("%nExit codes:%n")
                .exitCodeList(exitCodes("0", "migrated, or already migrated (nothing changed)",
                        "2", "refused before anything changed (the reason in one line)",
                        "1", "failed part-way and taken back (nothing changed)"));
        // The folder as a string: it becomes a Path in call(), where a name this locale cannot hold
        // is said in the command's words.
        spec.addPositional(PositionalParamSpec.builder().index("0").arity("1").required(true).paramLabel(DIR).type(String.class)
                .description("The course project's folder (the one with src/ or pom.xml).").build());
        spec.addOption(flag(UNDO, "Take back the migration of DIR, as course-backup/migrate-manifest.tsv records it"
                + " (refused when a file changed since)."));
        spec.addOption(flag(DRY_RUN, "Print the summary and the exact change, as a unified diff (paths relative to DIR;"
                + " git apply takes it); change nothing."));
        spec.addOption(flag(ALLOW_DIRTY, "Migrate a git folder that has uncommitted changes."));
        spec.addOption(option(ENCODING, String.class, "CHARSET", "The sources'"
                + " character encoding (windows-1255, ISO-8859-1, UTF-8); by default as the project states it (pom,"
                + " .idea/encodings.xml, Eclipse settings), else detected. It is written into the pom.").build());
        addHelpOptions(spec);
        return spec;
    }

    CommandSpec spec() {
        return spec;
    }

    @Override
    public Integer call() {
        try {
            Migration migration = Migration.ofThisProcess(out, err);
            Path folder = Path.of(CommandSpecs.<String>value(spec, DIR));
            if (given(spec, UNDO)) migration.undo(folder);
            else migration.migrate(folder, given(spec, ALLOW_DIRTY), given(spec, DRY_RUN), value(spec, ENCODING));
            return 0;
        } catch (MigrationException e) {
            err.println(RenderCommand.NAME + " migrate: " + e.getMessage());
            return e.partWay() ? RenderCommand.FAILURE : RenderCommand.BAD_INPUT;
        } catch (InvalidPathException e) {
            // A name (the folder's, or a file's in it) that the locale's file-name encoding cannot
            // hold: LANG=C and a Hebrew folder name. Nothing was changed: names are read first.
            err.println(RenderCommand.NAME + " migrate: cannot name " + e.getInput() + " in this locale's file-name encoding ("
                    + System.getProperty("sun.jnu.encoding", "unknown") + "): run it with a UTF-8 locale, such as"
                    + " LANG=C.UTF-8 (nothing was changed)");
            return RenderCommand.BAD_INPUT;
        }
    }
}
