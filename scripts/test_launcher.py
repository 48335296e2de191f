"""The launcher script `raytracer` at the project root: what it does without a jar, with a stale or
broken class-data-sharing archive, with the user's options, and which archive it takes on which
JDK. Needs the runnable jar (`mvn package`) except for the last; those cases are skipped without it."""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
JAR = ROOT / "target" / "raytracer.jar"


def project(tmp_path: Path, with_jar: bool) -> Path:
    """A folder holding a copy of the launcher and, if asked, a link to the built jar."""
    shutil.copy2(ROOT / "raytracer", tmp_path / "raytracer")
    if with_jar:
        (tmp_path / "target").mkdir()
        os.symlink(JAR, tmp_path / "target" / "raytracer.jar")
    return tmp_path


def run(folder: Path, *args: str, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([str(folder / "raytracer"), *args], capture_output=True, text=True,
                          env={**os.environ, **(env or {})}, timeout=120)


def test_without_the_jar_it_says_how_to_build_it(tmp_path):
    done = run(project(tmp_path, with_jar=False), "--version")
    assert done.returncode == 2
    assert "target/raytracer.jar not found: build it first (mvn -q package -DskipTests)" in done.stderr


needs_jar = pytest.mark.skipif(not JAR.is_file(), reason="no target/raytracer.jar: run mvn package first")


@needs_jar
def test_it_runs_the_command_line_with_its_arguments(tmp_path):
    done = run(project(tmp_path, with_jar=True), "--version")
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("raytracer ")


@needs_jar
def test_an_archive_that_does_not_fit_is_ignored_without_a_word(tmp_path):
    folder = project(tmp_path, with_jar=True)
    (folder / "target" / "raytracer.jsa").write_bytes(b"not an archive")
    done = run(folder, "--version")
    assert done.returncode == 0
    assert done.stderr == ""


@needs_jar
def test_the_users_options_come_after_the_launchers(tmp_path):
    # -XX:+PrintCommandLineFlags lists the options the JVM runs with; the user's TieredStopAtLevel=4
    # must be the one in force, over the launcher's C1-only default.
    done = run(project(tmp_path, with_jar=True), "--version",
               env={"RAYTRACER_JAVA_OPTS": "-XX:+PrintCommandLineFlags -XX:TieredStopAtLevel=4"})
    assert done.returncode == 0, done.stderr
    assert "-XX:TieredStopAtLevel=4" in done.stdout
    assert "-XX:TieredStopAtLevel=1" not in done.stdout


def fake_jdk(tmp_path: Path, version: str) -> Path:
    """A JAVA_HOME whose release file names `version` and whose java prints its arguments, one a line."""
    home = tmp_path / f"jdk-{version}"
    (home / "bin").mkdir(parents=True)
    (home / "release").write_text(f'IMPLEMENTOR="test"\nJAVA_VERSION="{version}"\n')
    java = home / "bin" / "java"
    java.write_text('#!/bin/sh\nfor a in "$@"; do echo "$a"; done\n')
    java.chmod(0o755)
    return home


@pytest.mark.parametrize("version, uses_cache", [("25.0.1", True), ("24", True), ("21.0.5", False), ("17.0.12", False)])
def test_the_ahead_of_time_cache_is_used_on_jdk_24_and_later_only(tmp_path, version, uses_cache):
    # JDK 17 refuses -XX:AOTCache as an unknown option, so the launcher reads the JDK's release file.
    (tmp_path / "project").mkdir()
    folder = project(tmp_path / "project", with_jar=False)
    (folder / "target").mkdir()
    for name in ("raytracer.jar", "raytracer.jsa", "raytracer.aot"):
        (folder / "target" / name).write_bytes(b"")
    done = run(folder, "scene.xml", env={"JAVA_HOME": str(fake_jdk(tmp_path, version)), "RAYTRACER_JAVA_OPTS": "-Dmine=1"})
    assert done.returncode == 0, done.stderr
    args = done.stdout.splitlines()
    assert args[-3:] == ["-jar", str(folder / "target" / "raytracer.jar"), "scene.xml"]
    assert args[-4] == "-Dmine=1"  # the user's options last before the jar
    if uses_cache:
        assert f"-XX:AOTCache={folder / 'target' / 'raytracer.aot'}" in args
        assert not any(a.startswith("-XX:SharedArchiveFile") for a in args)
    else:
        assert not any(a.startswith("-XX:AOTCache") for a in args)
        assert f"-XX:SharedArchiveFile={folder / 'target' / 'raytracer.jsa'}" in args
    assert "-XX:TieredStopAtLevel=1" in args and "-XX:+UseSerialGC" in args
