"""The launcher script `raytracer` at the project root: what it does without a jar, how it makes its
start-up archive (once per JDK and jar) and what it does with a broken one, with the user's
options, and which archive it takes on which JDK. Needs the runnable jar (`mvn package`) except for
the fake-JDK cases; those are skipped without it."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
JAR = ROOT / "target" / "raytracer.jar"


INLINING = Path("scripts") / "quick-tier.compilecommands"


def project(tmp_path: Path, with_jar: bool) -> Path:
    """A folder holding a copy of the launcher and its quick tier's inlining list and, if asked, a
    link to the built jar."""
    shutil.copy2(ROOT / "raytracer", tmp_path / "raytracer")
    (tmp_path / "scripts").mkdir()
    shutil.copy2(ROOT / INLINING, tmp_path / INLINING)
    if with_jar:
        (tmp_path / "target").mkdir()
        os.symlink(JAR, tmp_path / "target" / "raytracer.jar")
    return tmp_path


def startup(folder: Path, home: Path, suffix: str) -> Path:
    """Where the launcher keeps its start-up archive for the JDK at `home`: named by the checksum of
    the JDK's release file and that of the jar's path, as POSIX cksum computes them, and "-vector"
    when the launcher adds the vector module by default (an archive fits only its modules): to a
    render with both tiers, whose archive is a class-data archive (jsa) on every JDK, where the JDK
    has the module. The quick tier's has no module: an ahead-of-time cache (aot) on JDK 25 and
    later, else a jsa."""
    key = subprocess.run(["cksum"], stdin=(home / "release").open("rb"), capture_output=True, text=True,
                         check=True).stdout.split()[0]
    jar = str(folder / "target" / "raytracer.jar")  # the path the launcher names it by: its folder's, links kept
    key += "-" + subprocess.run(["cksum"], input=jar, capture_output=True, text=True, check=True).stdout.split()[0]
    if "jdk.incubator.vector" in (home / "release").read_text() and suffix == "jsa":
        key += "-vector"
    return folder / "target" / "startup" / f"raytracer-{key}.{suffix}"


def this_jdk() -> Path:
    """The JDK the launcher runs here (JAVA_HOME or java on the PATH). A command with both tiers
    (--version, a large render) takes a class-data archive (jsa) on it, whatever its version."""
    java = Path(os.environ["JAVA_HOME"]) / "bin" / "java" if os.environ.get("JAVA_HOME") else Path(shutil.which("java"))
    return java.resolve().parent.parent


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
def test_the_first_run_makes_the_start_up_archive_and_the_next_runs_use_it(tmp_path):
    folder = project(tmp_path, with_jar=True)
    archive = startup(folder, this_jdk(), "jsa")
    first = run(folder, "--version")
    assert first.returncode == 0, first.stderr
    assert first.stderr == f"raytracer: making the start-up archive for this JDK and jar (once, a few seconds): {archive}\n"
    assert archive.stat().st_size > 0
    assert [p.name for p in archive.parent.iterdir()] == [archive.name]  # no scratch folder left
    second = run(folder, "--version", env={"RAYTRACER_JAVA_OPTS": "-XX:+PrintCommandLineFlags"})
    assert second.returncode == 0 and second.stderr == ""
    # a jar newer than the archive (a rebuild): made again
    jar_time = (folder / "target" / "raytracer.jar").stat().st_mtime
    os.utime(archive, (jar_time - 10, jar_time - 10))
    third = run(folder, "--version")
    assert third.returncode == 0 and "making the start-up archive" in third.stderr


@needs_jar
@pytest.mark.parametrize("what", ["--version", "a short render"])
def test_a_project_copied_to_another_folder_makes_an_archive_of_its_own(tmp_path, what):
    # The JVM refuses an archive made for the jar at another path, silently: every launch of the
    # copy would start as slowly as without one. Worse, JDK 25 took the copied cache of a short
    # render (the quick tier's) while the original folder still held the same jar: the library's
    # classes then came from two places, and CourseClassGuard refused to render.
    args = ["--version"] if what == "--version" else [
        str(ROOT / "scenes" / "two-colors.xml"), "--width=40", f"--output={tmp_path / 'x.png'}", "--quiet"]
    (tmp_path / "before").mkdir()
    first = project(tmp_path / "before", with_jar=True)
    made = run(first, *args)
    assert made.returncode == 0 and "making the start-up archive" in made.stderr, made.stderr
    copy = tmp_path / "after"
    shutil.copytree(first, copy, symlinks=True)  # the jar's and the archive's times kept, as mv keeps them
    again = run(copy, *args)
    assert again.returncode == 0, again.stderr
    assert again.stderr.startswith("raytracer: making the start-up archive for this JDK and jar (once, a few"
                                   f" seconds): {copy / 'target' / 'startup'}/raytracer-"), again.stderr
    assert run(copy, *args).stderr == ""


@needs_jar
def test_an_archive_that_does_not_fit_is_ignored_without_a_word(tmp_path):
    folder = project(tmp_path, with_jar=True)
    archive = startup(folder, this_jdk(), "jsa")
    archive.parent.mkdir(parents=True)
    archive.write_bytes(b"not an archive")
    done = run(folder, "--version")
    assert done.returncode == 0
    assert done.stderr == ""


@needs_jar
def test_the_users_options_come_after_the_launchers(tmp_path):
    # -XX:+PrintCommandLineFlags lists the options the JVM runs with; the user's TieredStopAtLevel=1
    # must be in force over the launcher's default (both compilers).
    done = run(project(tmp_path, with_jar=True), "--version",
               env={"RAYTRACER_JAVA_OPTS": "-XX:+PrintCommandLineFlags -XX:TieredStopAtLevel=1"})
    assert done.returncode == 0, done.stderr
    assert "-XX:TieredStopAtLevel=1" in done.stdout


@needs_jar
@pytest.mark.parametrize("vector, tier", [("", "4"), ("1", "4"), ("0", "4"), ("", ""), ("1", ""), ("", "1")])
def test_a_render_prints_no_incubator_warning_and_says_its_walk(tmp_path, vector, tier):
    # A small render gets the quick tier alone (tier ""), and with it no module; the user's
    # TieredStopAtLevel (4, both tiers, or 1, the quick tier) leaves the module to RAYTRACER_VECTOR
    # and the JDK, and the line then names both reasons the walk is not compiled.
    folder = project(tmp_path, with_jar=True)
    done = run(folder, str(ROOT / "scenes" / "two-colors.xml"), "--width=40", f"--output={tmp_path / 'x.png'}",
               env={"RAYTRACER_VECTOR": vector, "RAYTRACER_JAVA_OPTS": f"-XX:TieredStopAtLevel={tier}" if tier else ""})
    assert done.returncode == 0, done.stderr
    assert "incubator" not in done.stderr
    module = tier and vector != "0"  # by default, with both tiers
    if module:  # where the JDK has it: a short render keeps the scalar walk
        assert "scalar walk (the vector walk is not compiled: a short render or a JVM without the optimizing compiler)" in done.stdout
    else:
        assert "scalar walk (no jdk.incubator.vector)" in done.stdout


def fake_project(tmp_path: Path) -> Path:
    """A project folder in tmp_path/project: the launcher and an empty jar, for a fake JDK's java."""
    (tmp_path / "project").mkdir()
    folder = project(tmp_path / "project", with_jar=False)
    (folder / "target").mkdir()
    (folder / "target" / "raytracer.jar").write_bytes(b"")
    return folder


