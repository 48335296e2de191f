/**
 * {@link scene.Scene}: what a render shows (geometries, lights, ambient light, background),
 * built by a scene test and left unchanged while rendering.
 */
package scene;
