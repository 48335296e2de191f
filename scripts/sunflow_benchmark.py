#!/usr/bin/env python3
"""Sunflow side by side: whole processes rendering the same scene, Sunflow 0.7.3 against this project.

The scene is the 137-primitive "final project" scene at 600x600 on 2 threads: Sunflow renders
scripts/sunflow/final-project.sc (written from the port, see its header), this project renders the
port, ../shared/data/sunflow-final-project.xml. Three cases:

  1spp      Sunflow -aa 0 0 (one sample per pixel)          ours --aa=NONE
  adaptive  Sunflow -aa 0 2 (adaptive, 1 to 16 samples)     ours --aa=ADAPTIVE (the file's depth 3, threshold 8)
  16spp     Sunflow -aa 2 2 (fixed 4x4 = 16 samples)        ours --aa=RANDOM (the file's grid 4x4)

Our side runs in the ways asked for: the launcher `./raytracer` (--launcher), `java -jar
target/raytracer.jar` (--jar); both by default), and any number of command templates (--command),
e.g. --command 'java -XX:+UseSerialGC --add-modules jdk.incubator.vector -jar target/raytracer.jar'.
A template is split like a shell command line (no shell runs it); leading NAME=VALUE words are
set in its environment (RAYTRACER_JAVA_OPTS='-XX:TieredStopAtLevel=4' ./raytracer); the render's
arguments (scene, --threads, --aa, --quiet, --output) go where the word {args} stands, else at the
end. Commands run from the project root.

Sunflow runs as `java -jar SUNFLOW_JAR -nogui -o OUT.png -threads 2 -aa MIN MAX final-project.sc`
(the jar built from Sunflow's source; Janino's jar beside it, as its manifest's Class-Path asks).

Method: whole processes, wall time from start to exit, one at a time. First an untimed warm-up:
every command once on the 1spp case (files into the page cache), and, per case, Sunflow and the
first of our commands once with their statistics printed (rays per pixel, shown under the table).
Then --rounds rounds; in each round, each case runs every command once, in an order rotated from
round to round. The table gives per case and command the median wall seconds (min, max), the
median CPU seconds (user + system of the process), and the median of the round-by-round ratios to
Sunflow's wall time in the same round (a machine whose speed drifts moves both sides of a ratio),
with a 95 % interval for that median that assumes nothing of the ratios' distribution (order
statistics; at least 6 rounds): a target such as "at most 0.5 of Sunflow's time" is met beyond
doubt only when the whole interval is below it.
Our commands' images of a case must be byte-identical (they are the same renderer); Sunflow's
image is a different renderer's and is not compared.

Run from anywhere: `python3 scripts/sunflow_benchmark.py --sunflow-jar PATH [--rounds N]`.
Builds nothing unless --build (then `mvn -q package -DskipTests` first). Writes the Markdown to
--out (default target/bench/sunflow.md) and prints it. Python 3.9+, standard library only, the
JDK on PATH (or JAVA_HOME).
"""
from __future__ import annotations

import argparse
import math
import os
import platform
import re
import resource
import shlex
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cold_start_benchmark import OUT, ROOT, java  # noqa: E402  (the same project root and JVM choice)

SCENE_SC = ROOT / "scripts" / "sunflow" / "final-project.sc"
SCENE_XML = ROOT.parent / "shared" / "data" / "sunflow-final-project.xml"
# case name -> (Sunflow's -aa min max, our --aa mode)
CASES = {
    "1spp": (("0", "0"), "NONE"),
    "adaptive": (("0", "2"), "ADAPTIVE"),
    "16spp": (("2", "2"), "RANDOM"),
}
SUNFLOW = "Sunflow"
ENV_WORD = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*=")


@dataclass
class Command:
    """One way of running a render: a label, a function from (case, output file) to argv, an environment."""
    label: str
    argv: object  # callable (case: str, out: Path, quiet: bool) -> list[str]
    env: dict = field(default_factory=dict)
    ours: bool = True


