package renderer;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import geometries.BoundingBox;
import geometries.Cylinder;
import geometries.Geometries;
import geometries.Geometry;
import geometries.Hit;
import geometries.HitVisitor;
import geometries.Intersectable;
import geometries.Plane;
import geometries.Polygon;
import geometries.Sphere;
import geometries.Triangle;
import geometries.TriangleMesh;
import geometries.Tube;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import lighting.PointLight;
import lighting.SpotLight;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Rgb;
import primitives.Util;
import primitives.Vector;
import scene.Scene;

/**
 * The course face: what a student sees in code completion on a course class is the course's API
 * (docs API.md and COURSE-YEARS.md, every year's spelling), the one-line improvements and the
 * library's few documented getters, and nothing of the engine. Each course class's public
 * methods, inherited ones included, and for a class a student may subclass its protected ones too,
 * are held equal to the list below: a new public method on a course class fails here until it is
 * either added to the list (it is course API) or moved behind a package-private method and an
 * internal facade (it is the engine's, as {@code geometries.LeanQueries}). Methods of
 * {@code Object} and {@code Enum} are left out; {@code equals}, {@code hashCode} and
 * {@code toString} are always allowed.
 */
class CourseFaceTest {
    /** The course's intersection queries and hooks of the three years (COURSE-YEARS.md §1, §4). */
    private static final List<String> INTERSECTABLE = List.of(
            // 2023–24: the queries, and the hook a shape overrides (also its one-argument form)
            "findIntersections(Ray)", "findIntersections(Ray, double)", "findGeoIntersections(Ray)",
            "findGeoIntersections(Ray, double)", "findGeoIntersectionsHelper(Ray)", "findGeoIntersectionsHelper(Ray, double)",
            // 2024–25
            "calculateIntersections(Ray)", "calculateIntersections(Ray, double)",
            "calculateIntersectionsHelper(Ray)", "calculateIntersectionsHelper(Ray, double)",
            // 2025–26
            "calcIntersections(Ray)", "calcIntersections(Ray, double)",
            "calcIntersectionsHelper(Ray)", "calcIntersectionsHelper(Ray, double)");

    /** {@code Geometry}'s course methods (API.md "geometries"), over {@link #INTERSECTABLE}. */
    private static final List<String> GEOMETRY = concat(INTERSECTABLE,
            "getEmission()", "setEmission(Color)", "getMaterial()", "setMaterial(Material)", "getNormal(Point)");

    /** The course's light queries (API.md "lighting"), and the soft-shadow improvement's disk. */
    private static final List<String> LIGHT_SOURCE = List.of("getIntensity(Point)", "getL(Point)", "getDistance(Point)",
            // soft shadows: the disk a user's own light may give (radius 0: a point)
            "getRadius()", "getPosition()");

    /** A point light's attenuation setters, every cohort's spelling (COURSE-YEARS.md §1, §4). */
    private static final List<String> ATTENUATION = List.of("setKc(double)", "setKl(double)", "setKq(double)",
            "setKC(double)", "setKL(double)", "setKQ(double)", "setkC(double)", "setkL(double)", "setkQ(double)");

    /** The tracer's course method and the improvements a tracer carries (README: glossy, soft shadows, BVH switch). */
    private static final List<String> TRACER = List.of("traceRay(Ray)", "setBeamSize(int)", "getBeamSize()",
            "setShadowSamples(int)", "getShadowSamples()", "setBvh(boolean)", "isBvh()");

    /** Each course class and the methods it shows: the course API, its improvements, documented getters. */
    private static final Map<Class<?>, List<String>> FACE = new LinkedHashMap<>();

