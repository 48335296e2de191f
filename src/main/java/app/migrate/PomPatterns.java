package app.migrate;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/** What the build must say after the migration ({@link BuildPlan}): its folders, and its include and exclude patterns. */
final class PomPatterns {
    private PomPatterns() {
    }

    static BuildPlan buildPlan(Toolchain tools, Project project, List<SourceFile> extras, List<SourceFile> tests,
            Set<SourceFile> leftOut, int release) {
        Layout layout = project.layout();
        Path d = layout.dir();
        List<String> mainRoots = layout.mainRoots().stream().map(r -> Layout.relative(d, r)).toList();
        Set<Path> testRootPaths = new LinkedHashSet<>(layout.testRoots());
        tests.forEach(t -> testRootPaths.add(t.root()));
        List<String> testRoots = testRootPaths.stream().filter(r -> tests.stream().anyMatch(t -> t.root().equals(r)))
                .map(r -> Layout.relative(d, r)).toList();
        // Tests in a folder that also holds sources: out of the main compile, and the only part of
        // that folder the test compile takes.
        List<SourceFile> mixed = tests.stream().filter(t -> layout.mainRoots().contains(t.root())).toList();
        List<SourceFile> all = new ArrayList<>(extras);
        all.addAll(tests);
        List<String> mainExcludes = patterns(mixed, all);
        List<String> testIncludes = mixed.isEmpty() ? List.of() : patterns(tests, all);
        List<String> testExcludes = leftOut.stream().map(SourceFile::inRoot).sorted().toList();
        boolean junit4 = Libraries.JUnit4.usedBy(tests);
        return new BuildPlan(tools.coordinates(), tools.junitVersion(), release, mainRoots, testRoots, mainExcludes,
                testIncludes, testExcludes, project.libraries().stream()
                        .filter(l -> l.systemPath() == null || project.resolved().containsKey(l)).toList(),
                junit4, project.encoding().charset().name());
    }

    /** Patterns for {@code chosen} within their folders: {@code unittests/**} where a whole top folder is chosen. */
    static List<String> patterns(List<SourceFile> chosen, List<SourceFile> all) {
        Set<String> out = new LinkedHashSet<>();
        for (SourceFile f : chosen) {
            String inRoot = f.inRoot();
            int slash = inRoot.indexOf('/');
            if (slash < 0) {
                out.add(inRoot);
                continue;
            }
            String top = inRoot.substring(0, slash + 1);
            boolean whole = all.stream().filter(a -> a.root().equals(f.root()) && a.inRoot().startsWith(top))
                    .allMatch(chosen::contains);
            out.add(whole ? top + "**" : inRoot);
        }
        return List.copyOf(out);
    }
}
