/**
 * Scenes from files: the XML scene format ({@link scene.io.XmlSceneReader}, with its render
 * settings) and Wavefront OBJ meshes ({@link scene.io.ObjReader}). Errors name the file, the
 * line and what was wrong.
 */
package scene.io;
