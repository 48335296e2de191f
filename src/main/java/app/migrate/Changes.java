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
     * @param report the summary, kept as {@link Plan#REPORT} (the last change)
     * @throws MigrationException when a build file cannot be read, or the pom cannot be updated
     */
    static List<Change> of(Project project, Plan plan, List<String> report) throws MigrationException {
        Layout layout = project.layout();
        Path d = layout.dir();
        Charset charset = project.encoding().charset();
        List<Change> changes = new ArrayList<>();
        for (SourceFile f : plan.course())
            changes.add(Change.move(f.relative(d), Layout.BACKUP + "/" + f.relative(d), f.text()));
        for (SourceFile f : plan.setAside().keySet())
            changes.add(Change.move(f.relative(d), Plan.SET_ASIDE + f.relative(d), f.text()));
        for (Kept k : Stream.concat(plan.extras().stream(), plan.tests().stream()).filter(Kept::changed).toList())
            changes.add(Change.replace(k.file().relative(d), Layout.relative(d, k.target()), k.file().text(), k.text(), charset));
        Path pom = d.resolve("pom.xml");
        if (Files.isRegularFile(pom)) {
            String text = read(pom);
            changes.add(Change.replace("pom.xml", "pom.xml", text, PomFile.update(text, plan.build()).text(), StandardCharsets.UTF_8));
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
        changes.add(Change.create(Plan.REPORT, String.join("\n", report) + "\n"));
        return changes;
    }

    private static String read(Path file) throws MigrationException {
        try {
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new MigrationException("cannot read " + file + ": " + e.getMessage() + " (nothing was changed)", e);
        }
    }
}
