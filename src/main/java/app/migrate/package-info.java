/**
 * {@code raytracer migrate DIR}: a course project, as students keep it (an IntelliJ module with
 * {@code src/} and {@code unittests/}, an Eclipse or plain folder, or a Maven project), onto the
 * library in one command, with nothing lost.
 *
 * <p>The steps, each its own class: {@link app.migrate.Layout} reads where the sources and tests
 * are; {@link app.migrate.Catalog} tells which of the student's classes the library provides
 * (those move to {@code course-backup/}); {@link app.migrate.CourseChoices} names where the
 * student's own code chose otherwise than the library where course years disagree;
 * {@link app.migrate.Javac} compiles the kept extras and the tests against the library, and
 * {@link app.migrate.Reasons} says per file why one does not compile; {@link app.migrate.PomFile}
 * and {@link app.migrate.ImlFile} write the build; {@link app.migrate.Manifest} records every
 * change so that {@code --undo} can take it back; {@link app.migrate.Migration} runs the whole.
 * Entry-point layer: it uses the library (to know its classes) and nothing in the library uses it.
 */
package app.migrate;
