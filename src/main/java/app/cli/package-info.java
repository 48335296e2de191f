/**
 * The command line ({@code java -jar raytracer.jar}): renders a scene file or the built-in
 * showcase. An entry point above the library; it alone needs picocli, which a library user does
 * not inherit.
 */
package app.cli;
