"""The jars `mvn package` attaches for a library user: the sources jar holds every source file of
the library, the vector walk's included (it is compiled from src/main/vector by an execution of its
own, outside the Maven source roots the sources jar reads), and the Javadoc jar has the course's
pages, not the engine's (public only for other packages of the library, marked @hidden), and each
course page lists the course's members only, inherited ones included: no lean query, bounding box,
library-class rule, doubles form or other engine member. The runnable jar's picocli is compiled for
Java 17 when a JDK 25 or later built it (pom.xml, profile jdk25-picocli), and is picocli's own jar
(Java 5) otherwise. Needs `mvn package`; skipped without the jars."""
from __future__ import annotations

import re
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
TARGET = ROOT / "target"


def attached(classifier: str) -> Path | None:
    found = sorted(TARGET.glob(f"raytracer-*-{classifier}.jar"))
    return found[-1] if found else None


SOURCES, JAVADOC = attached("sources"), attached("javadoc")
RUNNABLE = TARGET / "raytracer.jar"


@pytest.mark.skipif(not RUNNABLE.exists(), reason="no runnable jar: run mvn package first")
def test_the_runnable_jars_picocli_is_compiled_for_java_17_where_a_jdk_25_built_it():
    """JDK 25's start-up cache cannot hold Java 5 class files; the same classes for Java 17 it can."""
    with zipfile.ZipFile(RUNNABLE) as jar:
        build = int(re.search(r"Build-Jdk-Spec: (\d+)", jar.read("META-INF/MANIFEST.MF").decode()).group(1))
        classes = {n: jar.read(n) for n in jar.namelist() if n.startswith("picocli/") and n.endswith(".class")}
    majors = {int.from_bytes(data[6:8], "big") for data in classes.values()}
    assert majors == ({61} if build >= 25 else {49}), (build, majors)
    assert {"picocli/CommandLine.class", "picocli/CommandLine$Model$CommandSpec.class",
            "picocli/CommandLine$Help.class"} <= classes.keys()
    assert len(classes) > 200  # all of picocli, not a part


@pytest.mark.skipif(SOURCES is None, reason="no sources jar: run mvn package first")
def test_the_sources_jar_holds_every_library_source_file():
    roots = [ROOT / "src" / "main" / "java", ROOT / "src" / "main" / "vector"]
    expected = {str(f.relative_to(root)).replace("\\", "/") for root in roots for f in root.rglob("*.java")}
    with zipfile.ZipFile(SOURCES) as jar:
        listed = {n for n in jar.namelist() if n.endswith(".java")}
    assert "geometries/VectorWalk.java" in expected
    assert expected - listed == set()


@pytest.mark.skipif(JAVADOC is None, reason="no Javadoc jar: run mvn package first")
def test_the_javadoc_jar_is_the_course_face():
    """The student's pages: the course's types, not the engine's public-but-@hidden ones."""
    with zipfile.ZipFile(JAVADOC) as jar:
        names = set(jar.namelist())
    for course in ("geometries/Sphere.html", "geometries/Intersectable.html", "renderer/Camera.html",
                   "scene/Scene.html", "primitives/Point.html"):
        assert course in names
    for engine in ("geometries/Bvh.html", "geometries/Hit.html", "primitives/Rgb.html", "renderer/Sampling.html",
                   "scene/io/Messages.html", "geometries/VectorWalk.html",
                   "geometries/GeometryLists.html", "geometries/LeanQueries.html", "geometries/MeshChecks.html",
                   "lighting/LightQueries.html", "lighting/DoublesLight.html", "primitives/Kernels.html",
                   "primitives/Checks.html", "renderer/CameraReports.html", "renderer/ImageWriters.html"):
        assert engine not in names


