#!/usr/bin/env python3
"""Spark benchmark (BENCHMARKS.md, section "Spark"): the local render against the Spark render
in local mode, as whole processes, in interleaved pairs, with a byte comparison of every pair's
PNGs; then the tile times of a 1400x1400 render and, from them, the estimate of the speed-up on
many executors.

Run from the project root (Java 17 and Maven on the PATH; no Spark installation needed):

    python3 scripts/spark_benchmark.py                 # 3 pairs, showcase 600x600 RANDOM 8x8, local[2]
    python3 scripts/spark_benchmark.py --pairs 5 --no-build

The model of the estimate is printed with the table; see BENCHMARKS.md.
"""
import argparse
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

OUT = Path("target/spark-bench")
SUMMARY = re.compile(
    r"^spark render .*: (?P<job>[\d.]+) s, (?P<px>\d+) px, (?P<tiles>\d+) tiles \(tile time median (?P<median>[\d.]+) s, "
    r"p90 (?P<p90>[\d.]+) s, max (?P<max>[\d.]+) s, sum (?P<sum>[\d.]+) s\)", re.M)


def sh(cmd, **kw):
    return subprocess.run(cmd, check=True, **kw)


def build(skip):
    if not skip:
        sh(["mvn", "-q", "-B", "package", "-DskipTests"])
    OUT.mkdir(parents=True, exist_ok=True)
    cp_file = OUT / "classpath.txt"
    # compile scope = compile + provided: Spark's jars from the local Maven repository
    sh(["mvn", "-q", "-B", "dependency:build-classpath", "-Dmdep.includeScope=compile",
        "-Dmdep.outputFile=" + str(cp_file)])
    flags = re.search(r"<spark.jvm.args>(.*?)</spark.jvm.args>", Path("pom.xml").read_text(), re.S).group(1).split()
    return "target/raytracer.jar:" + cp_file.read_text().strip(), flags


def scene(grid):
    text = Path("scenes/showcase.xml").read_text()
    text, n = re.subn(r"<anti-aliasing [^>]*/>", '<anti-aliasing mode="random" grid="%d %d"/>' % (grid, grid), text)
    assert n == 1, "scenes/showcase.xml: expected one <anti-aliasing> element"
    path = OUT / ("showcase-random%d.xml" % grid)
    path.write_text(text)
    return path


def timed(cmd):
    t0 = time.monotonic()
    run = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    return time.monotonic() - t0, run.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pairs", type=int, default=3, help="interleaved local/Spark pairs (default 3)")
    ap.add_argument("--grid", type=int, default=8, help="RANDOM grid side of the paired renders (default 8)")
    ap.add_argument("--size", type=int, default=600, help="image side of the paired renders (default 600)")
    ap.add_argument("--master", default="local[2]", help="Spark master (default local[2])")
    ap.add_argument("--estimate-grid", type=int, default=2,
                    help="RANDOM grid side of the 1400x1400 tile-time run, scaled to 33x33 (default 2)")
    ap.add_argument("--no-build", action="store_true", help="use the jar and class path already built")
    a = ap.parse_args()

    cp, flags = build(a.no_build)
    bench = scene(a.grid)
    size = ["--width", str(a.size), "--height", str(a.size)]
    local = ["java", "-jar", "target/raytracer.jar", str(bench), *size, "-o", str(OUT / "local.png")]
    spark = ["java", *flags, "-cp", cp, "app.cli.Main", str(bench), *size, "--spark", a.master,
             "-o", str(OUT / "spark.png")]
    print("local: " + " ".join(local))
    print("spark: java <spark.jvm.args of pom.xml> -cp target/raytracer.jar:<Spark jars> app.cli.Main "
          + " ".join(spark[spark.index("app.cli.Main") + 1:]))
    rows = []
    for i in range(a.pairs):
        order = ("local", "spark") if i % 2 == 0 else ("spark", "local")  # ABBA: cancels a drift
        t = {}
        for which in order:
            t[which], out = timed(local if which == "local" else spark)
            if which == "spark":
                t["summary"] = SUMMARY.search(out)
        same = (OUT / "local.png").read_bytes() == (OUT / "spark.png").read_bytes()
        rows.append((t["local"], t["spark"], t["spark"] / t["local"], same, t["summary"]))
        print("pair %d: local %.2f s, spark %.2f s, ratio %.3f, PNG bytes %s" % (
            i + 1, t["local"], t["spark"], t["spark"] / t["local"], "identical" if same else "DIFFERENT"))
    print("median: local %.2f s, spark %.2f s, ratio (pairwise) %.3f; all identical: %s" % (
        statistics.median(r[0] for r in rows), statistics.median(r[1] for r in rows),
        statistics.median(r[2] for r in rows), all(r[3] for r in rows)))
    last = rows[-1][4]
    print("tiles of the last Spark run: %s tiles, median %s s, p90 %s s, max %s s, sum %s s, job %s s" % (
        last["tiles"], last["median"], last["p90"], last["max"], last["sum"], last["job"]))
    startup = statistics.median(r[1] - float(r[4]["job"]) for r in rows)
    print("Spark process time outside the job (JVM, context start, driver parse, PNG write): median %.2f s" % startup)

    # The estimate: tile times of the 1400x1400 render at a small grid, scaled to 33x33.
    est = scene(a.estimate_grid)
    cmd = ["java", *flags, "-cp", cp, "app.cli.Main", str(est), "--width", "1400", "--height", "1400",
           "--spark", a.master, "-o", str(OUT / "estimate.png")]
    _, out = timed(cmd)
    m = SUMMARY.search(out)
    scale = 33 * 33 / (a.estimate_grid * a.estimate_grid)
    n, work, tmax = int(m["tiles"]), float(m["sum"]) * scale, float(m["max"]) * scale
    job = float(m["job"])
    slots = int(re.search(r"\[(\d+)", a.master).group(1)) if "[" in a.master else 2
    # Scheduling overhead per task, measured: the slot-time of the job not spent rendering tiles.
    per_task = max(0.0, (job * slots - float(m["sum"])) / n)
    print("1400x1400 RANDOM %dx%d on %s: job %.2f s, %d tiles, sum %.2f s, max %.3f s; per-task overhead "
          "(slots x job - sum) / tiles = %.4f s" % (a.estimate_grid, a.estimate_grid, a.master, job, n,
                                                      float(m["sum"]), float(m["max"]), per_task))
    print("scaled x%.2f to RANDOM 33x33: work W = %.0f s, slowest tile t_max = %.1f s; local on %d cores ~ W/%d = %.0f s"
          % (scale, work, tmax, slots, slots, work / slots))
    print()
    print("| executors | W/E | t_max | overhead n*c/E | startup S | estimate T(E) = S + n*c/E + max(W/E, t_max) "
          "... S + n*c/E + W/E + t_max | speed-up vs local %d cores |" % slots)
    print("|--:|--:|--:|--:|--:|--:|--:|")
    for e in (8, 32, 128):
        lo = startup + n * per_task / e + max(work / e, tmax)
        hi = startup + n * per_task / e + work / e + tmax
        print("| %d | %.1f s | %.1f s | %.2f s | %.1f s | %.1f … %.1f s | %.0f … %.0f× |" % (
            e, work / e, tmax, n * per_task / e, startup, lo, hi, work / slots / hi, work / slots / lo))
    return 0 if all(r[3] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