def fake_jdk(tmp_path: Path, version: str, modules: str = "java.base") -> Path:
    """A JAVA_HOME whose release file names `version` and `modules`, and whose java prints its
    arguments, one a line, after the JVM's incubator warning on standard error."""
    home = tmp_path / f"jdk-{version}"
    (home / "bin").mkdir(parents=True)
    (home / "release").write_text(f'IMPLEMENTOR="test"\nJAVA_VERSION="{version}"\nMODULES="{modules}"\n')
    java = home / "bin" / "java"
    java.write_text('#!/bin/sh\n'
                    'case " $* " in *" jdk.incubator.vector "*) echo "WARNING: Using incubator modules: jdk.incubator.vector" >&2;; esac\n'
                    'echo "the JVM\'s own line" >&2\n'
                    'for a in "$@"; do echo "$a"; done\n'
                    'exit 3\n')
    java.chmod(0o755)
    return home


@pytest.mark.parametrize("version, asked, modules, vector", [
    ("17.0.12", "", "java.base jdk.incubator.vector java.desktop", True),
    ("17.0.12", "", "java.base jdk.incubator.vector", True),
    ("21.0.5", "1", "java.base jdk.incubator.vector", True),
    ("17.0.12", "", "java.base java.desktop", False),
    ("17.0.12", "0", "java.base jdk.incubator.vector", False),
    ("25.0.1", "", "java.base jdk.incubator.vector", True),  # with a class-data archive, not the AOT cache
    ("25.0.1", "0", "java.base jdk.incubator.vector", False),
    ("25.0.1", "1", "java.base jdk.incubator.vector", True)])
