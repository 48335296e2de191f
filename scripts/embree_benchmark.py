"""The tracing core side by side with Intel Embree 4: the same triangles, the same rays.

Each mesh is made here, deterministically: the course teapot (scenes/teapot.obj, 992 triangles)
and displaced UV spheres (a sphere whose radius follows a few sines; the rings near the poles
give long thin triangles, the bumps triangles of varied size and orientation) of about 10^4,
10^5 and 10^6 triangles (and 2x10^6, sphere-2e6, when asked with --meshes). A 512x512 pinhole view fills the image with each. Embree (PyPI's
embreex: one rtcIntersect1 per ray, in its C loop) and the library (bench.MeshRays: one
Bvh.closestHit per ray on a reused Hit) trace the same rays; the table gives Mrays/s of each,
the time ratio (wall time, and the tracing threads' CPU time, which a busy machine disturbs
less), hit agreement and the build times.

Run from the project root after `mvn -q -Pbench compile` (the script does it unless --no-build):

    .venv/bin/python scripts/embree_benchmark.py                 # every mesh, 5 passes
    .venv/bin/python scripts/embree_benchmark.py --meshes teapot,sphere-1e4 --passes 3

Each library row runs once per walk (--walks): the scalar walk of binary nodes
(-Draytracer.simd=false) and the vector walk of wide nodes (--add-modules jdk.incubator.vector
-Draytracer.simd=true);
the vector walk's distances must equal the scalar walk's for every ray (column "= scalar"), as
must its hits and misses.

One thread: Embree's process is pinned to one core (taskset -c 0), so its builder (TBB) gets one
thread; the library builds and traces on one thread by itself (Bvh.build(scene, 1), one worker),
its JVM left free to compile on the other core. Two threads: both cores, the library's trace on
two workers; embreex traces on the calling thread only, so Embree's two-thread row gives its build.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import statistics
import struct
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

OUT = Path("target/embree-bench")
WIDTH = HEIGHT = 512
# Rings x segments of the displaced spheres: 2 * rings * segments triangles, less the poles' fans.
# sphere-2e6 is the largest mesh (its build target); not in the default run (--meshes).
SPHERES = {"sphere-1e4": (70, 72), "sphere-1e5": (224, 224), "sphere-1e6": (707, 708), "sphere-2e6": (1000, 1000)}
DEFAULT_MESHES = "teapot,sphere-1e4,sphere-1e5,sphere-1e6"


def teapot() -> tuple[np.ndarray, np.ndarray]:
    """The course teapot: the vertices and the triangles of scenes/teapot.obj (fans for n-gons)."""
    vertices, faces = [], []
    for line in Path("scenes/teapot.obj").read_text().splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            vertices.append([float(p) for p in parts[1:4]])
        elif parts[0] == "f":
            idx = [int(p.split("/")[0]) for p in parts[1:]]
            idx = [i - 1 if i > 0 else len(vertices) + i for i in idx]
            faces.extend([idx[0], idx[k], idx[k + 1]] for k in range(1, len(idx) - 1))
    return np.array(vertices, dtype=np.float64), np.array(faces, dtype=np.int32)


def displaced_sphere(rings: int, segments: int) -> tuple[np.ndarray, np.ndarray]:
    """A UV sphere of radius 1 whose radius varies by a few sines: fans at the poles, quads between."""
    theta = np.linspace(0, np.pi, rings + 1)[1:-1]                 # inner rings, poles apart
    phi = np.linspace(0, 2 * np.pi, segments, endpoint=False)
    th, ph = np.meshgrid(theta, phi, indexing="ij")
    r = 1 + 0.12 * np.sin(5 * th) * np.cos(7 * ph) + 0.05 * np.sin(13 * ph + 3 * th) + 0.03 * np.cos(29 * th)
    ring = np.stack([r * np.sin(th) * np.cos(ph), r * np.sin(th) * np.sin(ph), r * np.cos(th)], axis=-1)
    vertices = np.concatenate([[[0, 0, 1.0]], ring.reshape(-1, 3), [[0, 0, -1.0]]])
    south = len(vertices) - 1

    def at(i, j):
        return 1 + i * segments + (j % segments)

    faces = [[0, at(0, j), at(0, j + 1)] for j in range(segments)]
    i = np.arange(rings - 2)[:, None]
    j = np.arange(segments)[None, :]
    a, b, c, d = at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)
    quads = np.stack([np.stack([a, c, b], -1), np.stack([b, c, d], -1)], axis=2).reshape(-1, 3)
    faces = np.concatenate([np.array(faces), quads,
                            [[south, at(rings - 2, j + 1), at(rings - 2, j)] for j in range(segments)]])
    return vertices.astype(np.float64), faces.astype(np.int32)


def mesh(name: str) -> tuple[np.ndarray, np.ndarray]:
    return teapot() if name == "teapot" else displaced_sphere(*SPHERES[name])


def view(vertices: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """512x512 pinhole rays, unit directions, from a corner view whose image the mesh fills."""
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    centre, radius = (lo + hi) / 2, np.linalg.norm(hi - lo) / 2
    to = np.array([-0.45, -0.35, -0.82])
    to /= np.linalg.norm(to)
    eye = centre - to * radius * 2.2
    right = np.cross(to, [0, 0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, to)
    half = 0.62 * radius                                         # the half-width at the centre's depth
    depth = radius * 2.2
    x = ((np.arange(WIDTH) + 0.5) / WIDTH * 2 - 1) * half
    y = (1 - (np.arange(HEIGHT) + 0.5) / HEIGHT * 2) * half
    xx, yy = np.meshgrid(x, y)                                    # row-major: row by row, as an image
    dirs = to * depth + xx[..., None] * right + yy[..., None] * up
    dirs = (dirs / np.linalg.norm(dirs, axis=-1, keepdims=True)).reshape(-1, 3)
    return np.broadcast_to(eye, dirs.shape).copy(), dirs


def embree(vertices, faces, origins, dirs, passes: int) -> dict:
    from embreex import rtcore_scene
    from embreex.mesh_construction import TriangleMesh

    o32, d32 = origins.astype(np.float32), dirs.astype(np.float32)
    builds = []
    for _ in range(3):
        start = time.perf_counter()
        scene = rtcore_scene.EmbreeScene()
        TriangleMesh(scene, vertices.astype(np.float32), faces)
        scene.run(o32[:1], d32[:1])                               # the first query commits (builds) the scene
        builds.append(time.perf_counter() - start)
    result = None
    for _ in range(5):                                            # untimed, as the library's warm-up
        result = scene.run(o32, d32, output=1)
    times, cpu = [], []
    for _ in range(passes):
        start, cpu_start = time.perf_counter(), time.thread_time()
        result = scene.run(o32, d32, output=1)
        times.append(time.perf_counter() - start)
        cpu.append(time.thread_time() - cpu_start)                # embreex traces on this thread
    t = np.where(result["geomID"] >= 0, result["tfar"].astype(np.float64), np.nan)
    return {"build_s": statistics.median(builds), "median_trace_s": statistics.median(times),
            "median_trace_cpu_s": statistics.median(cpu), "t": t}


# The vector walk from the first ray (-Draytracer.simd=true): a render takes it only when long,
# once compiled (docs/student-guide.md, "The vector walk"), and these processes measure the walk.
WALK_OPTIONS = {"scalar": ["-Draytracer.simd=false"],
                "vector": ["--add-modules", "jdk.incubator.vector", "-Draytracer.simd=true"]}


def library(mesh_file: Path, rays_file: Path, threads: int, passes: int, classpath: str, walk: str, java: str) -> dict:
    out = mesh_file.with_suffix(f".lib{threads}.{walk}.t")
    # Not pinned: the library's build and trace use exactly `threads` threads by themselves, and
    # pinning the JVM to one core would put its JIT compiler and GC threads on the tracing core
    # (passes then varied 3x within one process).
    command = [java, "-Xmx8g", *WALK_OPTIONS[walk], "-cp", classpath, "bench.MeshRays",
               str(mesh_file), str(rays_file), str(threads), str(passes), str(out)]
    line = subprocess.run(command, check=True, capture_output=True, text=True).stdout.strip().splitlines()[-1]
    result = json.loads(line)
    result["t"] = np.fromfile(out, dtype="<f8")
    return result


def same_distances(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two walks give every ray the same distance to the bit (NaN, a miss, equal to NaN)."""
    return a.shape == b.shape and bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))


