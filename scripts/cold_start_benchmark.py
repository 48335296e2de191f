#!/usr/bin/env python3
"""Cold start: a whole short render from JVM start to PNG, and the first render of a JUnit-like JVM.

Part 1 times whole processes rendering one scene file at one sample per pixel on 2 threads
(--aa NONE), in interleaved rounds: the baseline jar (--baseline-jar, an older build), this build's
`java -jar target/raytracer.jar`, and the launcher `./raytracer` (its start-up archive in
target/startup/, made on its first run, the serial collector, C1 only). Each round runs the three in a rotated order;
the ratios are taken round by round, so a machine whose speed drifts moves both sides of a ratio.

Part 2 starts `bench.FirstRender` (the README's first scene test, rendered three times in one JVM)
in fresh JVMs: the first render against the second, with the JVM's default options and with the
options the README suggests for a test JVM.

Run from the project root (`python scripts/cold_start_benchmark.py --scene FILE [--baseline-jar JAR]`);
the script builds what it runs (`mvn -q package -DskipTests`, `mvn -q -Pbench compile`) unless
--no-build. Writes the tables to target/bench/cold-start.md and prints them. Needs nothing but
Python 3.9+ and the JDK on PATH (or JAVA_HOME).
"""
from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "target" / "bench"
# What the README suggests for a test JVM (surefire's argLine): see docs/student-guide.md, "Timing a render".
TEST_JVM_OPTIONS = ["-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC"]


def java() -> str:
    home = os.environ.get("JAVA_HOME")
    return str(Path(home) / "bin" / "java") if home else "java"


def timed(command: list[str]) -> float:
    """Wall seconds of one whole process; raises if it fails."""
    start = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"cold_start_benchmark: {' '.join(command)} exited with {done.returncode}:\n{done.stderr}")
    return seconds


def whole_process(scene: Path, baseline: Path | None, rounds: int, work: Path) -> tuple[str, dict]:
    render = [str(scene), "--threads=2", "--aa=NONE", "--quiet"]
    commands = {}
    if baseline:
        commands["baseline jar"] = [java(), "-jar", str(baseline)] + render + [f"--output={work / 'baseline.png'}"]
    commands["java -jar target/raytracer.jar"] = [java(), "-jar", "target/raytracer.jar"] + render + [
        f"--output={work / 'jar.png'}"]
    commands["./raytracer"] = [str(ROOT / "raytracer")] + render + [f"--output={work / 'launcher.png'}"]
    names = list(commands)
    for name in names:  # one untimed run each: the files in the page cache, the archive mapped once
        timed(commands[name])
    times = {name: [] for name in names}
    for r in range(rounds):
        for name in names[r % len(names):] + names[:r % len(names)]:
            times[name].append(timed(commands[name]))
    lines = ["| command | median wall s | min | max |" + (" median ratio to the baseline (round by round) |" if baseline else ""),
             "|---|---|---|---|" + ("---|" if baseline else "")]
    for name in names:
        row = f"| `{name}` | {statistics.median(times[name]):.3f} | {min(times[name]):.3f} | {max(times[name]):.3f} |"
        if baseline:
            ratios = [a / b for a, b in zip(times[name], times["baseline jar"])]
            row += f" {statistics.median(ratios):.3f} |"
        lines.append(row)
    pngs = {name: (work / f).read_bytes() for name, f in
            zip(names, (["baseline.png"] if baseline else []) + ["jar.png", "launcher.png"])}
    same = len(set(pngs.values())) == 1
    lines.append("")
    lines.append(f"{rounds} rounds; the images of all commands are {'byte-identical' if same else 'NOT identical'}.")
    return "\n".join(lines), times


FIRST = re.compile(r"render (\d+): ([0-9.]+) s render, ([0-9.]+) s write")


def first_render(classpath: str, options: list[str], runs: int) -> dict:
    firsts, seconds = [], []
    for _ in range(runs):
        out = subprocess.run([java()] + options + ["-cp", classpath, "bench.FirstRender", "3"], cwd=ROOT,
                             check=True, capture_output=True, text=True).stdout
        renders = {int(m[1]): float(m[2]) + float(m[3]) for m in FIRST.finditer(out)}
        firsts.append(renders[1])
        seconds.append(renders[2])
    return {"first": statistics.median(firsts), "second": statistics.median(seconds),
            "ratio": statistics.median(a / b for a, b in zip(firsts, seconds))}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", type=Path, required=True, help="the scene file of part 1")
    parser.add_argument("--baseline-jar", type=Path, help="an older runnable jar to pair against")
    parser.add_argument("--rounds", type=int, default=7, help="interleaved rounds of part 1")
    parser.add_argument("--runs", type=int, default=7, help="fresh JVMs per option set in part 2")
    parser.add_argument("--no-build", action="store_true", help="use the jar and classes as they are")
    args = parser.parse_args()
    if not args.no_build:
        subprocess.run(["mvn", "-q", "package", "-DskipTests"], cwd=ROOT, check=True)
        subprocess.run(["mvn", "-q", "-Pbench", "compile"], cwd=ROOT, check=True)
    with tempfile.TemporaryDirectory() as tmp:
        table1, _ = whole_process(args.scene.resolve(), args.baseline_jar.resolve() if args.baseline_jar else None,
                                  args.rounds, Path(tmp))
    classpath = os.pathsep.join(["target/bench/classes", "target/classes"])
    rows = ["| test JVM options | first render s | second render s | first / second (median of the runs' ratios) |",
            "|---|---|---|---|"]
    for label, options in (("the JVM's defaults", []), (" ".join(TEST_JVM_OPTIONS), TEST_JVM_OPTIONS)):
        r = first_render(classpath, options, args.runs)
        rows.append(f"| {label} | {r['first']:.3f} | {r['second']:.3f} | {r['ratio']:.2f} |")
    table2 = "\n".join(rows) + f"\n\nMedians of {args.runs} fresh JVMs; a render's figure includes its PNG write."
    report = (f"### Whole process, {args.scene.name}, one sample per pixel, 2 threads\n\n{table1}\n\n"
              f"### First render in a fresh JVM (bench.FirstRender: the README's scene test)\n\n{table2}\n")
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "cold-start.md").write_text(report)
    print(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
