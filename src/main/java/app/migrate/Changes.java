package app.migrate;

import java.io.IOException;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * Every file a plan changes, with the text it leaves, worked out before anything is written: the
 * moves, the rewritten sources, the pom, the IntelliJ module, {@code .idea/compiler.xml} and the
 * report, in the order {@link Apply} makes them.
 */
final class Changes {
    private Changes() {
    }

    /**
     * Every file's change but the report's, which names them.
     *
     * @param files      the changes, in the order they are made
     * @param pomChanges what an update of the student's own pom changes, in words (empty for a new pom)
     */
    record Draft(List<Change> files, List<String> pomChanges) {
        /** These changes, then the report kept as {@link Plan#REPORT}: every change, the report last. */
        List<Change> withReport(List<String> report) {
            List<Change> all = new ArrayList<>(files);
            all.add(Change.create(Plan.REPORT, String.join("\n", report) + "\n"));
            return List.copyOf(all);
        }
    }

    /**
     * @throws MigrationException when a build file cannot be read, or the pom cannot be updated
     */
    static Draft of(Project project, Plan plan) throws MigrationException {
        Layout layout = project.layout();
        Path d = layout.dir();
        Charset charset = project.encoding().charset();
        List<Change> changes = new ArrayList<>();
        for (SourceFile f : plan.course())
            changes.add(Change.move(f.relative(d), Layout.BACKUP + "/" + f.relative(d), f.text(), charset));
        for (SourceFile f : plan.setAside().keySet())
            changes.add(Change.move(f.relative(d), Plan.SET_ASIDE + f.relative(d), f.text(), charset));
        for (Kept k : Stream.concat(plan.extras().stream(), plan.tests().stream()).filter(Kept::changed).toList())
            changes.add(Change.replace(k.file().relative(d), Layout.relative(d, k.target()), k.file().text(), k.text(), charset));
        Path pom = d.resolve("pom.xml");
        List<String> pomChanges = List.of();
        if (Files.isRegularFile(pom)) {
            String text = read(pom);
            PomFile.Updated updated = PomFile.update(text, plan.build());
            pomChanges = updated.changes();
            changes.add(Change.replace("pom.xml", "pom.xml", text, updated.text(), StandardCharsets.UTF_8));
        } else {
            changes.add(Change.create("pom.xml", PomFile.create(plan.build(), d.getFileName().toString())));
        }
        if (layout.iml() != null) {
            String iml = read(layout.iml());
            String added = ImlFile.addLibrary(iml, plan.build());
            String path = Layout.relative(d, layout.iml());
            if (added != null && !added.equals(iml)) changes.add(Change.replace(path, path, iml, added, StandardCharsets.UTF_8));
        }
        Path compilerXml = d.resolve(".idea/compiler.xml");
        if (Files.isDirectory(d.resolve(".idea")) && !plan.leftOut().isEmpty()) {
            List<String> leftOut = plan.leftOut().keySet().stream().map(f -> f.relative(d)).toList();
            if (Files.isRegularFile(compilerXml)) {
                String xml = read(compilerXml);
                changes.add(Change.replace(".idea/compiler.xml", ".idea/compiler.xml", xml, ImlFile.exclude(xml, leftOut),
                        StandardCharsets.UTF_8));
            } else {
                changes.add(Change.create(".idea/compiler.xml", ImlFile.exclude(null, leftOut)));
            }
        }
        return new Draft(List.copyOf(changes), pomChanges);
    }

    private static String read(Path file) throws MigrationException {
        try {
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new MigrationException("cannot read " + file + ": " + e.getMessage() + " (nothing was changed)", e);
        }
    }
}
