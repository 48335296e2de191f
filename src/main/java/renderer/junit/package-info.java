/**
 * Image assertions for JUnit tests: {@link renderer.junit.ImageAssertions} compares a render (a
 * {@link renderer.Camera}'s image or a PNG) with a reference image by the metrics and limits
 * ({@link renderer.junit.ImageThresholds}) of the project's OpenImageIO verification, and
 * {@link renderer.junit.RenderReports} publishes each render's figures in the test's report.
 * <p>Optional: it needs {@code junit-jupiter-api} on the class path, which the library's users
 * have in their tests; a user who never calls it needs nothing more.
 */
package renderer.junit;
