package scene.io;

import static scene.io.ValueType.BOOLEAN;
import static scene.io.ValueType.COEFFICIENTS;
import static scene.io.ValueType.COLOR;
import static scene.io.ValueType.GRID;
import static scene.io.ValueType.INTEGER;
import static scene.io.ValueType.LONG;
import static scene.io.ValueType.NON_NEGATIVE;
import static scene.io.ValueType.POINT;
import static scene.io.ValueType.POSITIVE;
import static scene.io.ValueType.POSITIVE_INTEGER;
import static scene.io.ValueType.SIZE;
import static scene.io.ValueType.TEXT;
import static scene.io.ValueType.VECTOR;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.function.BiFunction;

import geometries.BoundingBox;
import geometries.Cylinder;
import geometries.Geometry;
import geometries.LeanQueries;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightQueries;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Checks;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Vector;
import renderer.AntiAliasing;
import renderer.Camera;
import renderer.Execution;
import renderer.Sampling;
import renderer.View;
import scene.Scene;

/**
 * Reads a scene file (the format is described in docs/scene-format.md) into a {@link Scene} and
 * the specification of its render as the file states it: the view and the {@link RenderSettings},
 * replayed onto a camera builder when a camera is asked for ({@link LoadedScene}). The course's
 * scene files read unchanged:
 * {@code <scene background-color="75 127 90"><ambient-light color="255 191 191"/><geometries>
 * <sphere center="0 0 -100" radius="50"/>…}.
 *
 * <p>The reader builds everything through the library's public API; geometry classes know
 * nothing about XML. It is strict: an unknown element or attribute, a missing or malformed value,
 * or a value the library refuses stops the reading with a {@link SceneFormatException} that
 * names the file, line and column and says what was expected. Nothing is guessed.
 */
public final class XmlSceneReader {
    private static final List<String> SCENE_CHILDREN = List.of("ambient-light", "geometries", "lights", "camera",
            "image", "render");
    private static final List<String> GEOMETRIES = List.of("sphere", "plane", "polygon", "triangle", "tube",
            "cylinder", "mesh");
    private static final List<String> LIGHTS = List.of("directional-light", "point-light", "spot-light");
    private static final List<String> RENDER_CHILDREN = List.of("anti-aliasing", "depth-of-field");
    /** Attributes a schema-aware editor adds to the root; they do not concern the scene. */
    private static final List<String> SCHEMA_ATTRIBUTES = List.of("xmlns:xsi", "xsi:noNamespaceSchemaLocation");

    // Settings validated by the library's own setters, so the rules live in one place.
    private static final ValueType<Integer> THREADS = INTEGER.narrowedBy(
            "0 (the calling thread), a number of threads up to " + Camera.MAX_THREADS_PER_CORE + " per core, or -1 or -2 (all cores)",
            Execution::requireThreads);
    private static final ValueType<Integer> ADAPTIVE_DEPTH = INTEGER.narrowedBy("an integer from 1 to 6",
            Sampling.Adaptive::requireDepth);
    private static final ValueType<int[]> AA_GRID = GRID.narrowedBy(GRID.expected() + ", at most "
            + Camera.MAX_SAMPLES_PER_PIXEL + " samples", g -> new Sampling.Grid(g[0], g[1]));
    private static final ValueType<Integer> LENS_SAMPLES = POSITIVE_INTEGER.narrowedBy("an integer from 1 to "
            + Camera.MAX_SAMPLES_PER_PIXEL, Sampling::requireLensSamples);
    private static final ValueType<Integer> SHININESS = INTEGER.narrowedBy("an integer ≥ 0",
            n -> Checks.requireNonNegative(n, "shininess"));
    private static final ValueType<String> IMAGE_NAME = TEXT.narrowedBy("a file name without /, \\, :, .., control"
            + " characters or invisible format characters (U+202E...), at most " + RenderSettings.MAX_IMAGE_NAME_LENGTH + " characters (the image goes"
            + " to images/<name>.png; only the command line's -o chooses another place)", RenderSettings::requireImageName);

