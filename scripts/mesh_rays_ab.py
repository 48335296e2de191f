"""Interleaved A/B of the library's mesh tracing between two builds: bench.MeshRays, one thread.

embree_benchmark.py's ratio to Embree divides two processes run one after the other, so on a busy
machine it moves with whatever else runs in either. This script compares two builds of the library
only (say main and a branch, each a checkout compiled with `mvn -q -Pbench compile`), on the
meshes and rays embree_benchmark.py wrote to target/embree-bench/: for each mesh, pairs of
processes A B or B A in turn (the order alternates, so a drift favours neither), each the median
of its timed passes (the tracing thread's CPU time by default, which other processes on the machine
disturb less than the wall time); then the median over the pairs of B's time over A's. The library's ratio to
Embree "before" and "after" is then its median time over Embree's from the same runs' tables.

    .venv/bin/python scripts/mesh_rays_ab.py --a ../main --b . --pairs 7 \
        --java /usr/lib/jvm/temurin-25-jdk-amd64/bin/java
"""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

MESHES = "teapot,sphere-1e4,sphere-1e5,sphere-1e6"


def classpath(tree: Path) -> str:
    deps = subprocess.run(["mvn", "-q", "-o", "-Pbench", "dependency:build-classpath", "-Dmdep.outputFile=/dev/stdout"],
                          cwd=tree, check=True, capture_output=True, text=True).stdout.strip()
    return str(tree / "target/bench/classes") + ":" + deps


def trace(java: str, cp: str, options: list[str], data: Path, mesh: str, passes: int, key: str) -> float:
    """One process: bench.MeshRays on one thread; its median pass, seconds (of CPU or wall time)."""
    command = [java, "-Xmx8g", *options, "-cp", cp, "bench.MeshRays", str(data / f"{mesh}.mesh"),
               str(data / f"{mesh}.rays"), "1", str(passes), str(data / f"{mesh}.ab.t")]
    line = subprocess.run(command, check=True, capture_output=True, text=True).stdout.strip().splitlines()[-1]
    return json.loads(line)[key]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--a", type=Path, required=True, help="the first checkout (before), compiled with -Pbench")
    parser.add_argument("--b", type=Path, required=True, help="the second checkout (after), compiled with -Pbench")
    parser.add_argument("--data", type=Path, default=Path("target/embree-bench"), help="where embree_benchmark.py wrote the meshes and rays")
    parser.add_argument("--meshes", default=MESHES)
    parser.add_argument("--pairs", type=int, default=7)
    parser.add_argument("--passes", type=int, default=7, help="timed passes per process (after MeshRays' own warm-up)")
    parser.add_argument("--java", default="java")
    parser.add_argument("--time", choices=("cpu", "wall"), default="cpu",
                        help="the tracing thread's CPU time (default: less disturbed by other processes) or wall time")
    parser.add_argument("--options", default="--add-modules jdk.incubator.vector -Draytracer.simd=true",
                        help="JVM options of both sides (default: the vector walk from the first ray)")
    args = parser.parse_args()
    cps = {"A": classpath(args.a.resolve()), "B": classpath(args.b.resolve())}
    options = args.options.split()
    print("| mesh | pairs | A median s | B median s | B ÷ A, median of pairs (quartiles) |")
    print("|---|--:|--:|--:|--:|")
    for mesh in args.meshes.split(","):
        times = {"A": [], "B": []}
        for pair in range(args.pairs):
            for side in ("AB" if pair % 2 == 0 else "BA"):
                times[side].append(trace(args.java, cps[side], options, args.data, mesh, args.passes,
                                         "median_trace_cpu_s" if args.time == "cpu" else "median_trace_s"))
        quotients = sorted(b / a for a, b in zip(times["A"], times["B"]))
        q = statistics.quantiles(quotients, n=4) if len(quotients) > 1 else [quotients[0]] * 3
        print(f"| {mesh} | {args.pairs} | {statistics.median(times['A']):.4f} | {statistics.median(times['B']):.4f} | "
              f"{statistics.median(quotients):.3f} ({q[0]:.3f}–{q[2]:.3f}) |", flush=True)
        print(json.dumps({"mesh": mesh, "A": times["A"], "B": times["B"]}), file=sys.stderr, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