# Each course class's page, and a member of the course's it must list (so that a page the member
# pattern below cannot read fails, rather than passing with nothing found).
COURSE_PAGES = {
    "primitives/Point.html": "distanceSquared", "primitives/Vector.html": "crossProduct",
    "primitives/Ray.html": "findClosestGeoPoint", "primitives/Color.html": "reduce",
    "primitives/Double3.html": "lowerThan", "primitives/Material.html": "setShininess",
    "primitives/Util.html": "alignZero",
    "geometries/Intersectable.html": "findGeoIntersectionsHelper",
    "geometries/Intersectable.GeoPoint.html": "equals", "geometries/Intersectable.Intersection.html": "equals",
    "geometries/Geometry.html": "getNormal", "geometries/Geometries.html": "add",
    "geometries/Sphere.html": "findGeoIntersections", "geometries/Plane.html": "findGeoIntersections",
    "geometries/Polygon.html": "findGeoIntersections", "geometries/Triangle.html": "findGeoIntersections",
    "geometries/Tube.html": "findGeoIntersections", "geometries/Cylinder.html": "findGeoIntersections",
    "geometries/TriangleMesh.html": "findGeoIntersections",
    "lighting/LightSource.html": "getL", "lighting/AmbientLight.html": "getIntensity",
    "lighting/DirectionalLight.html": "getL", "lighting/PointLight.html": "setKl",
    "lighting/SpotLight.html": "setNarrowBeam",
    "scene/Scene.html": "setBackground",
    "renderer/Camera.html": "constructRay", "renderer/Camera.Builder.html": "setVpSize",
    "renderer/ImageWriter.html": "writePixel", "renderer/RayTracerBase.html": "traceRay",
    "renderer/RayTracerBasic.html": "traceRay", "renderer/SimpleRayTracer.html": "traceRay",
}

# Names of the engine's members that once showed on course pages (declared or inherited).
ENGINE_NAMES = {"closestHit", "visitHits", "getBoundingBox", "isLibraryShape", "isLibraryPrimitive", "isLibraryLight",
                "settingsStamp", "validate", "describe", "isDegenerate", "headOffset", "getImageLabel", "getSceneName",
                "memoryNeeded", "bytesNeeded", "requireFileName", "hiddenCharacter", "writeTile", "requireFinite",
                "requirePositive", "requireNonNegative"}
# Parameter types that only the engine's members take: its records, and an out-array of doubles
# (the doubles forms: a light's getL(x, y, z, out), Vector's normalize(x, y, z, out)).
ENGINE_PARAMETER = re.compile(r"geometries\.Hit\b|geometries\.HitVisitor|geometries\.BoundingBox|primitives\.Rgb"
                              r"|double(?:%5B%5D|\[\])")
# A member's anchor on a Javadoc page: id="name(types)" where it is declared, #name(types) in the
# lists of inherited methods; constructors are %3Cinit%3E(...).
MEMBER = re.compile(r'(?:id="|#)([A-Za-z_$][\w$]*)\(([^")]*)\)')


def members(page: str) -> set[tuple[str, str]]:
    return set(MEMBER.findall(page))


@pytest.mark.skipif(JAVADOC is None, reason="no Javadoc jar: run mvn package first")
@pytest.mark.parametrize("page", sorted(COURSE_PAGES))
def test_a_course_page_lists_no_engine_member(page: str):
    with zipfile.ZipFile(JAVADOC) as jar:
        text = jar.read(page).decode("utf-8")
    listed = members(text)
    assert COURSE_PAGES[page] in {name for name, _ in listed}, f"{page}: the course member is not found"
    engine = sorted(f"{name}({types})" for name, types in listed
                    if name in ENGINE_NAMES or ENGINE_PARAMETER.search(types))
    assert engine == [], f"{page} lists engine members"


def test_the_member_check_names_engine_members():
    """The pattern sees a declared member and an inherited one, with their types: it can fail."""
    page = ('<section class="detail" id="closestHit(geometries.Hit)">'
            '<a href="Intersectable.html#getL(double,double,double,double%5B%5D)">getL</a>'
            '<a href="#%3Cinit%3E(double%5B%5D,int%5B%5D)">TriangleMesh</a>')
    listed = members(page)
    assert ("closestHit", "geometries.Hit") in listed
    assert any(ENGINE_PARAMETER.search(types) for name, types in listed if name == "getL")
    assert not any(name.startswith("%3C") for name, _ in listed)
