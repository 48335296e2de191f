/**
 * The course's light sources, which scene tests add to {@code scene.lights}:
 * {@link lighting.AmbientLight}, {@link lighting.DirectionalLight} (at infinity),
 * {@link lighting.PointLight} (optionally a disk, for soft shadows) and {@link lighting.SpotLight},
 * behind {@link lighting.LightSource}. Each says the intensity, direction and distance at a
 * shaded point.
 */
package lighting;