def split_template(template: str) -> tuple[dict, list[str]]:
    """A command template's leading NAME=VALUE words (its environment) and the rest (its words)."""
    words = shlex.split(template)
    env = {}
    while words and ENV_WORD.match(words[0]):
        name, value = words.pop(0).split("=", 1)
        env[name] = value
    if not words:
        raise ValueError(f"command template {template!r} names no program")
    return env, words


def fill(words: list[str], args: list[str]) -> list[str]:
    """The template's words with the render's arguments at {args}, or appended."""
    if "{args}" in words:
        i = words.index("{args}")
        return words[:i] + args + words[i + 1:]
    return words + args


def our_args(scene: Path, case: str, out: Path, threads: int, quiet: bool) -> list[str]:
    args = [str(scene), f"--threads={threads}", f"--aa={CASES[case][1]}", f"--output={out}"]
    return args + (["--quiet"] if quiet else [])


def our_command(label: str, template: str, scene: Path, threads: int) -> Command:
    env, words = split_template(template)
    return Command(label, lambda case, out, quiet: fill(words, our_args(scene, case, out, threads, quiet)), env)


def sunflow_command(jar: Path, scene: Path, threads: int, jvm_options: list[str]) -> Command:
    def argv(case: str, out: Path, quiet: bool) -> list[str]:
        aa_min, aa_max = CASES[case][0]
        return [java(), *jvm_options, "-jar", str(jar), "-nogui", "-o", str(out), "-threads", str(threads),
                "-aa", aa_min, aa_max, str(scene)]
    return Command(SUNFLOW, argv, ours=False)


@dataclass
class Run:
    wall: float
    cpu: float
    output: str


