package app.spark;

import java.io.IOException;
import java.io.Serializable;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

import scene.io.FileSource;
import scene.io.LoadedScene;
import scene.io.SceneFormatException;
import scene.io.XmlSceneReader;

/**
 * A scene file with the bytes of every file its reading needed (the scene and its OBJ meshes),
 * captured on the driver while it validates the scene, so that an executor parses exactly those
 * bytes: it needs no shared file system, and a file changed meanwhile cannot make it render
 * something else. Files are keyed by the path as the reader resolved it, so messages match.
 */
final class SceneFiles implements Serializable {
    private static final long serialVersionUID = 1L;

    private final String scene;
    /** The folder meshes may come from, as the driver was given it; null: the scene's own. */
    private final String meshRoot;
    /** Path (as resolved by the reader) → content; insertion order is reading order. */
    private final LinkedHashMap<String, byte[]> contents;

    private SceneFiles(String scene, String meshRoot, LinkedHashMap<String, byte[]> contents) {
        this.scene = scene;
        this.meshRoot = meshRoot;
        this.contents = contents;
    }

    /** A scene as the driver read it: the parsed scene, and the files that reading used. */
    record Captured(LoadedScene loaded, SceneFiles files) {
    }

    /**
     * Reads and validates a scene file from the disk, keeping the bytes of every file read.
     *
     * @param meshRoot the folder meshes may be read from; null: the scene file's own folder
     * @throws IOException          when the scene file cannot be read
     * @throws SceneFormatException when it is not a valid scene (a mesh that cannot be read, or
     *                              outside the folder, included)
     */
    static Captured read(Path scene, Path meshRoot) throws IOException, SceneFormatException {
        Objects.requireNonNull(scene, "scene");
        LinkedHashMap<String, byte[]> contents = new LinkedHashMap<>();
        LoadedScene loaded = XmlSceneReader.read(scene, (file, maxBytes) -> {
            byte[] bytes = FileSource.DISK.readAllBytes(file, maxBytes);
            contents.put(file.toString(), bytes);
            return bytes;
        }, meshRoot);
        return new Captured(loaded, new SceneFiles(scene.toString(), meshRoot == null ? null : meshRoot.toString(), contents));
    }

    /**
     * Parses the captured bytes again (on an executor).
     *
     * @throws IOException          never for a capture of a valid scene (a file the capture does
     *                              not hold is a {@link NoSuchFileException})
     * @throws SceneFormatException never for a capture of a valid scene
     */
    LoadedScene load() throws IOException, SceneFormatException {
        return XmlSceneReader.read(Path.of(scene), (file, maxBytes) -> {
            byte[] bytes = contents.get(file.toString());
            if (bytes == null) throw new NoSuchFileException(file.toString(), null, "not sent with the scene");
            return bytes;
        }, meshRoot == null ? null : Path.of(meshRoot));
    }

    /** @return the scene file as the user named it */
    String scene() {
        return scene;
    }

    /** @return the number of bytes captured, all files together (what the broadcast carries) */
    long size() {
        long size = 0;
        for (Map.Entry<String, byte[]> e : contents.entrySet()) size += e.getValue().length;
        return size;
    }
}