    static {
        List<String> pointOps = List.of("add(Vector)", "subtract(Point)", "distance(Point)", "distanceSquared(Point)",
                "getX()", "getY()", "getZ()",
                // the record-style spelling some 2025–26 projects use
                "x()", "y()", "z()");
        FACE.put(Point.class, pointOps);
        FACE.put(Vector.class, concat(pointOps, "add(Vector)", "subtract(Vector)", "scale(double)", "dotProduct(Vector)",
                "crossProduct(Vector)", "lengthSquared()", "length()", "normalize()",
                // the library's own: −v, documented on Vector
                "negate()"));
        FACE.put(Ray.class, List.of("getHead()", "getDirection()", "getPoint(double)", "findClosestPoint(List)",
                "findClosestGeoPoint(List)",
                // 2024–25 and 2025–26
                "findClosestIntersection(List)", "origin()", "direction()"));
        FACE.put(Color.class, List.of("add(Color[])", "add(Color)", "scale(double)", "scale(Double3)", "reduce(int)",
                "reduce(double)", "getColor()",
                // the library's own getters and packing, documented on Color; adaptive AA's measure
                "getR()", "getG()", "getB()", "toRgb()", "distance(Color)"));
        FACE.put(Double3.class, List.of("add(Double3)", "subtract(Double3)", "scale(double)", "reduce(double)",
                "product(Double3)", "lowerThan(double)", "lowerThan(Double3)",
                // the three years' accessor spellings (COURSE-YEARS.md §3.8), and the zero test
                "getD1()", "getD2()", "getD3()", "d1()", "d2()", "d3()", "_d1()", "_d2()", "_d3()", "isZero()"));
        List<String> material = new ArrayList<>();
        for (String k : List.of("Kd", "Ks", "Kt", "Kr", "Ka", "KD", "KS", "KT", "KR", "KA", "kD", "kS", "kT", "kR", "kA"))
            material.addAll(List.of("set" + k + "(double)", "set" + k + "(Double3)"));
        material.addAll(List.of("setShininess(int)", "setNShininess(int)", "setnShininess(int)",
                // glossy reflection and diffuse glass (README), and the index of refraction
                "setReflectionSpread(double)", "setTransmissionSpread(double)", "setIor(double)"));
        FACE.put(Material.class, material);
        FACE.put(Util.class, List.of("isZero(double)", "alignZero(double)", "compareSign(double, double)",
                "random(double, double)"));

        FACE.put(Intersectable.class, INTERSECTABLE);
        FACE.put(Intersectable.GeoPoint.class, List.of());
        FACE.put(Intersectable.Intersection.class, List.of());
        FACE.put(Geometry.class, GEOMETRY);
        FACE.put(Geometries.class, concat(INTERSECTABLE, "add(Intersectable[])",
                // the course's BVH switches (no-ops: the render's BVH is always on) and the list's own view
                "buildBVH()", "makeBVH()", "enableBVH()", "getItems()", "isEmpty()"));
        FACE.put(Sphere.class, concat(GEOMETRY, "getCenter()", "getRadius()"));
        FACE.put(Plane.class, concat(GEOMETRY, "getQ()", "getNormal()"));
        FACE.put(Polygon.class, GEOMETRY);
        FACE.put(Triangle.class, GEOMETRY);
        FACE.put(Tube.class, concat(GEOMETRY, "getAxis()", "getRadius()"));
        FACE.put(Cylinder.class, concat(GEOMETRY, "getAxis()", "getRadius()", "getHeight()"));
        FACE.put(TriangleMesh.class, concat(GEOMETRY, "triangleCount()", "vertexCount()", "hasVertexNormals()",
                "getVertex(int)", "getVertexNormal(int)", "getTriangleIndices(int)"));

        FACE.put(LightSource.class, LIGHT_SOURCE);
        FACE.put(AmbientLight.class, List.of("getIntensity()"));
        FACE.put(DirectionalLight.class, concat(LIGHT_SOURCE, "getIntensity()"));
        FACE.put(PointLight.class, concat(concat(LIGHT_SOURCE, ATTENUATION), "getIntensity()",
                // a subclass's hook (protected), and the soft-shadow radius (README)
                "attenuation(Point)", "setRadius(double)"));
        FACE.put(SpotLight.class, concat(FACE.get(PointLight.class), "setNarrowBeam(double)"));

        FACE.put(Scene.class, List.of("setBackground(Color)", "setAmbientLight(AmbientLight)", "setGeometries(Geometries)",
                "setLights(List)", "buildBVH()", "makeBVH()", "enableBVH()"));

        FACE.put(Camera.class, List.of("getBuilder()", "constructRay(int, int, int, int)", "renderImage()",
                "printGrid(int, Color)", "writeToImage()",
                // 2024–25, 2025–26; starting a builder from a camera (§4)
                "writeToImage(String)", "constructRay(int, int)", "getBuilder(Camera)",
                // the library's own, documented on Camera: render() returns what the render did
                "render()", "getLocation()", "getVTo()", "getVUp()", "getVRight()", "getImageWriter()", "maxThreads()"));
        FACE.put(Camera.Builder.class, List.of("setLocation(Point)", "setDirection(Vector, Vector)",
                "setDirection(Point, Vector)", "setDirection(Point)", "setVpSize(double, double)", "setVpDistance(double)",
                "setImageWriter(ImageWriter)", "setRayTracer(RayTracerBase)", "build()",
                // 2024–25, 2025–26 (COURSE-YEARS.md §1), camera roll and the course's BVH/CBR switches
                "setResolution(int, int)", "setRayTracer(Scene, RayTracerType)", "rotate(int)", "enableBVH()",
                "enableCBR()", "setViewPlaneSize(double, double)", "setViewPlaneDistance(double)",
                // the improvements, one line each (API.md): anti-aliasing, depth of field, threads and progress
                "setAntiAliasing(AntiAliasing)", "setAntiAliasing(AntiAliasing, int, int)", "setAntiAliasingGrid(int, int)",
                "setAdaptive(int, double)", "setDepthOfField(double, double)", "setPinhole()", "setDepthOfFieldSamples(int)",
                "setDofRays(int)", "setMultithreading(int)", "setDebugPrint(double)",
                // the render's output: its seed, summary line, where lines go, and a listener (the JUnit reports)
                "setSeed(long)", "setSummary(boolean)", "setOutput(PrintStream)", "setRenderListener(BiConsumer)"));
        FACE.put(ImageWriter.class, List.of("getNx()", "getNy()", "writePixel(int, int, Color)", "writeToImage()",
                // 2024–25, 2025–26
                "writeToImage(String)", "nX()", "nY()",
                // the library's own, documented: the name, the file, a pixel read back, a write to a path
                "getImageName()", "getPath()", "getRgb(int, int)", "writeToImage(Path)"));
        FACE.put(RayTracerBase.class, List.of("traceRay(Ray)"));
        FACE.put(RayTracerBasic.class, TRACER);
        FACE.put(SimpleRayTracer.class, TRACER);
        FACE.put(RayTracerType.class, List.of("values()", "valueOf(String)"));
        FACE.put(AntiAliasing.class, List.of("values()", "valueOf(String)"));
    }