def test_the_vector_module_is_added_by_default_where_the_jdk_has_it_and_its_warning_dropped(
        tmp_path, version, asked, modules, vector):
    # "scene.xml" does not exist: the launcher cannot estimate it and keeps both tiers.
    folder = fake_project(tmp_path)
    home = fake_jdk(tmp_path, version, modules)
    suffix = "jsa"
    archive = startup(folder, home, suffix)
    archive = archive.with_name(archive.name.replace("-vector", "").replace(f".{suffix}", ("-vector" if vector else "") + f".{suffix}"))
    archive.parent.mkdir()
    archive.write_bytes(b"")  # as after a start-up archive that could not be made
    done = run(folder, "scene.xml", env={"JAVA_HOME": str(home), "RAYTRACER_VECTOR": asked})
    assert done.returncode == 3  # the JVM's own exit status
    assert ("jdk.incubator.vector" in done.stdout.splitlines()) == vector
    assert done.stderr == "the JVM's own line\n"  # the warning, and only it, dropped


@pytest.mark.parametrize("version, quick, uses_cache", [
    ("25.0.1", True, True), ("26", True, True), ("24", True, False), ("21.0.5", True, False), ("17.0.12", True, False),
    ("25.0.1", False, False), ("26", False, False), ("17.0.12", False, False)])
def test_the_ahead_of_time_cache_is_used_for_the_quick_tier_on_jdk_25_and_later_only(tmp_path, version, quick,
                                                                                     uses_cache):
    # JDK 17 refuses -XX:AOTCache as an unknown option, so the launcher reads the JDK's release
    # file; the one-step cache (-XX:AOTCacheOutput) the launcher makes came with JDK 25. With both
    # tiers and the vector module, JDK 25's cache held no module graph and took longer than the
    # class-data archive: there the launcher takes the archive on every JDK.
    folder = fake_project(tmp_path)
    home = fake_jdk(tmp_path, version)  # no vector module: the archive's name has no "-vector"
    archive = startup(folder, home, "aot" if uses_cache else "jsa")
    archive.parent.mkdir()
    archive.write_bytes(b"made")
    scene = str(scene_file(tmp_path, IMAGE)) if quick else "scene.xml"
    done = run(folder, scene, env={"JAVA_HOME": str(home), "RAYTRACER_JAVA_OPTS": "-Dmine=1"})
    assert done.returncode == 3, done.stderr
    assert done.stderr == "the JVM's own line\n"  # nothing made: the archive is there, newer than the jar
    args = done.stdout.splitlines()
    assert args[-3:] == ["-jar", str(folder / "target" / "raytracer.jar"), scene]
    assert args[-4] == "-Dmine=1"  # the user's options last before the jar
    if uses_cache:
        assert f"-XX:AOTCache={archive}" in args
        assert not any(a.startswith("-XX:SharedArchiveFile") for a in args)
    else:
        assert not any(a.startswith("-XX:AOTCache") for a in args)
        assert f"-XX:SharedArchiveFile={archive}" in args
    assert "-XX:+UseSerialGC" in args
    assert ("-XX:TieredStopAtLevel=1" in args) == quick


