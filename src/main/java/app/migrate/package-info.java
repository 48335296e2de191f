/**
 * {@code raytracer migrate DIR}: a course project, as students keep it (an IntelliJ module with
 * {@code src/} and {@code unittests/}, an Eclipse or plain folder, or a Maven project), onto the
 * library in one command, with nothing lost.
 *
 * <p>The steps, each its own class, run in order by {@link app.migrate.Migration} (which nothing
 * here calls back): {@link app.migrate.Layout} reads where the sources and tests are, once;
 * {@link app.migrate.Preflight} refuses, before anything changes, what cannot be migrated;
 * {@link app.migrate.Catalog} tells which of the student's classes the library provides (those move
 * to {@code course-backup/}); {@link app.migrate.CourseChoices} names where the student's own code
 * chose otherwise than the library where course years disagree; {@link app.migrate.Planner}
 * compiles ({@link app.migrate.Javac}) the kept extras and the tests against the library, rewritten
 * by {@link app.migrate.SourceRewrite} through javac's parser, and {@link app.migrate.Reasons} says
 * per file why one does not compile; {@link app.migrate.PomPatterns} says what the build must hold,
 * and {@link app.migrate.Changes} works out every file's new text ({@link app.migrate.PomFile},
 * {@link app.migrate.ImlFile}) before anything is written; {@link app.migrate.Report} is the
 * summary; {@code --dry-run} prints the changes as a {@link app.migrate.UnifiedDiff};
 * {@link app.migrate.Apply} writes exactly them, each recorded first in the
 * {@link app.migrate.Manifest}, so that {@link app.migrate.Undo} can take them back.
 * Entry-point layer: it uses the library (to know its classes) and nothing in the library uses it.
 */
package app.migrate;