    private final Path file;
    private final String fileName;
    private final FileSource files;
    /** The folder meshes must lie in (absolute, normalized): the scene file's unless the caller chose another. */
    private final Path meshRoot;

    private XmlSceneReader(Path file, FileSource files, Path meshRoot) {
        this.file = file;
        this.fileName = file.toString();
        this.files = files;
        this.meshRoot = (meshRoot != null ? meshRoot : file.toAbsolutePath().getParent()).toAbsolutePath().normalize();
    }

    /**
     * Reads a scene file (UTF-8). Mesh files are found relative to the scene file's folder and
     * must lie in it (see {@link #read(Path, FileSource, Path)}).
     *
     * @param file the scene file; messages name it as given
     * @return the scene, its view when the file has a camera, and its render settings
     * @throws IOException          when the file cannot be read
     * @throws SceneFormatException when its content is not a valid scene (the message names the
     *                              place and what was expected)
     */
    public static LoadedScene read(Path file) throws IOException, SceneFormatException {
        return read(file, FileSource.DISK);
    }

    /**
     * As {@link #read(Path)}, with the bytes of the scene file and of its meshes taken from
     * {@code files} (paths and messages are the same as when read from the disk). The scene file
     * is held to {@link Limits#MAX_SCENE_BYTES}, each mesh to {@link Limits#MAX_OBJ_BYTES}.
     *
     * @param file  the scene file as the user named it
     * @param files where the bytes of {@code file} and of the meshes it references come from
     * @return the scene, its view and its settings
     * @throws IOException          when {@code files} cannot give the scene file
     * @throws SceneFormatException when its content is not a valid scene, or the file is not a
     *                              regular file or is larger than the limit
     */
    public static LoadedScene read(Path file, FileSource files) throws IOException, SceneFormatException {
        return read(file, files, null);
    }

    /**
     * As {@link #read(Path, FileSource)}, with the folder the meshes must lie in. A scene file
     * from someone else must not read other files of the machine: a mesh path is resolved against
     * the scene file's folder, must stay inside {@code meshRoot} (by its path, and, when the file
     * exists, by its real path, so that a link cannot lead out), and must name an OBJ file
     * ({@code .obj}); otherwise the file is refused, unread, with one message naming the path.
     *
     * @param file     the scene file as the user named it
     * @param files    where the bytes of {@code file} and of the meshes it references come from
     * @param meshRoot the folder meshes may be read from, sub-folders included; null: the scene
     *                 file's own folder
     * @return the scene, its view and its settings
     * @throws IOException          when {@code files} cannot give the scene file
     * @throws SceneFormatException when its content is not a valid scene (a mesh outside the
     *                              folder or not an OBJ file included), or the file is not a
     *                              regular file or is larger than the limit
     */
    public static LoadedScene read(Path file, FileSource files, Path meshRoot) throws IOException, SceneFormatException {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(files, "files");
        byte[] content;
        try {
            content = files.readAllBytes(file, Limits.MAX_SCENE_BYTES);
        } catch (FileSource.RefusedFileException e) {
            throw new SceneFormatException(file.toString(), 0, 0, e.reason()
                    + " (expected an XML scene file within the limit; meshes go in OBJ files)");
        }
        return parse(content, file, files, meshRoot);
    }

    /**
     * Reads a scene file's content as if it were at {@code file} (for messages and mesh paths);
     * meshes come from the disk.
     */
    static LoadedScene read(byte[] content, Path file) throws SceneFormatException {
        return parse(content, file, FileSource.DISK, null);
    }

    private static LoadedScene parse(byte[] content, Path file, FileSource files, Path meshRoot)
            throws SceneFormatException {
        String text = decodeUtf8(content, file.toString());
        if (text.startsWith("\uFEFF")) text = text.substring(1); // a byte-order mark is not content
        XmlSceneReader reader = new XmlSceneReader(file, files, meshRoot);
        return reader.scene(XmlTreeBuilder.parse(text, reader.fileName));
    }