    /**
     * Names of engine members that once showed on course classes: none may come back under any
     * list (a second line of defence, independent of {@link #FACE}).
     */
    private static final Set<String> ENGINE_NAMES = Set.of("closestHit", "visitHits", "getBoundingBox", "isLibraryShape",
            "isLibraryPrimitive", "isLibraryLight", "settingsStamp", "validate", "describe", "isDegenerate", "headOffset",
            "getImageLabel", "getSceneName", "memoryNeeded", "bytesNeeded", "requireFileName", "hiddenCharacter",
            "writeTile", "requireFinite", "requirePositive", "requireNonNegative");

    /** The engine's types: a course method never takes one. */
    private static final Set<Class<?>> ENGINE_TYPES = Set.of(Hit.class, HitVisitor.class, BoundingBox.class, Rgb.class,
            double[].class);

    private static List<String> concat(List<String> base, String... more) {
        return Stream.concat(base.stream(), Arrays.stream(more)).toList();
    }

    private static List<String> concat(List<String> a, List<String> b) {
        return Stream.concat(a.stream(), b.stream()).toList();
    }

    /** {@code name(Simple, Types)}: a method as code completion lists it. */
    private static String signature(Method m) {
        return m.getName() + Arrays.stream(m.getParameterTypes()).map(Class::getSimpleName)
                .collect(Collectors.joining(", ", "(", ")"));
    }

