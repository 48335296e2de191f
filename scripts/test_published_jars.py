"""The jars `mvn package` attaches for a library user: the sources jar holds every source file of
the library, the vector walk's included (it is compiled from src/main/vector by an execution of its
own, outside the Maven source roots the sources jar reads), and the Javadoc jar has the course's
pages, not the engine's (public only for other packages of the library, marked @hidden). Needs `mvn package`; skipped without the jars."""
from __future__ import annotations

import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
TARGET = ROOT / "target"


def attached(classifier: str) -> Path | None:
    found = sorted(TARGET.glob(f"raytracer-*-{classifier}.jar"))
    return found[-1] if found else None


SOURCES, JAVADOC = attached("sources"), attached("javadoc")


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
                   "geometries/GeometryLists.html"):
        assert engine not in names
