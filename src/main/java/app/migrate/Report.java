package app.migrate;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

/** The summary a migration prints and keeps as {@code course-backup/migration-report.txt}. */
final class Report {
    private Report() {
    }

    /** @param pomChanges what the update of the student's own pom changes, in words (empty for a new pom) */
    static List<String> lines(Path d, Project project, Plan plan, List<String> pomChanges, Toolchain tools) {
        Layout layout = project.layout();
        BuildPlan build = plan.build();
        List<String> r = new ArrayList<>();
        r.add("raytracer migrate: " + d + " (" + layout.kind().label + ": " + Layout.names(d, layout.mainRoots())
                + (layout.testRoots().isEmpty() ? "" : "; tests " + Layout.names(d, layout.testRoots()))
                + "; Java release " + build.release() + "; sources in " + project.encoding().describe() + ")");
        if (!project.strays().isEmpty())
            r.add("Tests found outside the folders your build names, now test folders: " + Layout.names(d, project.strays()));
        if (!project.libraries().isEmpty()) {
            r.add("Your libraries, now dependencies in pom.xml: " + project.libraries().size());
            project.libraries().forEach(l -> r.add("  " + l.describe() + (project.resolved().containsKey(l) ? ""
                    : l.systemPath() != null ? "; not in the project (never committed?): left out of pom.xml"
                    : "; not in " + tools.mavenRepository() + ", and mvn could not fetch it now (mvn test will try again)")));
        }
        if (!plan.choices().isEmpty()) {
            r.add("Where your code chose otherwise than the library (docs/student-guide.md, \"Which course year?\"):");
            plan.choices().forEach(c -> r.add("  " + c.line()));
        }
        List<SourceFile> courses = plan.course().stream().filter(f -> Catalog.isCourseClass(f.className())).toList();
        List<SourceFile> namesakes = plan.course().stream().filter(f -> !Catalog.isCourseClass(f.className())).toList();
        r.add("Moved to " + Layout.BACKUP + "/ (the library provides them): " + courses.size() + " classes");
        Map<String, List<String>> byPackage = new TreeMap<>();
        courses.forEach(f -> byPackage.computeIfAbsent(f.packageName(), p -> new ArrayList<>()).add(f.simpleName()
                + (project.relocated().containsKey(f.className()) ? " (as the library's " + project.relocated().get(f.className()) + ")"
                        : "")));
        byPackage.forEach((p, names) -> r.add("  " + (p.isEmpty() ? "(no package)" : p) + ": " + String.join(", ", names)));
        if (!namesakes.isEmpty())
            r.add("Moved to " + Layout.BACKUP + "/ too (your own classes, named as classes inside the library, beside which they"
                    + " cannot stay; the library's BVH is always on in place of one of yours): " + String.join(", ",
                            namesakes.stream().map(SourceFile::className).toList()));
        List<Kept> extras = plan.extras();
        List<Kept> keptCourse = extras.stream().filter(k -> Catalog.isCourseClassInCoursePackage(k.file().className())).toList();
        if (!keptCourse.isEmpty()) {
            r.add("Kept (course classes the library has no class for; they compile against it): " + keptCourse.size());
            keptCourse.forEach(k -> r.add("  " + Layout.relative(d, k.target())));
        }
        r.add("Kept (your own classes; they compile against the library): " + (extras.size() - keptCourse.size()));
        extras.stream().filter(k -> !keptCourse.contains(k)).forEach(k -> r.add("  " + Layout.relative(d, k.target())));
        if (!plan.setAside().isEmpty()) {
            r.add("Set aside into " + Plan.SET_ASIDE + " (they do not compile against the library): " + plan.setAside().size());
            plan.setAside().forEach((f, why) -> r.add("  " + why));
        }
        Map<SourceFile, String> leftOut = plan.leftOut();
        r.add("Tests kept: " + plan.tests().size() + " files" + (leftOut.isEmpty() ? "" : "; left out of the build (the files"
                + " stay where they are, excluded in pom.xml): " + leftOut.size()));
        leftOut.forEach((f, why) -> r.add("  " + why));
        if (plan.tests().isEmpty() && leftOut.isEmpty())
            r.add("Warning: no JUnit test was found in this project (none in " + Layout.names(d, layout.mainRoots())
                    + (layout.testRoots().isEmpty() ? "" : ", " + Layout.names(d, layout.testRoots())) + " or any other folder):"
                    + " mvn test will run none; if your tests are elsewhere, name that folder in your .iml or pom and migrate again");
        if (!plan.trimmed().isEmpty()) {
            r.add("Tests kept with some of their methods left out (each replaced by a comment line naming why): "
                    + plan.trimmed().size() + " files");
            plan.trimmed().forEach((f, why) -> r.add("  " + why));
        }
        long rewritten = Stream.concat(extras.stream(), plan.tests().stream()).filter(Kept::changed).count();
        if (rewritten > 0)
            r.add("Rewritten (package and import lines pointed at the library's classes, or test methods taken out as said above): " + rewritten
                    + " files (originals in " + Change.ORIGINALS + ")");
        if (!Files.isRegularFile(d.resolve("pom.xml")))
            r.add("pom.xml: written (" + build.library() + ", JUnit " + build.junit() + ", Java release " + build.release()
                    + ", every test class runs whatever its name)");
        else
            r.add("pom.xml: updated (" + (pomChanges.isEmpty() ? "it had all the library needs" : String.join(", ", pomChanges)) + ")");
        if (layout.iml() != null)
            r.add(d.relativize(layout.iml()) + ": the library jar added (from " + tools.mavenRepository() + ")");
        if (!Files.isRegularFile(tools.installedJar())) {
            // Without it, mvn test ends in Maven's "Could not find artifact": the step comes first.
            r.add("The library is not installed in " + tools.mavenRepository() + " yet (mvn test would say \"Could not find"
                    + " artifact " + tools.coordinates() + "\"); install it first, and again after pulling a newer version:");
            r.add("  cd " + tools.libraryClone().map(Path::toString).orElse("<the raytracer clone>") + " && mvn -q install -DskipTests");
        }
        r.add("Next: cd " + d + " && mvn test   (IntelliJ: Build > Rebuild Project, then run your tests)");
        r.add("Undo: raytracer migrate --undo " + d + (Files.isDirectory(d.resolve(".git"))
                ? "   (or with git: git status lists every change)" : ""));
        return r;
    }
}