def test_an_archive_that_cannot_be_made_is_said_once_and_not_tried_again(tmp_path):
    # The fake JVM fails the training render: one line, an empty file in its place, and the next
    # run neither tries again nor passes the empty file to the JVM.
    folder = fake_project(tmp_path)
    home = fake_jdk(tmp_path, "17.0.12")
    first = run(folder, "scene.xml", env={"JAVA_HOME": str(home)})
    lines = first.stderr.splitlines()
    assert lines[0].startswith("raytracer: making the start-up archive")
    assert lines[1] == "raytracer: no start-up archive (-XX:+UseSerialGC); running without it" or \
        lines[1].startswith("raytracer: no start-up archive (")
    assert startup(folder, home, "jsa").read_bytes() == b""
    second = run(folder, "scene.xml", env={"JAVA_HOME": str(home)})
    assert second.stderr == "the JVM's own line\n"
    assert not any(a.startswith("-XX:SharedArchiveFile") for a in second.stdout.splitlines())


def scene_file(folder: Path, body: str, name: str = "scene.xml") -> Path:
    """A scene file holding `body` inside <scene>: only the tags the launcher's estimate reads."""
    path = folder / name
    path.write_text(f'<?xml version="1.0" encoding="UTF-8"?>\n<scene name="s">\n{body}\n</scene>\n')
    return path


CORES = len(os.sched_getaffinity(0))
IMAGE = '<image name="s" width="600" height="600"/>'


@pytest.mark.parametrize("body, args, quick", [
    # 600x600 at one sample a pixel: 3.6x10^5 rays, a short render
    (IMAGE, [], True),
    ("", [], True),  # the format's default image, 500x500
    (IMAGE + '<render><anti-aliasing mode="random" grid="4 4"/></render>', [], False),  # 5.8x10^6
    (IMAGE + '<render><anti-aliasing mode="random"/></render>', ["--width", "300"], True),  # 300x300x16
    (IMAGE + '<render><anti-aliasing mode="random"/></render>', ["--width=400", "--height=400"], False),
    (IMAGE, ["--aa=random"], False),  # the file's grid, the format's 4x4
    (IMAGE + '<render><anti-aliasing mode="adaptive" depth="3"/></render>', [], True),  # counted as 2 a pixel
    ('<image width="1200" height="1200"/><render><anti-aliasing mode="adaptive"/></render>', [], False),
    (IMAGE + '<render><anti-aliasing mode="corners"/></render>', [], True),  # 5 a pixel: 1.8x10^6
    ('<image width="700" height="700"/><render><anti-aliasing mode="corners"/></render>', [], False),
    (IMAGE + '<render><depth-of-field focal-distance="9" aperture="1"/></render>', [], False),  # 16 lens rays
    (IMAGE + '<render><depth-of-field focal-distance="9" aperture="0"/></render>', [], True),  # a pinhole
    # soft shadows: 16 shadow rays toward a light with a radius, for each hit
    (IMAGE + '<lights><point-light color="1 1 1" position="0 0 0" radius="0.5"/></lights>', [], False),
    (IMAGE + '<lights><point-light color="1 1 1" position="0 0 0" radius="0"/></lights>', [], True),
    (IMAGE + '<render bvh="false"/>', [], False),  # every ray against every shape
    # what the command line says wins over the file, and the file's comments are not read
    ('<!-- <image width="6000" height="6000"/> a > b -->' + IMAGE, [], True),
    ("<image\n   name='s'\n   width='3000'\n   height='3000'/>", [], False),  # quotes and lines as XML allows
    (IMAGE, ["--aa", "RANDOM", "-q", "--output=x.png", "--seed", "3"], False),
    (IMAGE, ["-ox.png", "-o", "y.png", "--mesh-root", "/tmp", "--threads", "-1"], True),
    # anything the launcher does not read: both tiers, as before it estimated
    (IMAGE, ["--help"], False),
    (IMAGE, ["--frames", "a.xml"], False),
    ('<image width="six" height="600"/>', [], False),
    (IMAGE + '<render><anti-aliasing mode="sideways"/></render>', [], False),
])
def test_a_short_render_that_keeps_every_core_busy_gets_the_quick_tier_alone(tmp_path, body, args, quick):
    # The fake JVM prints the options it was given: -XX:TieredStopAtLevel=1 is the quick tier alone.
    folder = fake_project(tmp_path)
    home = fake_jdk(tmp_path, "17.0.12")
    scene = scene_file(tmp_path, body)
    done = run(folder, str(scene), *args, env={"JAVA_HOME": str(home), "RAYTRACER_JAVA_OPTS": "-Dmine=1"})
    assert done.returncode == 3, done.stderr
    given = done.stdout.splitlines()
    assert ("-XX:TieredStopAtLevel=1" in given) == quick
    assert (f"-XX:CompileCommandFile={folder / INLINING}" in given) == quick  # its inlining, and only its
    assert given.index("-Dmine=1") == len(given) - 4 - len(args)  # the user's options still last, then -jar JAR SCENE


