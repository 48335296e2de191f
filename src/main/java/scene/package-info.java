/**
 * The course's {@link scene.Scene}: what a render shows (geometries, lights, ambient light,
 * background), filled by a scene test and left unchanged while rendering.
 */
package scene;