def run(command: Command, case: str, out: Path, quiet: bool = True) -> Run:
    """One whole process, one at a time; fails loudly if it fails or writes no image."""
    argv = command.argv(case, out, quiet)
    out.unlink(missing_ok=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True, env={**os.environ, **command.env})
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    shown = " ".join(f"{k}={shlex.quote(v)}" for k, v in command.env.items()) + " " * bool(command.env) + shlex.join(argv)
    if done.returncode != 0:
        raise SystemExit(f"sunflow_benchmark: {shown} exited with {done.returncode}:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    if not out.is_file():  # Sunflow exits 0 on a scene it could not read
        raise SystemExit(f"sunflow_benchmark: {shown} wrote no {out}:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    return Run(wall, cpu, done.stdout + done.stderr)


OUR_RAYS = re.compile(r"rays: camera (\d+), shadow (\d+), secondary (\d+)")
SUNFLOW_RAYS = re.compile(r"^\S+\s+info\s+:\s+(eye|total)\s+(\d+)\s+([0-9.]+)", re.MULTILINE)


def rays_per_pixel(output: str, ours: bool, pixels: int) -> tuple[float, float] | None:
    """(camera rays, all rays) per pixel from a render's printed statistics, or None."""
    if ours:
        m = OUR_RAYS.search(output)
        if not m:
            return None
        camera, shadow, secondary = (int(g) for g in m.groups())
        return camera / pixels, (camera + shadow + secondary) / pixels
    found = {m[1]: int(m[2]) for m in SUNFLOW_RAYS.finditer(output)}
    if "eye" not in found or "total" not in found:
        return None
    return found["eye"] / pixels, found["total"] / pixels


def median_interval(values: list[float], level: float = 0.95) -> tuple[float, float] | None:
    """A distribution-free interval for the median of the population the values were drawn from.

    The k-th smallest and k-th largest values, for the largest k whose interval holds the median
    with probability at least `level` whatever the (continuous) distribution: it misses only when
    fewer than k values fall on one side of the median, 2 * P(Binomial(n, 1/2) < k). None when
    even the smallest and largest value are not enough (fewer than 6 values at 95 %): more rounds
    are needed.
    """
    n = len(values)
    ordered = sorted(values)
    tail = 0.0  # P(B <= k - 1), B ~ Binomial(n, 1/2)
    best = None
    for k in range(1, n // 2 + 1):
        tail += math.comb(n, k - 1) / 2 ** n
        if 1 - 2 * tail < level:
            break
        best = (ordered[k - 1], ordered[n - k])
    return best


def table(cases: list[str], commands: list[Command], walls: dict, cpus: dict) -> str:
    lines = ["| case | command | median wall s | min | max | median CPU s | median ratio to Sunflow (round by round) "
             "| 95 % interval of that median |",
             "|---|---|--:|--:|--:|--:|--:|--:|"]
    for case in cases:
        base = walls[case][SUNFLOW]
        for c in commands:
            w = walls[case][c.label]
            ratios = [a / b for a, b in zip(w, base)]
            interval = median_interval(ratios)
            shown = "—" if not c.ours else f"{interval[0]:.3f}–{interval[1]:.3f}" if interval else "more rounds needed"
            lines.append(f"| {case} | `{c.label}` | {statistics.median(w):.3f} | {min(w):.3f} | {max(w):.3f} | "
                         f"{statistics.median(cpus[case][c.label]):.3f} | {statistics.median(ratios):.3f} | {shown} |")
    return "\n".join(lines)


def java_version() -> str:
    done = subprocess.run([java(), "-version"], capture_output=True, text=True)
    return (done.stderr or done.stdout).splitlines()[0] if (done.stderr or done.stdout) else "unknown"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n".join(__doc__.splitlines()[2:]))
    parser.add_argument("--sunflow-jar", type=Path, required=True,
                        help="Sunflow's runnable jar, built from its source (Janino's janino.jar beside it)")
    parser.add_argument("--rounds", type=int, default=7, help="interleaved rounds (default 7)")
    parser.add_argument("--out", type=Path, default=OUT / "sunflow.md", help="the Markdown report (default target/bench/sunflow.md)")
    parser.add_argument("--launcher", action=argparse.BooleanOptionalAction, default=True,
                        help="time ./raytracer (default on)")
    parser.add_argument("--jar", action=argparse.BooleanOptionalAction, default=True,
                        help="time java -jar target/raytracer.jar (default on)")
    parser.add_argument("--command", action="append", default=[], metavar="TEMPLATE",
                        help="another way to run ours, e.g. 'java -XX:+UseSerialGC -jar target/raytracer.jar' (repeatable)")
    parser.add_argument("--cases", default=",".join(CASES), help=f"which cases, comma-separated (default {','.join(CASES)})")
    parser.add_argument("--threads", type=int, default=2, help="render threads on both sides (default 2)")
    parser.add_argument("--scene-sc", type=Path, default=SCENE_SC, help="Sunflow's scene (default scripts/sunflow/final-project.sc)")
    parser.add_argument("--scene-xml", type=Path, default=SCENE_XML, help="ours (default ../shared/data/sunflow-final-project.xml)")
    parser.add_argument("--sunflow-jvm-options", default="", help="JVM options for Sunflow's java, e.g. '-Xmx1g' (default none)")
    parser.add_argument("--images", type=Path, help="keep each command's last image per case in this folder")
    parser.add_argument("--build", action="store_true", help="mvn -q package -DskipTests first")
    args = parser.parse_args(argv)

    cases = [c.strip() for c in args.cases.split(",") if c.strip()]
    unknown = [c for c in cases if c not in CASES]
    if unknown or not cases or args.rounds < 1:
        parser.error(f"cases must be among {', '.join(CASES)} and rounds at least 1 (got {args.cases!r}, {args.rounds})")
    for path, what in ((args.sunflow_jar, "--sunflow-jar"), (args.scene_sc, "--scene-sc"), (args.scene_xml, "--scene-xml")):
        if not path.is_file():
            parser.error(f"{what}: no file {path}")
    if args.build:
        subprocess.run(["mvn", "-q", "package", "-DskipTests"], cwd=ROOT, check=True)
    scene_xml, scene_sc = args.scene_xml.resolve(), args.scene_sc.resolve()
    templates = ([("./raytracer", shlex.quote(str(ROOT / "raytracer")))] if args.launcher else []) \
        + ([("java -jar target/raytracer.jar", f"{shlex.quote(java())} -jar target/raytracer.jar")] if args.jar else []) \
        + [(t, t) for t in args.command]
    if not templates:
        parser.error("nothing of ours to time: --launcher, --jar or --command")
    if (args.launcher or args.jar) and not (ROOT / "target" / "raytracer.jar").is_file():
        parser.error("no target/raytracer.jar: build it first (mvn -q package -DskipTests) or pass --build")
    try:
        ours = [our_command(label, template, scene_xml, args.threads) for label, template in templates]
    except ValueError as e:
        parser.error(str(e))
    sunflow = sunflow_command(args.sunflow_jar.resolve(), scene_sc, args.threads, shlex.split(args.sunflow_jvm_options))
    commands = [sunflow] + ours
    if len({c.label for c in commands}) != len(commands):
        parser.error("two commands with the same label")

    load = os.getloadavg()
    walls = {case: {c.label: [] for c in commands} for case in cases}
    cpus = {case: {c.label: [] for c in commands} for case in cases}
    rays: dict = {}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        png = {c.label: i for i, c in enumerate(commands)}
        image = lambda case, c: work / f"{case}-{png[c.label]}.png"
        # Warm-up, untimed: every command on the first case; statistics of Sunflow and our first command per case.
        for c in commands:
            run(c, cases[0], image(cases[0], c))
        for case in cases:
            for c in (sunflow, ours[0]):
                r = run(c, case, image(case, c), quiet=False)
                rays[(case, c.ours)] = rays_per_pixel(r.output, c.ours, 600 * 600)
        for r_ in range(args.rounds):
            for case in cases:
                k = r_ % len(commands)
                for c in commands[k:] + commands[:k]:
                    done = run(c, case, image(case, c))
                    walls[case][c.label].append(done.wall)
                    cpus[case][c.label].append(done.cpu)
        identical = {case: len({image(case, c).read_bytes() for c in ours}) == 1 for case in cases}
        if args.images:
            args.images.mkdir(parents=True, exist_ok=True)
            for case in cases:
                for c in commands:
                    name = "sunflow" if not c.ours else re.sub(r"[^A-Za-z0-9]+", "-", c.label).strip("-")[:60]
                    (args.images / f"{case}-{png[c.label]}-{name}.png").write_bytes(image(case, c).read_bytes())

    notes = [f"{args.rounds} interleaved round(s) after the warm-up; {args.threads} threads; 600x600; "
             f"{java_version()}; {os.cpu_count()} CPUs ({platform.machine()}); load average at the start "
             f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}.",
             f"Sunflow: `{shlex.join(sunflow.argv(cases[0], Path('OUT.png'), True))}` (-aa per case: "
             + ", ".join(f"{case} {' '.join(CASES[case][0])}" for case in cases) + ").",
             f"Ours: each command + `{shlex.join(our_args(scene_xml, cases[0], Path('OUT.png'), args.threads, True))}` "
             "(--aa per case: " + ", ".join(f"{case} {CASES[case][1]}" for case in cases) + ")."]
    for case in cases:
        sf, us = rays.get((case, False)), rays.get((case, True))
        fmt = lambda r: f"{r[0]:.2f} camera / {r[1]:.2f} all" if r else "not printed"
        notes.append(f"{case}: rays per pixel, Sunflow {fmt(sf)}, ours {fmt(us)}; our images "
                     + ("byte-identical across our commands." if identical[case] else "**NOT identical** across our commands."))
    report = (f"### Sunflow side by side: {scene_xml.name} / {scene_sc.name}, whole process\n\n"
              f"{table(cases, commands, walls, cpus)}\n\n" + "\n".join(f"- {n}" for n in notes) + "\n")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(report)
    print(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