@pytest.mark.parametrize("threads, quick", [(None, True), (str(CORES), True), ("-1", True), ("-2", True),
                                            ("1", CORES == 1), ("0", CORES == 1)])
def test_a_spare_core_keeps_both_tiers(tmp_path, threads, quick):
    # With fewer render threads than cores, the optimizing compiler runs beside the render.
    folder = fake_project(tmp_path)
    home = fake_jdk(tmp_path, "17.0.12")
    in_file = scene_file(tmp_path, IMAGE + (f'<render threads="{threads}"/>' if threads else ""), "file.xml")
    on_line = scene_file(tmp_path, IMAGE, "line.xml")
    for scene, args in [(in_file, []), (on_line, [f"--threads={threads}"] if threads else [])]:
        done = run(folder, str(scene), *args, env={"JAVA_HOME": str(home)})
        assert ("-XX:TieredStopAtLevel=1" in done.stdout.splitlines()) == quick, (scene.name, args)


SPHERE = '<sphere center="0 0 0" radius="1"/>'
LONG = IMAGE + '<render><anti-aliasing mode="random" grid="4 4"/></render>'  # 5.8x10^6 rays: both tiers


@pytest.mark.parametrize("body, args, asked, vector", [
    # fewer than 512 shapes and no mesh: no tree the vector walk takes, so no module to resolve
    (LONG + "<geometries>" + SPHERE * 511 + "</geometries>", [], "", False),
    (LONG + "<geometries>" + SPHERE * 511 + "</geometries>", [], "1", True),  # unless asked for
    (LONG + "<geometries>" + SPHERE * 300 + '<plane point="0 0 0" normal="0 1 0"/>' * 100
     + '<polygon vertices="0 0 0, 1 0 0, 0 1 0"/>' * 112 + "</geometries>", [], "", True),  # 512 shapes
    (LONG + '<geometries><mesh file="m.obj"/></geometries>', [], "", True),  # a mesh may hold any number
    (LONG + '<geometries><mesh file="m.obj"/></geometries><render bvh="false"/>', [], "", False),  # no tree
    (LONG + "<!-- " + "<mesh file='m.obj'/>" + " -->", [], "", False),  # a comment is not a mesh
    (LONG, ["--help"], "", True),  # what the launcher does not read: the module, as before
    (IMAGE + '<geometries><mesh file="m.obj"/></geometries>', [], "", False),  # the quick tier alone
])
def test_the_vector_module_is_left_out_for_a_scene_too_small_for_the_vector_walk(tmp_path, body, args, asked,
                                                                                  vector):
    folder = fake_project(tmp_path)
    home = fake_jdk(tmp_path, "17.0.12", "java.base jdk.incubator.vector")
    scene = scene_file(tmp_path, body)
    done = run(folder, str(scene), *args, env={"JAVA_HOME": str(home), "RAYTRACER_VECTOR": asked})
    assert done.returncode == 3, done.stderr
    assert ("jdk.incubator.vector" in done.stdout.splitlines()) == vector


def test_without_a_scene_the_showcase_is_estimated_and_a_big_file_is_not_read(tmp_path):
    folder = fake_project(tmp_path)
    home = fake_jdk(tmp_path, "17.0.12")
    env = {"JAVA_HOME": str(home)}
    assert "-XX:TieredStopAtLevel=1" not in run(folder, env=env).stdout.splitlines()  # no scenes/ here
    os.symlink(ROOT / "scenes", folder / "scenes")
    assert "-XX:TieredStopAtLevel=1" in run(folder, env=env).stdout.splitlines()  # the built-in showcase
    assert "-XX:TieredStopAtLevel=1" not in run(folder, "--width=3000", env=env).stdout.splitlines()
    big = scene_file(tmp_path, IMAGE + "<!--" + "x" * (1 << 20) + "-->")
    assert "-XX:TieredStopAtLevel=1" not in run(folder, str(big), env=env).stdout.splitlines()


