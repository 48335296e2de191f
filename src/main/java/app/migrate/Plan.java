package app.migrate;

import java.util.List;
import java.util.Map;

/**
 * Everything a migration decided in its scratch folder, before the project changes: what moves,
 * what stays (and its new text), what is set aside or left out and why, and the build.
 *
 * @param course   the course classes the library provides: they move into {@code course-backup/}
 * @param extras   the student's other classes that compile against the library
 * @param setAside those that do not, each with its line for the summary
 * @param tests    the tests that compile against the library
 * @param leftOut  those that do not (left where they are, excluded from the build), with their lines
 * @param trimmed  tests kept without some of their methods, with their lines
 * @param choices  where the student's course classes chose otherwise than the library
 * @param build    what the build files must say
 */
record Plan(List<SourceFile> course, List<Kept> extras, Map<SourceFile, String> setAside, List<Kept> tests,
        Map<SourceFile, String> leftOut, Map<SourceFile, String> trimmed, List<CourseChoices.Choice> choices, BuildPlan build) {
    static final String REPORT = Layout.BACKUP + "/migration-report.txt";
    static final String SET_ASIDE = Layout.BACKUP + "/set-aside/";
}
