/**
 * The built-in scenes: the showcase, the course teapot, the glossy scene and the scaling scene,
 * used by the command line, the benchmarks and the tests; each is deterministic.
 */
package scene.samples;