@needs_jar
def test_the_quick_tier_renders_the_same_image_and_yields_to_the_users_choice(tmp_path):
    folder = project(tmp_path, with_jar=True)
    scene, args = str(ROOT / "scenes" / "two-colors.xml"), ["--width=60", "--quiet"]
    quick = run(folder, scene, *args, f"--output={tmp_path / 'quick.png'}",
                env={"RAYTRACER_JAVA_OPTS": "-XX:+PrintCommandLineFlags"})
    both = run(folder, scene, *args, f"--output={tmp_path / 'both.png'}",
               env={"RAYTRACER_JAVA_OPTS": "-XX:+PrintCommandLineFlags -XX:TieredStopAtLevel=4"})
    assert quick.returncode == 0 and both.returncode == 0, quick.stderr + both.stderr
    flags = quick.stdout + both.stdout
    assert "-XX:TieredStopAtLevel=1 " in quick.stdout and "-XX:TieredStopAtLevel=4 " in both.stdout, flags
    assert "TieredStopAtLevel=1" not in both.stdout  # the user's tier, alone
    # the inlining list, taken without a word on standard output (its "quiet")
    assert f"-XX:CompileCommandFile={folder / INLINING} " in quick.stdout, quick.stdout
    assert "CompileCommand" not in both.stdout and len(quick.stdout.splitlines()) == 1, quick.stdout
    assert (tmp_path / "quick.png").read_bytes() == (tmp_path / "both.png").read_bytes()


def test_without_its_inlining_list_the_quick_tier_still_runs(tmp_path):
    folder = fake_project(tmp_path)
    (folder / INLINING).unlink()
    done = run(folder, str(scene_file(tmp_path, IMAGE)), env={"JAVA_HOME": str(fake_jdk(tmp_path, "17.0.12"))})
    given = done.stdout.splitlines()
    assert "-XX:TieredStopAtLevel=1" in given and not any("CompileCommand" in g for g in given), given


@needs_jar
def test_the_estimates_defaults_are_the_commands_own(tmp_path):
    # The launcher's estimate assumes the scene format's defaults where a tag or attribute is
    # missing (image size, grid, adaptive depth, shadow and lens samples). The command's summary
    # line for a scene without those tags states its own: they must be the same numbers.
    script = (ROOT / "raytracer").read_text()
    assumed = dict(re.findall(r"\b(w|h|gx|gy|depth|shadows|lenses) = (\d+)", script[script.index("BEGIN {"):]))
    scene = scene_file(tmp_path, '<geometries><sphere center="0 0 -50" radius="10"><material kd="0.5"/></sphere>'
                                 '</geometries><camera location="0 0 0" direction="0 0 -1" up="0 1 0" vp-size="50"'
                                 ' vp-distance="100"/><render><depth-of-field focal-distance="50" aperture="1"/>'
                                 '</render>')
    java = this_jdk() / "bin" / "java"
    lines = {}
    for mode in ["NONE", "RANDOM", "ADAPTIVE"]:
        done = subprocess.run([str(java), "-jar", str(JAR), str(scene), f"--aa={mode}",
                               f"--output={tmp_path / 'x.png'}"], capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        lines[mode] = next(line for line in done.stdout.splitlines() if line.startswith("render s:") and "[" in line)
    assert f" {assumed['w']}x{assumed['h']} [" in lines["NONE"]
    assert f"x{assumed['lenses']}, " in lines["NONE"]  # the lens samples without anti-aliasing
    assert f"shadow samples {assumed['shadows']}," in lines["NONE"]
    assert f"RANDOM {assumed['gx']}x{assumed['gy']}," in lines["RANDOM"]
    assert f"ADAPTIVE depth {assumed['depth']} " in lines["ADAPTIVE"]