def run_embree_pinned(name: str, cpus: str, passes: int) -> dict:
    """Embree in a child process pinned to {@code cpus} (TBB sizes its pool by the affinity mask)."""
    out = OUT / f"{name}.embree{len(cpus.split(','))}.t"
    command = ["taskset", "-c", cpus, sys.executable, __file__, "--embree-child", name, "--passes", str(passes)]
    line = subprocess.run(command, check=True, capture_output=True, text=True).stdout.strip().splitlines()[-1]
    result = json.loads(line)
    result["t"] = np.fromfile(out, dtype="<f8")
    return result


def files(name: str) -> tuple[Path, Path, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    vertices, faces = mesh(name)
    origins, dirs = view(vertices)
    mesh_file, rays_file = OUT / f"{name}.mesh", OUT / f"{name}.rays"
    with open(mesh_file, "wb") as f:
        f.write(struct.pack("<ii", len(vertices), len(faces)))
        f.write(vertices.astype("<f8").tobytes())
        f.write(faces.astype("<i4").tobytes())
    with open(rays_file, "wb") as f:
        f.write(struct.pack("<i", len(dirs)))
        f.write(np.concatenate([origins, dirs], axis=1).astype("<f8").tobytes())
    return mesh_file, rays_file, vertices, faces, origins, dirs


def agreement(a: np.ndarray, b: np.ndarray) -> tuple[float, float]:
    """Share of rays with the same hit/miss, and the largest relative distance difference of rays both hit."""
    same = np.mean(np.isnan(a) == np.isnan(b))
    both = ~np.isnan(a) & ~np.isnan(b)
    rel = np.max(np.abs(a[both] - b[both]) / np.maximum(b[both], 1e-12)) if both.any() else 0.0
    return float(same), float(rel)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", default=DEFAULT_MESHES, help="comma-separated: teapot, " + ", ".join(SPHERES)
                        + " (default " + DEFAULT_MESHES + ")")
    parser.add_argument("--passes", type=int, default=5, help="timed passes over all rays (median reported)")
    parser.add_argument("--no-build", action="store_true", help="skip `mvn -q -Pbench compile`")
    parser.add_argument("--java", default="java", help="the java command the library runs on (default: java on the PATH)")
    parser.add_argument("--walks", default="scalar,vector", help="the library's walks to run: scalar, vector (default both)")
    parser.add_argument("--threads", default="1,2", help="the rows to run: 1 (one thread), 2 (two), or both (default 1,2)")
    parser.add_argument("--out", type=Path, default=OUT / "table.md", help="where the Markdown table goes")
    parser.add_argument("--embree-child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    OUT.mkdir(parents=True, exist_ok=True)

    if args.embree_child:                                         # the pinned child: Embree on files made by the parent
        name = args.embree_child
        vertices, faces = mesh(name)
        origins, dirs = view(vertices)
        result = embree(vertices, faces, origins, dirs, args.passes)
        result["t"].astype("<f8").tofile(OUT / f"{name}.embree{os.sched_getaffinity(0).__len__()}.t")
        print(json.dumps({k: v for k, v in result.items() if k != "t"}))
        return 0

    if shutil.which("taskset") is None:
        print("error: taskset (util-linux) is needed to pin the runs to one core", file=sys.stderr)
        return 2
    if not args.no_build:
        subprocess.run(["mvn", "-q", "-Pbench", "compile"], check=True)
    classpath = subprocess.run(["mvn", "-q", "-Pbench", "dependency:build-classpath", "-Dmdep.outputFile=/dev/stdout"],
                               check=True, capture_output=True, text=True).stdout.strip()
    classpath = "target/bench/classes" + os.pathsep + classpath

    walks = args.walks.split(",")
    if not walks or any(w not in WALK_OPTIONS for w in walks):
        print(f"error: --walks takes scalar and/or vector, got {args.walks!r}", file=sys.stderr)
        return 2
    rows = ["| mesh | triangles | threads | walk | Embree Mrays/s | library Mrays/s | library ÷ Embree time | ÷ CPU time | same hit/miss | max rel. Δt | = scalar | Embree build s | library build s | build ÷ Embree |",
            "|---|--:|--:|---|--:|--:|--:|--:|--:|--:|---|--:|--:|--:|"]
    for name in args.meshes.split(","):
        mesh_file, rays_file, vertices, faces, origins, dirs = files(name)
        for threads, cpus in ((t, c) for t, c in ((1, "0"), (2, "0,1")) if str(t) in args.threads.split(",")):
            emb = run_embree_pinned(name, cpus, args.passes)
            scalar_t = None
            for walk in walks:
                lib = library(mesh_file, rays_file, threads, args.passes, classpath, walk, args.java)
                same, rel = agreement(lib["t"], emb["t"])
                if walk == "scalar":
                    scalar_t = lib["t"]
                equal = "–" if walk == "scalar" or scalar_t is None else ("yes" if same_distances(lib["t"], scalar_t) else "**NO**")
                n = len(dirs)
                # embreex traces on the calling thread: its two-core row gives the build only.
                emb_rate = f"{n / emb['median_trace_s'] / 1e6:.2f}" if threads == 1 else "–"
                ratio = f"{lib['median_trace_s'] / emb['median_trace_s']:.2f}" if threads == 1 else "–"
                # The tracing threads' CPU time: what other processes on a busy machine disturb least.
                cpu_ratio = (f"{lib['median_trace_cpu_s'] / emb['median_trace_cpu_s']:.2f}"
                             if threads == 1 and "median_trace_cpu_s" in lib else "–")
                build_ratio = f"{lib['build_s'] / emb['build_s']:.2f}" if threads == 1 else "–"
                rows.append(f"| {name} | {len(faces)} | {threads} | {walk} | {emb_rate} | {n / lib['median_trace_s'] / 1e6:.2f} | "
                            f"{ratio} | {cpu_ratio} | {same * 100:.3f} % | {rel:.1e} | {equal} | {emb['build_s']:.3f} | {lib['build_s']:.3f} | {build_ratio} |")
                print(rows[-1], flush=True)
    table = "\n".join(rows) + "\n"
    args.out.write_text(table)
    print(f"\n{table}\n(written to {args.out})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