    /**
     * The methods a student sees on {@code c}: its public methods, inherited ones included (the
     * bridges the compiler writes for a package-private superclass's public methods too), and,
     * for a class they may extend, the protected methods of it and its superclasses.
     */
    private static List<Method> visible(Class<?> c) {
        List<Method> methods = new ArrayList<>();
        for (Method m : c.getMethods())
            if (m.getDeclaringClass() != Object.class && m.getDeclaringClass() != Enum.class) methods.add(m);
        if (!Modifier.isFinal(c.getModifiers()) && !c.isInterface())
            for (Class<?> k = c; k != null && k != Object.class && k != Enum.class; k = k.getSuperclass())
                for (Method m : k.getDeclaredMethods())
                    if (Modifier.isProtected(m.getModifiers())) methods.add(m);
        return methods;
    }

    private static Set<String> signatures(Class<?> c) {
        Set<String> s = new TreeSet<>();
        for (Method m : visible(c)) s.add(signature(m));
        s.removeAll(Set.of("equals(Object)", "hashCode()", "toString()"));
        return s;
    }

    static Stream<Arguments> courseClasses() {
        return FACE.entrySet().stream().map(e -> Arguments.of(e.getKey().getName(), e.getKey(), e.getValue()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("courseClasses")
    @DisplayName("a course class shows exactly the course's methods and the documented improvements")
    void showsTheCourseFace(String name, Class<?> c, List<String> allowed) {
        Set<String> shown = signatures(c);
        Set<String> extra = new TreeSet<>(shown);
        extra.removeAll(allowed);
        assertThat(extra).as("%s shows methods that are not course API: move them behind a package-private method and"
                + " an internal facade, or list them here if the course defines them", name).isEmpty();
        Set<String> missing = new TreeSet<>(allowed);
        missing.removeAll(shown);
        assertThat(missing).as("%s lacks methods its list names (the list drifted from the class)", name).isEmpty();
    }

    /** The members of {@code c} a student would see that are the engine's: a known engine name, or an engine type. */
    private static List<String> engineMembers(Class<?> c) {
        List<String> engine = new ArrayList<>();
        for (Method m : visible(c)) {
            boolean engineType = Arrays.stream(m.getParameterTypes()).anyMatch(ENGINE_TYPES::contains)
                    || ENGINE_TYPES.contains(m.getReturnType());
            if (ENGINE_NAMES.contains(m.getName()) || engineType)
                engine.add(m.getDeclaringClass().getSimpleName() + "." + signature(m));
        }
        return engine;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("courseClasses")
    @DisplayName("no course class shows an engine member: a known engine name, or one taking an engine type or an out-array")
    void showsNoEngineMember(String name, Class<?> c, List<String> allowed) {
        assertThat(engineMembers(c)).as(name).isEmpty();
    }

    @Test
    @DisplayName("the checks see inherited, bridged and protected methods, and name the engine's")
    void theChecksSee() {
        // Inherited through Geometry and Intersectable, and protected: a hook a student overrides.
        assertThat(signatures(Sphere.class)).contains("getEmission()", "findGeoIntersectionsHelper(Ray, double)");
        // A public method of the package-private superclass of the lights, seen through its bridge.
        assertThat(signatures(AmbientLight.class)).contains("getIntensity()");
        // The engine's facades show what the course classes no longer do, and the check names it.
        assertThat(engineMembers(geometries.LeanQueries.class)).contains("LeanQueries.closestHit(Intersectable, Hit)",
                "LeanQueries.isLibraryShape(Geometry)");
        assertThat(engineMembers(lighting.LightQueries.class)).contains(
                "LightQueries.getL(LightSource, double, double, double, double[])", "LightQueries.settingsStamp(LightSource)");
    }
}
