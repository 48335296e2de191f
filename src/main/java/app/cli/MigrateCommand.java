package app.cli;

import java.io.PrintStream;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import app.migrate.Migration;
import app.migrate.MigrationException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code raytracer migrate DIR}: a course project onto the library (see {@link Migration}). Exit
 * codes: 0 migrated (or nothing to do), 2 refused before anything changed (not a course project,
 * does not compile as it is, read-only, an earlier backup in the way, uncommitted git changes),
 * 1 failed part-way and taken back.
 */
@Command(name = "migrate", mixinStandardHelpOptions = true, sortOptions = false, usageHelpAutoWidth = true,
        description = { "Moves a course project (an IntelliJ module with src/ and unittests/, an Eclipse, plain or Maven"
                + " project) onto the library, with nothing lost: the course classes the library provides go to"
                + " DIR/course-backup/, your own classes stay, a pom.xml builds the project where it stands, and"
                + " every test that does not compile against the library is left out of the build with its reason.",
                "Nothing is deleted; --undo takes the whole migration back." },
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = { "0:migrated, or already migrated (nothing changed)",
                "2:refused before anything changed (the reason in one line)",
                "1:failed part-way and taken back (nothing changed)" })
final class MigrateCommand implements Callable<Integer> {
    @Parameters(paramLabel = "DIR", description = "The course project's folder (the one with src/ or pom.xml).")
    private String dir; // turned into a Path here, where a name this locale cannot hold is said in the command's words

    @Option(names = "--undo", description = "Take back the migration of DIR, as course-backup/migrate-manifest.tsv records it"
            + " (refused when a file changed since).")
    private boolean undo;

    @Option(names = "--dry-run", description = "Print the summary and the exact change, as a unified diff (paths relative"
            + " to DIR; git apply takes it); change nothing.")
    private boolean dryRun;

    @Option(names = "--allow-dirty", description = "Migrate a git folder that has uncommitted changes.")
    private boolean allowDirty;

    @Option(names = "--encoding", paramLabel = "CHARSET", description = "The sources' character encoding (windows-1255,"
            + " ISO-8859-1, UTF-8); by default as the project states it (pom, .idea/encodings.xml, Eclipse settings),"
            + " else detected. It is written into the pom.")
    private String encoding;

    private final PrintStream out;
    private final PrintStream err;

    MigrateCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    @Override
    public Integer call() {
        try {
            Migration migration = Migration.ofThisProcess(out, err);
            Path folder = Path.of(dir);
            if (undo) migration.undo(folder);
            else migration.migrate(folder, allowDirty, dryRun, encoding);
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
