/**
 * The course's light sources, which scene tests add to {@code scene.lights}:
 * {@link lighting.AmbientLight}, {@link lighting.DirectionalLight} (at infinity),
 * {@link lighting.PointLight} (optionally a disk, for soft shadows) and {@link lighting.SpotLight},
 * behind {@link lighting.LightSource}. Each says the intensity, direction and distance at a
 * shaded point.
 *
 * <p>The engine's, out of the student's sight: the library's lights answer the same three
 * questions about a point given as doubles, and have their settings checked before and after a
 * render; those methods are package-private ({@code DoublesLight}) and the renderer asks them
 * through {@code LightQueries}, which asks a user's own light through its course methods.
 */
package lighting;
