"""Parity of the Java image assertions (package renderer.junit) with verify_images.py.

For every golden image (its render in target/test-run/images/golden against images/reference) and for
deliberately perturbed copies of every reference, the Java side (renderer.junit.VerdictTool, on
the classes `mvn -B verify` compiled) and this script's OpenImageIO comparison must reach the same
verdict and the same figures, image for image.  The table of verdicts is written to
target/image-assertions-parity.md.

Needs the compiled classes and the golden renders: it runs after `mvn -B verify` (as .ci/run
does).  Without them it is skipped, except under CI, where that is a failure.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import OpenImageIO as oiio
import pytest

SCRIPTS = Path(__file__).resolve().parent
ROOT = SCRIPTS.parent
sys.path.insert(0, str(SCRIPTS))

import verify_images  # noqa: E402

CLASSES = ROOT / "target" / "classes"
TEST_CLASSES = ROOT / "target" / "test-classes"
TOOL_CLASS = TEST_CLASSES / "renderer" / "junit" / "VerdictTool.class"
GOLDEN = ROOT / "target" / "test-run" / "images" / "golden"
REFERENCES = ROOT / "images" / "reference"
TABLE = ROOT / "target" / "image-assertions-parity.md"


def missing_prerequisites() -> str | None:
    if not TOOL_CLASS.exists():
        return f"{TOOL_CLASS.relative_to(ROOT)} is not compiled: run `mvn -B verify` first"
    if not GOLDEN.is_dir() or not any(GOLDEN.glob("*.png")):
        return "no golden renders in target/test-run/images/golden: run `mvn -B verify` first"
    if java() is None:
        return "no java executable (JAVA_HOME or PATH)"
    return None


def java() -> str | None:
    home = os.environ.get("JAVA_HOME")
    if home and (Path(home) / "bin" / "java").exists():
        return str(Path(home) / "bin" / "java")
    return shutil.which("java")


@pytest.fixture(scope="module", autouse=True)
def prerequisites() -> None:
    problem = missing_prerequisites()
    if problem:
        if os.environ.get("CI"):
            pytest.fail(f"parity proof cannot run under CI: {problem}")
        pytest.skip(problem)


# --------------------------------------------------------------------------
# Perturbed copies


def read_u8(path: Path) -> np.ndarray:
    buf = oiio.ImageBuf(str(path))
    pixels = buf.get_pixels(oiio.UINT8)
    assert pixels is not None, buf.geterror()
    return np.array(pixels, dtype=np.uint8)


def write_u8(path: Path, pixels: np.ndarray) -> None:
    h, w, c = pixels.shape
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, c, oiio.UINT8))
    assert buf.set_pixels(oiio.ROI(), np.ascontiguousarray(pixels, dtype=np.uint8))
    assert buf.write(str(path)), buf.geterror()


def shifted(pixels: np.ndarray, steps: np.ndarray | int) -> np.ndarray:
    """Moves values by `steps` 8-bit steps, away from the end they would clip at."""
    v = pixels.astype(np.int32)
    return np.where(v > 127, v - steps, v + steps).clip(0, 255).astype(np.uint8)


def some_pixels(rng: np.random.Generator, pixels: np.ndarray, count: int) -> tuple[np.ndarray, np.ndarray]:
    h, w, _ = pixels.shape
    flat = rng.choice(h * w, size=count, replace=False)
    return flat // w, flat % w


def few_pixels(steps: int, count: int, channel: int | None = None):
    def perturb(p: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        out = p.copy()
        ys, xs = some_pixels(rng, p, count)
        channels = slice(None) if channel is None else channel
        out[ys, xs, channels] = shifted(p[ys, xs, channels], steps)
        return out

    return perturb


def many_pixels(steps: int, share: float):
    def perturb(p: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        h, w, _ = p.shape
        mask = rng.random((h, w)) < share
        out = p.copy()
        out[mask] = shifted(p[mask], steps)
        return out

    return perturb


def noise(sigma_steps: float):
    def perturb(p: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        n = np.rint(rng.normal(0, sigma_steps, p.shape)).astype(np.int32)
        return (p.astype(np.int32) + n).clip(0, 255).astype(np.uint8)

    return perturb


def cropped(p: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    return p[:, :-1, :]


def with_alpha(p: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    return np.concatenate([p, np.full(p.shape[:2] + (1,), 255, np.uint8)], axis=2)


PERTURBATIONS = {
    "identical copy": lambda p, rng: p,
    "3 pixels +1 step (all channels)": few_pixels(1, 3),
    "2 pixels +2 steps": few_pixels(2, 2, channel=1),
    "3 pixels +2 steps": few_pixels(2, 3, channel=1),
    "5 pixels +2 steps": few_pixels(2, 5, channel=0),
    "1 pixel +3 steps": few_pixels(3, 1, channel=2),
    "1 pixel +4 steps": few_pixels(4, 1, channel=2),
    "1 pixel +60 steps": few_pixels(60, 1),
    "40% of pixels +1 step": many_pixels(1, 0.4),
    "0.01% of pixels +2 steps": many_pixels(2, 0.0001),
    "5% of pixels +2 steps": many_pixels(2, 0.05),
    "noise sigma 0.4 steps": noise(0.4),
    "noise sigma 2 steps": noise(2.0),
    "one column cropped": cropped,
    "alpha channel added": with_alpha,
}


@dataclass
class Case:
    image: str
    perturbation: str
    render: Path
    reference: Path


def make_cases(work: Path) -> list[Case]:
    cases: list[Case] = []
    for reference in sorted(REFERENCES.glob("*.png")):
        name = reference.name
        cases.append(Case(name, "golden render", GOLDEN / name, reference))
        original = read_u8(reference)
        for index, (label, perturb) in enumerate(PERTURBATIONS.items()):
            rng = np.random.default_rng([index, sum(name.encode())])
            copy = work / f"{reference.stem}.{index:02d}.png"
            write_u8(copy, perturb(original, rng))
            cases.append(Case(name, label, copy, reference))
        truncated = work / f"{reference.stem}.truncated.png"
        truncated.write_bytes(reference.read_bytes()[: reference.stat().st_size // 2])
        cases.append(Case(name, "render truncated (unreadable)", truncated, reference))
        not_png = work / f"{reference.stem}.text.png"
        not_png.write_text("not a PNG\n")
        cases.append(Case(name, "reference not a PNG", reference, not_png))
        cases.append(Case(name, "reference missing", reference, work / f"{reference.stem}.missing.png"))
    return cases


# --------------------------------------------------------------------------
# Both sides


def python_verdicts(cases: list[Case], config: verify_images.Config, report_dir: Path) -> list[dict]:
    results = []
    for case in cases:
        if not case.reference.exists():
            r = verify_images.missing_reference(case.render.name, case.reference.parent, allow_new=False)
        else:
            r = verify_images.compare_pair(
                case.render.name, case.render, case.reference, config, report_dir
            )
        verdict = "WARN" if r.status is verify_images.Status.PASS and r.warning else str(r.status)
        results.append({"verdict": verdict, "metrics": r.metrics.to_json() if r.metrics else None})
    return results


def java_verdicts(cases: list[Case], work: Path, t: verify_images.Thresholds) -> dict:
    pairs = work / "pairs.tsv"
    pairs.write_text("".join(f"{c.render}\t{c.reference}\n" for c in cases), encoding="utf-8")
    numbers = [str(getattr(t, k)) for k in verify_images.THRESHOLD_KEYS]
    classpath = os.pathsep.join([str(CLASSES), str(TEST_CLASSES)])
    done = subprocess.run(
        [java(), "-cp", classpath, "renderer.junit.VerdictTool", str(pairs), *numbers],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def same_number(a: float | None, b: float | None) -> bool:
    if a is None or b is None:
        return a is b
    return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)


def compare_sides(cases: list[Case], ours: list[dict], theirs: list[dict]) -> list[str]:
    problems = []
    for case, py, jv in zip(cases, ours, theirs, strict=True):
        where = f"{case.image} / {case.perturbation}"
        if py["verdict"] != jv["verdict"]:
            problems.append(f"{where}: OpenImageIO {py['verdict']}, Java {jv['verdict']} ({jv['message']})")
            continue
        pm, jm = py["metrics"], jv.get("metrics")
        if (pm is None) != (jm is None):
            problems.append(f"{where}: metrics on one side only")
            continue
        if pm is None:
            continue
        for key in ("maxx", "maxy", "maxc", "nfail", "nwarn", "npixels"):
            if pm[key] != jm[key]:
                problems.append(f"{where}: {key} OpenImageIO {pm[key]}, Java {jm[key]}")
        for key in ("maxerror", "meanerror", "rms_error", "psnr"):
            if not same_number(pm[key], jm[key]):
                problems.append(f"{where}: {key} OpenImageIO {pm[key]}, Java {jm[key]}")
    return problems


def write_table(title: str, cases: list[Case], ours: list[dict], theirs: list[dict]) -> None:
    lines = [
        f"## {title}",
        "",
        "| Image | Perturbation | OIIO verdict | Java verdict | Max error | Fail % |",
        "|---|---|---|---|---|---|",
    ]
    for case, py, jv in zip(cases, ours, theirs, strict=True):
        m = py["metrics"]
        figures = [f"{m['maxerror']:.4f}", f"{m['fail_percent']:.3f}"] if m else ["", ""]
        lines.append(
            f"| {case.image} | {case.perturbation} | {py['verdict']} | {jv['verdict']} | "
            + " | ".join(figures)
            + " |"
        )
    TABLE.parent.mkdir(exist_ok=True)
    with TABLE.open("a", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n\n")


@pytest.fixture(scope="module")
def cases(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list[Case]]:
    work = tmp_path_factory.mktemp("parity")
    TABLE.unlink(missing_ok=True)
    return work, make_cases(work)


def run_parity(
    title: str, cases: tuple[Path, list[Case]], t: verify_images.Thresholds
) -> tuple[list[dict], dict]:
    work, case_list = cases
    report_dir = work / f"report-{abs(hash(t))}"
    report_dir.mkdir()
    ours = python_verdicts(case_list, verify_images.Config(t, {}), report_dir)
    theirs = java_verdicts(case_list, work, t)
    write_table(title, case_list, ours, theirs["results"])
    problems = compare_sides(case_list, ours, theirs["results"])
    assert not problems, f"{len(problems)} of {len(case_list)} differ:\n" + "\n".join(problems)
    return ours, theirs


def test_java_defaults_are_the_thresholds_file_defaults(cases) -> None:
    work, _ = cases
    pairs = work / "empty.tsv"
    pairs.write_text("")
    classpath = os.pathsep.join([str(CLASSES), str(TEST_CLASSES)])
    out = subprocess.run(
        [java(), "-cp", classpath, "renderer.junit.VerdictTool", str(pairs)],
        capture_output=True, text=True, check=True,
    ).stdout
    config = verify_images.load_config(REFERENCES / "thresholds.json")
    assert json.loads(out)["thresholds"] == {
        k: getattr(config.defaults, k) for k in verify_images.THRESHOLD_KEYS
    }
    assert not config.overrides, "the Java assertions do not read per-image overrides"


def test_every_golden_image_and_perturbation_gets_the_same_verdict(cases) -> None:
    config = verify_images.load_config(REFERENCES / "thresholds.json")
    ours, _ = run_parity("Default thresholds (images/reference/thresholds.json)", cases, config.defaults)
    _, case_list = cases
    assert len(ours) == len(case_list) >= 25 * (len(PERTURBATIONS) + 4)
    verdicts = {r["verdict"] for r in ours}
    # Not a vacuous proof: the cases reach every verdict the defaults can give (WARN cannot
    # happen with them: warnthresh > failthresh and warnpercent = failpercent).
    assert verdicts >= {"PASS", "FAIL", "SIZE-MISMATCH", "ERROR", "MISSING-REFERENCE"}
    golden = [r for c, r in zip(case_list, ours) if c.perturbation == "golden render"]
    assert all(r["verdict"] == "PASS" for r in golden), "the golden suite itself must pass"


def test_same_verdicts_with_limits_that_let_warnings_through(cases) -> None:
    loose = verify_images.Thresholds(
        failthresh=0.01, failpercent=1.0, hardfail=0.1, warnthresh=0.005, warnpercent=0.005
    )
    ours, _ = run_parity("Loose limits with warnings (failthresh 0.01, failpercent 1, hardfail 0.1, warnthresh 0.005, warnpercent 0.005)", cases, loose)
    assert {"PASS", "WARN", "FAIL"} <= {r["verdict"] for r in ours}