    /**
     * Decodes strictly: the parser is given text, so bytes that are not UTF-8 are reported here,
     * at their line and column.
     */
    private static String decodeUtf8(byte[] bytes, String fileName) throws SceneFormatException {
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length); // UTF-8 never decodes to more chars than bytes
        CoderResult result = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT).decode(in, out, true);
        if (result.isError()) {
            String before = out.flip().toString();
            SourceText decoded = new SourceText(before);
            int line = decoded.line(before.length());
            throw new SceneFormatException(fileName, line, decoded.column(before.length()),
                    "bytes that are not UTF-8 (expected an XML scene file encoded in UTF-8)");
        }
        return out.flip().toString();
    }

    private LoadedScene scene(XmlElement root) throws SceneFormatException {
        if (!root.name().equals("scene"))
            throw root.error("the root element is <" + root.name() + "> (expected <scene>)");
        List<String> allowed = new ArrayList<>(List.of("name", "background-color"));
        allowed.addAll(SCHEMA_ATTRIBUTES);
        root.allowAttributes(allowed);
        Scene scene = new Scene(root.optional("name", TEXT, defaultName()));
        scene.setBackground(root.optional("background-color", COLOR, Color.BLACK));

        Map<String, XmlElement> parts = uniqueChildren(root, SCENE_CHILDREN);
        XmlElement part;
        if ((part = parts.get("ambient-light")) != null) scene.setAmbientLight(ambientLight(part));
        if ((part = parts.get("geometries")) != null) geometries(part, scene);
        if ((part = parts.get("lights")) != null) lights(part, scene);
        XmlElement image = parts.get("image");
        RenderSettings settings = RenderSettings.defaults(image != null && image.has("name")
                ? image.required("name", IMAGE_NAME) : imageNameOf(root, scene.name));
        if (image != null) settings = image(image, settings);
        if ((part = parts.get("render")) != null) settings = render(part, settings, scene);
        else if ((part = parts.get("lights")) != null) // the defaults, these lights: blamed at <lights>
            requireRayBudget(List.of(new Stated(part, "", settings)), scene);
        ViewSpec view = (part = parts.get("camera")) != null ? camera(part) : null;
        return new LoadedScene(scene, view, settings, view != null ? null
                : root.error("the scene has no <camera> (expected a <camera> element inside <scene> to render it)"));
    }

    /**
     * The scene's name as the image's, when no {@code <image name>} is given: it must then be a
     * plain file name too (see {@link RenderSettings#requireImageName(String)}).
     */
    private static String imageNameOf(XmlElement root, String sceneName) throws SceneFormatException {
        try {
            return RenderSettings.requireImageName(sceneName);
        } catch (IllegalArgumentException ex) {
            String reason = "the scene name names the image: " + ex.getMessage() + " (expected " + IMAGE_NAME.expected()
                    + ", or an <image name=\"…\">)";
            throw root.has("name") ? root.errorAt("name", reason, ex) : root.error(reason, ex);
        }
    }

    /** The scene's name when the file gives none: the file name without its extension. */
    private String defaultName() {
        String name = file.getFileName() == null ? "scene" : file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(0, dot) : name;
    }

    /**
     * The children of {@code parent}, each allowed at most once.
     */
    private static Map<String, XmlElement> uniqueChildren(XmlElement parent, List<String> allowed)
            throws SceneFormatException {
        Map<String, XmlElement> parts = new HashMap<>();
        for (XmlElement child : parent.children()) {
            expectKnown(child, parent, allowed);
            if (parts.putIfAbsent(child.name(), child) != null)
                throw child.error("a second <" + child.name() + "> in <" + parent.name() + "> (expected at most one, the first is at line "
                        + parts.get(child.name()).line() + ")");
        }
        return parts;
    }

    private static void expectKnown(XmlElement child, XmlElement parent, List<String> allowed)
            throws SceneFormatException {
        if (!allowed.contains(child.name()))
            throw child.error("unknown element <" + child.name() + "> in <" + parent.name() + "> (expected "
                    + (allowed.isEmpty() ? "no child elements" : "one of: " + String.join(", ", allowed)) + ")");
    }

    private static void noChildren(XmlElement element) throws SceneFormatException {
        if (!element.children().isEmpty()) expectKnown(element.children().get(0), element, List.of());
    }

    // ---------------------------------------------------------------- lights

    /** The course writes only the colour; kA defaults to 1 as in its Java scenes. */
    private static AmbientLight ambientLight(XmlElement e) throws SceneFormatException {
        e.allowAttributes(List.of("color", "ka"));
        noChildren(e);
        return new AmbientLight(e.required("color", COLOR), e.optional("ka", COEFFICIENTS, Double3.ONE));
    }

    private static void lights(XmlElement lights, Scene scene) throws SceneFormatException {
        lights.allowAttributes(List.of());
        for (XmlElement e : lights.children()) {
            expectKnown(e, lights, LIGHTS);
            noChildren(e);
            scene.lights.add(light(e));
        }
    }

    private static LightSource light(XmlElement e) throws SceneFormatException {
        switch (e.name()) {
            case "directional-light" -> {
                e.allowAttributes(List.of("color", "direction"));
                return new DirectionalLight(e.required("color", COLOR), e.required("direction", VECTOR));
            }
            case "point-light" -> {
                e.allowAttributes(List.of("color", "position", "kc", "kl", "kq", "radius"));
                PointLight light = new PointLight(e.required("color", COLOR), e.required("position", POINT));
                attenuation(e, light);
                return light;
            }
            default -> { // spot-light
                e.allowAttributes(List.of("color", "position", "direction", "kc", "kl", "kq", "radius", "narrow-beam"));
                SpotLight light = new SpotLight(e.required("color", COLOR), e.required("position", POINT),
                        e.required("direction", VECTOR));
                attenuation(e, light);
                e.ifPresent("narrow-beam", POSITIVE, light::setNarrowBeam);
                return light;
            }
        }
    }

    private static void attenuation(XmlElement e, PointLight light) throws SceneFormatException {
        e.ifPresent("kc", NON_NEGATIVE, light::setKc);
        e.ifPresent("kl", NON_NEGATIVE, light::setKl);
        e.ifPresent("kq", NON_NEGATIVE, light::setKq);
        e.ifPresent("radius", NON_NEGATIVE, light::setRadius);
        try {
            LightQueries.validate(light); // checked here, not when rendering, to report it at its place
        } catch (IllegalArgumentException ex) {
            String at = e.has("kc") ? "kc" : e.has("kl") ? "kl" : "kq";
            String reason = "invalid <" + e.name() + ">: " + ex.getMessage() + " (expected kc, kl and kq ≥ 0, not all 0)";
            throw e.has(at) ? e.errorAt(at, reason, ex) : e.error(reason, ex);
        }
    }

    // ---------------------------------------------------------------- geometries

    private void geometries(XmlElement geometries, Scene scene) throws SceneFormatException {
        geometries.allowAttributes(List.of());
        for (XmlElement e : geometries.children()) {
            expectKnown(e, geometries, GEOMETRIES);
            Geometry geometry = geometry(e);
            geometry.setEmission(e.optional("emission", COLOR, Color.BLACK));
            Map<String, XmlElement> parts = uniqueChildren(e, List.of("material"));
            if (parts.containsKey("material")) geometry.setMaterial(material(parts.get("material")));
            scene.geometries.add(geometry);
        }
    }

    /** The shape itself (emission and material are common to all and set by the caller). */
    private Geometry geometry(XmlElement e) throws SceneFormatException {
        switch (e.name()) {
            case "sphere" -> {
                e.allowAttributes(List.of("center", "radius", "emission"));
                Point center = e.required("center", POINT);
                double radius = e.required("radius", POSITIVE);
                return construct(e, "a center and a positive radius", () -> new Sphere(center, radius));
            }
            case "plane" -> {
                e.allowAttributes(List.of("p0", "p1", "p2", "point", "normal", "emission"));
                if (e.has("point") || e.has("normal")) {
                    for (String p : List.of("p0", "p1", "p2"))
                        if (e.has(p))
                            throw e.errorAt(p, "<plane> takes either p0, p1, p2 or point and normal, not both"
                                    + " (expected one of the two forms)");
                    Point q = e.required("point", POINT);
                    Vector normal = e.required("normal", VECTOR);
                    return construct(e, "a point and a non-zero normal", () -> new Plane(q, normal));
                }
                Point[] p = vertices(e, 3);
                return construct(e, "three distinct points not on one line", () -> new Plane(p[0], p[1], p[2]));
            }
            case "triangle" -> {
                e.allowAttributes(List.of("p0", "p1", "p2", "emission"));
                Point[] p = vertices(e, 3);
                return construct(e, "three distinct points not on one line", () -> new Triangle(p[0], p[1], p[2]));
            }
            case "polygon" -> {
                int n = 0;
                while (e.has("p" + n)) ++n;
                List<String> allowed = new ArrayList<>();
                for (int i = 0; i <= Math.max(n, 2); ++i) allowed.add("p" + i);
                allowed.add("emission");
                e.allowAttributes(allowed);
                Point[] p = vertices(e, Math.max(n, 3));
                return construct(e, "at least 3 vertices p0, p1, p2, … of a convex planar polygon, in order",
                        () -> new Polygon(p));
            }
            case "tube" -> {
                e.allowAttributes(List.of("radius", "origin", "axis", "emission"));
                double radius = e.required("radius", POSITIVE);
                Ray axis = new Ray(e.required("origin", POINT), e.required("axis", VECTOR));
                return construct(e, "a positive radius, a point on the axis and the axis direction",
                        () -> new Tube(radius, axis));
            }
            case "mesh" -> {
                e.allowAttributes(List.of("file", "emission"));
                return mesh(e);
            }
            default -> { // cylinder
                e.allowAttributes(List.of("radius", "origin", "axis", "height", "emission"));
                double radius = e.required("radius", POSITIVE);
                Ray axis = new Ray(e.required("origin", POINT), e.required("axis", VECTOR));
                double height = e.required("height", POSITIVE);
                return construct(e, "a positive radius, the centre of the base, the axis direction and a positive height",
                        () -> new Cylinder(radius, axis, height));
            }
        }
    }

    /**
     * A triangle mesh from an OBJ file, whose path is relative to the scene file's folder (or
     * absolute). A missing or malformed OBJ file is reported at the {@code file} attribute.
     */
    private Geometry mesh(XmlElement e) throws SceneFormatException {
        String expected = "an OBJ file; a relative path starts at the scene file's folder";
        Path obj = meshFile(e);
        try {
            // Decoded as ObjReader.read(Path) does: UTF-8, malformed bytes replaced (only comments
            // and names may hold them, and those are ignored).
            byte[] bytes;
            try {
                bytes = files.readAllBytes(obj, Limits.MAX_OBJ_BYTES);
            } catch (FileSource.RefusedFileException refused) {
                throw new ObjFormatException(obj.toString(), 0, refused.reason());
            } catch (OutOfMemoryError oom) { // the file's bytes alone: named as the reader names its own
                long size;
                try {
                    size = Files.size(obj);
                } catch (IOException unknown) {
                    size = -1; // the message goes without the size
                }
                throw ObjReader.outOfMemory(oom, obj.toString(), size, 0, 0, false);
            }
            TriangleMesh mesh = ObjReader.read(new InputStreamReader(new ByteArrayInputStream(bytes), StandardCharsets.UTF_8),
                    obj.toString(), bytes.length);
            requireWithinRange(LeanQueries.boundingBox(mesh), obj);
            return mesh;
        } catch (ObjFormatException ex) {
            throw e.errorAt("file", e.quote("file") + ": " + ex.getMessage() + " (expected " + expected + ")", ex);
        } catch (IOException ex) {
            throw e.errorAt("file", e.quote("file") + ": cannot read " + obj + ": " + Messages.reason(ex) + " (expected " + expected + ")", ex);
        }
    }

    /**
     * The mesh file of {@code e}, resolved against the scene file's folder, if it names an OBJ
     * file inside {@link #meshRoot} (by its path, and by its real path when it exists).
     */
    private Path meshFile(XmlElement e) throws SceneFormatException {
        String name = e.required("file", TEXT);
        String allowed = " (expected an OBJ file inside " + meshRoot + "; the command line's --mesh-root DIR allows"
                + " another folder)";
        Path obj;
        try {
            obj = file.resolveSibling(name);
        } catch (InvalidPathException ex) {
            throw e.errorAt("file", e.quote("file") + ": not a path: " + ex.getReason() + allowed);
        }
        Path fileName = obj.getFileName();
        if (fileName == null || !fileName.toString().toLowerCase(Locale.ROOT).endsWith(".obj"))
            throw e.errorAt("file", e.quote("file") + ": " + obj + " is not an OBJ file (its name does not end in .obj)"
                    + allowed);
        if (!obj.toAbsolutePath().normalize().startsWith(meshRoot))
            throw e.errorAt("file", e.quote("file") + ": " + obj + " is outside the folder meshes are read from" + allowed);
        boolean linkedOut;
        try {
            linkedOut = Files.exists(obj) && !obj.toRealPath().startsWith(meshRoot.toRealPath());
        } catch (IOException ex) { // gone meanwhile, or unreadable: reading it says so
            linkedOut = false;
        }
        if (linkedOut)
            throw e.errorAt("file", e.quote("file") + ": " + obj + " leads outside the folder meshes are read from"
                    + " (through a link)" + allowed);
        return obj;
    }

    /**
     * A mesh's vertices are held to the scene file's number range ({@link Limits#MAX_MAGNITUDE}),
     * as its own coordinates are: the OBJ reader takes any finite number, and a vertex at 1e300
     * would overflow the squared lengths of shading and fail the render instead of the load.
     */
    private static void requireWithinRange(BoundingBox box, Path obj) throws ObjFormatException {
        double extent = Math.max(Math.max(Math.max(-box.getMinX(), box.getMaxX()), Math.max(-box.getMinY(), box.getMaxY())),
                Math.max(-box.getMinZ(), box.getMaxZ()));
        if (extent > Limits.MAX_MAGNITUDE)
            throw new ObjFormatException(obj.toString(), 0, "a vertex coordinate of magnitude " + extent
                    + ", larger than " + ValueType.format(Limits.MAX_MAGNITUDE) + " (the limit of a scene's numbers)");
    }

    /** Required attributes p0 … p(n-1). */
    private static Point[] vertices(XmlElement e, int n) throws SceneFormatException {
        Point[] p = new Point[n];
        for (int i = 0; i < n; ++i) p[i] = e.required("p" + i, POINT);
        return p;
    }

    /** A shape constructor whose IllegalArgumentException becomes a message at the element. */
    @FunctionalInterface
    private interface Construction {
        Geometry build();
    }

    private static Geometry construct(XmlElement e, String expected, Construction construction)
            throws SceneFormatException {
        try {
            return construction.build();
        } catch (IllegalArgumentException ex) {
            throw e.error("invalid <" + e.name() + ">: " + ex.getMessage() + " (expected " + expected + ")", ex);
        }
    }

    private static Material material(XmlElement e) throws SceneFormatException {
        e.allowAttributes(List.of("kd", "ks", "kt", "kr", "shininess", "reflection-spread", "transmission-spread", "ior"));
        noChildren(e);
        Material m = new Material();
        e.ifPresent("kd", COEFFICIENTS, m::setKd);
        e.ifPresent("ks", COEFFICIENTS, m::setKs);
        e.ifPresent("kt", COEFFICIENTS, m::setKt);
        e.ifPresent("kr", COEFFICIENTS, m::setKr);
        e.ifPresent("shininess", SHININESS, m::setShininess);
        e.ifPresent("reflection-spread", NON_NEGATIVE, m::setReflectionSpread);
        e.ifPresent("transmission-spread", NON_NEGATIVE, m::setTransmissionSpread);
        e.ifPresent("ior", POSITIVE, m::setIor);
        return m;
    }

    // ---------------------------------------------------------------- image, render, camera

    private static RenderSettings image(XmlElement e, RenderSettings s) throws SceneFormatException {
        e.allowAttributes(List.of("name", "width", "height", "grid-interval", "grid-color"));
        noChildren(e);
        if (e.has("width") || e.has("height")) {
            // Stated together: a side the file leaves out is the format's default.
            int width = e.optional("width", POSITIVE_INTEGER, s.width());
            int height = e.optional("height", POSITIVE_INTEGER, s.height());
            try {
                s = s.withImageSize(width, height);
            } catch (IllegalArgumentException ex) { // too many pixels: each side alone is valid
                String at = e.has("width") ? "width" : "height";
                throw e.errorAt(at, e.quote(at) + ": " + ex.getMessage() + " (expected width × height at most "
                        + RenderSettings.MAX_PIXELS + " pixels)", ex);
            }
        }
        if (e.has("grid-interval") || e.has("grid-color"))
            s = s.withGrid(e.optional("grid-interval", POSITIVE_INTEGER, 0), e.optional("grid-color", COLOR, s.gridColor()));
        return s;
    }

    /** {@code s} with the value of {@code attribute} stated by {@code with}, when {@code e} has it. */
    private static <T> RenderSettings stated(XmlElement e, String attribute, ValueType<T> type, RenderSettings s,
            BiFunction<RenderSettings, T, RenderSettings> with) throws SceneFormatException {
        return e.has(attribute) ? with.apply(s, e.required(attribute, type)) : s;
    }

    /**
     * The {@code <render>} element: its attributes, then {@code <anti-aliasing>}, then
     * {@code <depth-of-field>}, each stated over the one before; the ray budget is checked once,
     * when the element is read whole.
     */
    private static RenderSettings render(XmlElement e, RenderSettings s, Scene scene) throws SceneFormatException {
        e.allowAttributes(List.of("threads", "seed", "bvh", "beam-size", "shadow-samples"));
        s = stated(e, "threads", THREADS, s, RenderSettings::withThreads);
        s = stated(e, "seed", LONG, s, RenderSettings::withSeed);
        s = stated(e, "bvh", BOOLEAN, s, RenderSettings::withBvh);
        s = stated(e, "beam-size", POSITIVE_INTEGER, s, RenderSettings::withBeamSize);
        s = stated(e, "shadow-samples", POSITIVE_INTEGER, s, RenderSettings::withShadowSamples);
        // What the file states up to each element, in the file's order: where a budget over the limit is blamed.
        List<Stated> stated = new ArrayList<>(3);
        stated.add(new Stated(e, e.has("beam-size") ? "beam-size" : "shadow-samples", s));
        Map<String, XmlElement> parts = uniqueChildren(e, RENDER_CHILDREN);
        XmlElement aa = parts.get("anti-aliasing");
        if (aa != null) {
            aa.allowAttributes(List.of("mode", "grid", "depth", "threshold"));
            noChildren(aa);
            s = stated(aa, "grid", AA_GRID, s, (r, grid) -> r.withAntiAliasingGrid(grid[0], grid[1]));
            AntiAliasing mode = aa.required("mode", ValueType.enumeration(AntiAliasing.class));
            s = stated(aa, "depth", ADAPTIVE_DEPTH, s.withAntiAliasing(mode), RenderSettings::withAdaptiveDepth);
            s = stated(aa, "threshold", NON_NEGATIVE, s, RenderSettings::withAdaptiveThreshold);
            stated.add(new Stated(aa, mode == AntiAliasing.RANDOM ? "grid" : mode == AntiAliasing.ADAPTIVE ? "depth" : "mode", s));
        }
        XmlElement dof = parts.get("depth-of-field");
        if (dof != null) {
            dof.allowAttributes(List.of("focal-distance", "aperture", "samples"));
            noChildren(dof);
            double focalDistance = dof.required("focal-distance", POSITIVE);
            double aperture = dof.required("aperture", NON_NEGATIVE);
            s = stated(dof, "samples", LENS_SAMPLES, s.withDepthOfField(focalDistance, aperture),
                    RenderSettings::withDepthOfFieldSamples);
            stated.add(new Stated(dof, "samples", s));
        }
        requireRayBudget(stated, scene);
        return s;
    }

    /**
     * What a file states up to and including {@code element}, and where a ray budget these
     * settings exceed is reported: at {@code attribute} of {@code element}, or at the element
     * when the attribute is not written (a default, or the lights, made the product too large).
     */
    private record Stated(XmlElement element, String attribute, RenderSettings settings) {
    }

    /**
     * The library's ray budget (see {@link RenderSettings#requireRayBudget(Scene)}) for every
     * setting the file states (the last of {@code stated}), over the scene's lights (read before
     * the settings): checked once. Only when it fails are the earlier parts checked, to report the
     * budget where reading the file in order first exceeds it, with that part's figures; the
     * settings as a whole may be within it although a part is not (a lens takes ADAPTIVE's depth
     * 6 at 4,096 samples, not the 4,225 of its lattice), and are then accepted, as the camera is.
     *
     * @param stated the file's settings, element by element, in the file's order; not empty
     */
    private static void requireRayBudget(List<Stated> stated, Scene scene) throws SceneFormatException {
        Stated all = stated.get(stated.size() - 1);
        try {
            all.settings.requireRayBudget(scene);
        } catch (IllegalArgumentException over) {
            for (Stated part : stated.subList(0, stated.size() - 1)) {
                try {
                    part.settings.requireRayBudget(scene);
                } catch (IllegalArgumentException first) {
                    first.addSuppressed(over); // the whole's figures, kept beside the part's
                    throw overBudget(part, first);
                }
            }
            throw overBudget(all, over);
        }
    }

    /** The error of a budget {@code part} exceeds, at its attribute or element, with the library's message. */
    private static SceneFormatException overBudget(Stated part, IllegalArgumentException ex) {
        XmlElement e = part.element;
        String reason = "invalid <" + e.name() + ">: " + ex.getMessage() + " (expected samples per pixel"
                + " × (1 + 2 × beam-size) × (1 + shadow-samples × lights with a radius + other lights) at most "
                + RenderSettings.MAX_RAYS_PER_PIXEL + ")";
        return e.has(part.attribute) ? e.errorAt(part.attribute, reason, ex) : e.error(reason, ex);
    }

    /**
     * The camera's view (location, direction, view plane) as the file states it, checked as a
     * camera built from it will check it.
     */
    private static ViewSpec camera(XmlElement e) throws SceneFormatException {
        e.allowAttributes(List.of("location", "direction", "up", "target", "vp-size", "vp-distance"));
        noChildren(e);
        Point location = e.required("location", POINT);
        if (e.has("direction") && e.has("target"))
            throw e.errorAt("target", "<camera> takes either direction and up, or target, not both"
                    + " (expected one of the two forms)");
        ViewSpec.Direction direction;
        if (e.has("direction")) {
            Vector to = e.required("direction", VECTOR);
            Vector up = e.required("up", VECTOR);
            try {
                View.Frame.along(to, up); // setDirection(to, up)'s rule, checked here to report it at 'up'
            } catch (IllegalArgumentException ex) {
                throw e.errorAt("up", "invalid <camera>: " + ex.getMessage()
                        + " (expected an up vector orthogonal to the direction)", ex);
            }
            direction = new ViewSpec.Along(to, up);
        } else if (e.has("target")) {
            direction = new ViewSpec.Toward(e.required("target", POINT), e.optional("up", VECTOR, null));
        } else {
            throw e.error("<camera> is missing its view direction (expected attributes direction and up, or target)");
        }
        double[] size = e.required("vp-size", SIZE);
        ViewSpec view = new ViewSpec(location, direction, size[0], size[1], e.required("vp-distance", POSITIVE));

        // The checks that need every part (target at the location, up along the view) are the
        // library's rules for the view a camera built from the file will have.
        View checked;
        try {
            checked = view.view();
        } catch (IllegalArgumentException ex) {
            throw e.error("invalid <camera>: " + ex.getMessage()
                    + " (expected a target away from the location and an up not along the view direction)", ex);
        }
        // The rays through the view plane's centre and quarters: a view plane too near or too
        // small for the location's precision gives them no direction (the zero vector).
        try {
            checked.constructRay(1, 1, 0, 0);
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) checked.constructRay(2, 2, j, i);
        } catch (IllegalArgumentException ex) {
            throw e.errorAt("vp-distance", "invalid <camera>: no ray through the view plane: " + ex.getMessage()
                    + " (expected a view plane whose distance and size are not lost in the precision of the location)", ex);
        }
        return view;
    }
}
