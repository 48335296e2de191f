/**
 * Light sources: ambient, directional (at infinity), point (optionally a disk, for soft
 * shadows) and spot. Each says the intensity, direction and distance at a shaded point.
 */
package lighting;
