"""Tests for verify_images.py.  Images are generated into tmp_path; none are committed."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import OpenImageIO as oiio
import pytest

SCRIPT = Path(__file__).resolve().parent / "verify_images.py"
sys.path.insert(0, str(SCRIPT.parent))

import verify_images

DEFAULT_THRESHOLDS = {
    "defaults": {
        "failthresh": 0.004,
        "failpercent": 0.02,
        "hardfail": 0.012,
        "warnthresh": 0.008,
        "warnpercent": 0.02,
    },
    "overrides": {},
}


@dataclass
class Run:
    code: int
    out: str
    err: str

    @property
    def last_line(self) -> str:
        return self.out.rstrip("\n").splitlines()[-1]


def write_png(path: Path, pixels: np.ndarray) -> None:
    """Write uint8 (h, w, c) pixels as an 8-bit PNG."""
    h, w, c = pixels.shape
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, c, oiio.UINT8))
    assert buf.set_pixels(oiio.ROI(), np.ascontiguousarray(pixels, dtype=np.uint8))
    assert buf.write(str(path)), buf.geterror()


def gradient(w: int = 32, h: int = 24, c: int = 3) -> np.ndarray:
    """Mid-range values so +-1 noise never clips at 0 or 255."""
    y, x = np.mgrid[0:h, 0:w]
    base = 40 + (x * 5 + y * 3) % 170
    return np.stack([base + 10 * k for k in range(c)], axis=-1).astype(np.uint8)


@pytest.fixture
def project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A project root laid out like the real one, used as the working directory."""
    (tmp_path / "images" / "reference").mkdir(parents=True)
    (tmp_path / "target" / "test-run" / "images" / "golden").mkdir(parents=True)
    write_thresholds(tmp_path, DEFAULT_THRESHOLDS)
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("CI", raising=False)
    return tmp_path


# Where the golden suite writes its renders, relative to the project root (the script's default).
GOLDEN = Path("target/test-run/images/golden")


def write_thresholds(root: Path, data: object) -> None:
    (root / "images" / "reference" / "thresholds.json").write_text(json.dumps(data))


def add_pair(root: Path, name: str, render: np.ndarray, reference: np.ndarray) -> None:
    write_png(root / GOLDEN / name, render)
    write_png(root / "images" / "reference" / name, reference)


def run(capsys: pytest.CaptureFixture[str], *args: str) -> Run:
    code = verify_images.main(list(args))
    captured = capsys.readouterr()
    return Run(code, captured.out, captured.err)


def report(root: Path) -> dict:
    return json.loads((root / "target" / "image-report" / "report.json").read_text())


def image_entry(root: Path, name: str) -> dict:
    return next(i for i in report(root)["images"] if i["name"] == name)


# ---------------------------------------------------------------- comparisons


def test_identical_images_pass(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    add_pair(project, "same.png", gradient(), gradient())
    r = run(capsys)
    assert r.code == 0
    assert r.last_line == "1 passed, 0 failed"
    assert "PASS  same.png  mean 0.00000 max 0.0000 @ (0,0) psnr inf dB  fail 0.000%" in r.out
    entry = image_entry(project, "same.png")
    assert entry["status"] == "PASS"
    assert entry["metrics"]["psnr"] is None  # infinite PSNR is null in strict JSON


def test_single_pixel_beyond_hardfail_fails(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    render = gradient()
    render[5, 7, 1] += 4  # 4/255 = 0.0157 > hardfail 0.012; 1 pixel of 768 = 0.13% > 0.02%
    add_pair(project, "one_pixel.png", render, gradient())
    r = run(capsys)
    assert r.code == 1
    assert r.last_line == "0 passed, 1 failed"
    line = next(l for l in r.out.splitlines() if "one_pixel.png" in l)
    assert line.startswith("FAIL  one_pixel.png")
    assert "@ (7,5)" in line and "exceeds hardfail 0.012" in line
    metrics = image_entry(project, "one_pixel.png")["metrics"]
    assert (metrics["maxx"], metrics["maxy"], metrics["maxc"], metrics["nfail"]) == (7, 5, 1, 1)


def test_hardfail_applies_even_when_percentage_is_allowed(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write_thresholds(project, {"defaults": {"failpercent": 50}, "overrides": {}})
    render = gradient()
    render[0, 0, 0] += 10
    add_pair(project, "spike.png", render, gradient())
    r = run(capsys)
    assert r.code == 1
    assert "exceeds hardfail" in r.out and "allowed 50%" not in r.out


def test_too_many_pixels_over_failthresh_fails_below_hardfail(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    render = gradient()
    render[:2, :, 0] += 2  # 2/255 = 0.0078: above failthresh, below hardfail; 64 of 768 pixels
    add_pair(project, "shifted.png", render, gradient())
    r = run(capsys)
    assert r.code == 1
    assert "8.333% of pixels (64) differ by more than failthresh 0.004, allowed 0.02%" in r.out
    assert "hardfail" not in next(l for l in r.out.splitlines() if "shifted.png" in l)


def test_noise_within_tolerance_passes(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    rng = np.random.default_rng(7)
    noise = rng.choice(np.array([-1, 1]), size=gradient().shape)
    render = (gradient().astype(int) + noise).astype(np.uint8)  # every value off by 1/255 = 0.0039
    add_pair(project, "noisy.png", render, gradient())
    r = run(capsys)
    assert r.code == 0, r.out
    assert r.last_line == "1 passed, 0 failed"
    metrics = image_entry(project, "noisy.png")["metrics"]
    assert metrics["maxerror"] == pytest.approx(1 / 255, abs=1e-6)
    assert metrics["nfail"] == 0


def test_size_mismatch_fails(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # All-black images of different sizes: OpenImageIO's compare alone reports no error.
    add_pair(project, "size.png", np.zeros((10, 12, 3), np.uint8), np.zeros((8, 12, 3), np.uint8))
    r = run(capsys)
    assert r.code == 1
    assert "SIZE-MISMATCH  size.png  size differs: render 12x10, reference 12x8" in r.out
    assert r.last_line == "0 passed, 1 failed"


def test_channel_count_mismatch_fails(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # RGB vs RGBA with alpha 0: OpenImageIO treats the missing channel as 0 and would pass it.
    rgba = np.concatenate([gradient(), np.zeros((24, 32, 1), np.uint8)], axis=-1)
    add_pair(project, "alpha.png", gradient(), rgba)
    r = run(capsys)
    assert r.code == 1
    assert "channel count differs: render 3 (RGB), reference 4 (RGBA)" in r.out
    assert image_entry(project, "alpha.png")["status"] == "SIZE-MISMATCH"


def test_unreadable_render_is_an_error(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write_png(project / "images" / "reference" / "broken.png", gradient())
    (project / GOLDEN / "broken.png").write_bytes(b"not a png")
    r = run(capsys)
    assert r.code == 1
    assert "ERROR  broken.png  cannot read" in r.out


def test_warning_does_not_fail(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write_thresholds(
        project, {"defaults": {"warnthresh": 0.001, "warnpercent": 0}, "overrides": {}}
    )
    render = gradient()
    render[3, 3, 0] += 1
    add_pair(project, "warn.png", render, gradient())
    r = run(capsys)
    assert r.code == 0
    assert "warning: " in r.out
    assert image_entry(project, "warn.png")["warning"].startswith("warning:")


# ---------------------------------------------------------------- missing files


def test_missing_reference_and_missing_render_are_failures(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write_png(project / GOLDEN / "new.png", gradient())
    write_png(project / "images" / "reference" / "gone.png", gradient())
    r = run(capsys)
    assert r.code == 1
    assert "MISSING-REFERENCE  new.png" in r.out
    assert "MISSING-RENDER  gone.png" in r.out
    assert "references with no render (1): gone.png" in r.out
    assert "renders with no reference (1): new.png" in r.out
    assert r.last_line == "0 passed, 2 failed"
    data = report(project)
    assert data["missing_renders"] == ["gone.png"]
    assert data["missing_references"] == ["new.png"]


def test_allow_new_accepts_missing_reference_but_not_missing_render(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write_png(project / GOLDEN / "new.png", gradient())
    r = run(capsys, "--allow-new")
    assert r.code == 0
    assert "MISSING-REFERENCE  new.png" in r.out
    assert r.last_line == "0 passed, 0 failed"

    write_png(project / "images" / "reference" / "gone.png", gradient())
    assert run(capsys, "--allow-new").code == 1


def test_reference_folder_inside_renders_is_not_a_render(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    add_pair(project, "a.png", gradient(), gradient())
    (project / GOLDEN / "sub").mkdir()
    write_png(project / GOLDEN / "sub" / "nested.png", gradient())
    r = run(capsys)
    assert r.last_line == "1 passed, 0 failed"
    assert "nested.png" not in r.out


# ---------------------------------------------------------------- configuration


@pytest.mark.parametrize(
    ("thresholds", "message"),
    [
        ({"overrides": {"a.png": {"failpercent": 0.5}}}, 'needs a non-empty "reason"'),
        (
            {"overrides": {"a.png": {"failpercent": 0.5, "reason": "  "}}},
            'needs a non-empty "reason"',
        ),
        ({"overrides": {"a.png": {"reason": "noisy"}}}, "changes no threshold"),
        ({"overrides": {"a.png": {"failpercnt": 1, "reason": "x"}}}, 'unknown key "failpercnt"'),
        ({"defaults": {"hardfail": -1}}, "hardfail must be a finite number >= 0, got -1"),
        ({"defaults": {"failpercent": 150}}, "failpercent is a percentage (0..100), got 150"),
        ({"defaults": {"failthresh": "0.1"}}, 'failthresh must be a number, got "0.1"'),
        ({"defaults": {"failthresh": True}}, "failthresh must be a number, got true"),
        ({"default": {}}, "unknown top-level key(s) ['default']"),
        ([], "top level must be a JSON object, got list"),
    ],
)
def test_bad_thresholds_exit_2(
    project: Path, capsys: pytest.CaptureFixture[str], thresholds: object, message: str
) -> None:
    add_pair(project, "a.png", gradient(), gradient())
    write_thresholds(project, thresholds)
    r = run(capsys)
    assert r.code == 2
    assert message in r.err
    assert "passed" not in r.out


def test_invalid_json_exit_2(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / "images" / "reference" / "thresholds.json").write_text('{"defaults": {,}}')
    r = run(capsys)
    assert r.code == 2
    assert "invalid JSON at line 1 column 15" in r.err


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--renders", "nope"], "renders folder not found: nope"),
        (["--references", "nope"], "references folder not found: nope"),
        (["--thresholds", "nope.json"], "thresholds file not found: nope.json"),
        (["--references", str(GOLDEN)], "renders and references are the same folder"),
    ],
)
def test_bad_paths_exit_2(
    project: Path, capsys: pytest.CaptureFixture[str], args: list[str], message: str
) -> None:
    r = run(capsys, *args)
    assert r.code == 2
    assert message in r.err


def test_override_with_reason_loosens_one_image(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    render = gradient()
    render[:2, :, 0] += 2
    add_pair(project, "soft.png", render, gradient())
    add_pair(project, "strict.png", render, gradient())
    write_thresholds(
        project,
        {
            "defaults": DEFAULT_THRESHOLDS["defaults"],
            "overrides": {
                "soft.png": {"failpercent": 10, "reason": "soft shadows are sampled"},
                "typo.png": {"failpercent": 10, "reason": "stale"},
            },
        },
    )
    r = run(capsys)
    assert r.code == 1
    assert "PASS  soft.png" in r.out and "(override: soft shadows are sampled)" in r.out
    assert "FAIL  strict.png" in r.out
    assert "warning: thresholds override for typo.png matches no render or reference" in r.out
    entry = image_entry(project, "soft.png")
    assert entry["thresholds"]["failpercent"] == 10
    assert entry["thresholds"]["hardfail"] == 0.012  # inherited from defaults
    assert entry["override_reason"] == "soft shadows are sampled"


def test_committed_thresholds_file_is_valid() -> None:
    committed = SCRIPT.parent.parent / "images" / "reference" / "thresholds.json"
    config = verify_images.load_config(committed)
    assert config.defaults == verify_images.Thresholds()
    assert config.overrides == {}


# ---------------------------------------------------------------- reports


def test_reports_and_artifacts(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = gradient()
    bad[10:14, 10:14] = 255
    add_pair(project, "bad.png", bad, gradient())
    add_pair(project, "good.png", gradient(), gradient())
    write_png(project / "images" / "reference" / "gone.png", gradient())
    r = run(capsys)
    assert r.last_line == "1 passed, 2 failed"

    out = project / "target" / "image-report"
    md = (out / "report.md").read_text()
    for name in ("bad.png", "good.png", "gone.png"):
        assert name in md
    assert (
        "| bad.png | FAIL |" in md
        and "| good.png | PASS |" in md
        and "| gone.png | MISSING-RENDER |" in md
    )
    assert "[diff](<bad.png.diff.png>)" in md and "[heat](<bad.png.heat.png>)" in md

    data = report(project)
    assert data["summary"] == {"passed": 1, "failed": 2, "new_allowed": 0}
    assert {i["name"]: i["status"] for i in data["images"]} == {
        "bad.png": "FAIL",
        "good.png": "PASS",
        "gone.png": "MISSING-RENDER",
    }

    bad_entry = image_entry(project, "bad.png")
    assert bad_entry["diff_image"] == "bad.png.diff.png"
    assert image_entry(project, "good.png")["diff_image"] is None
    assert not (out / "good.png.diff.png").exists()

    diff = oiio.ImageBuf(str(out / "bad.png.diff.png")).get_pixels(oiio.FLOAT)
    heat = oiio.ImageBuf(str(out / "bad.png.heat.png")).get_pixels(oiio.FLOAT)
    assert diff.shape == heat.shape == (24, 32, 3)
    assert diff[12, 12].min() == 1.0 and diff[0, 0].max() == 0.0  # amplified and clamped
    assert heat[0, 0].max() == 0.0  # black = identical
    assert heat[12, 12][0] == heat[12, 12][1] == 1.0  # error > 0.25: yellow towards white


def test_diff_image_drops_alpha(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    ref = np.concatenate([gradient(), np.full((24, 32, 1), 255, np.uint8)], axis=-1)
    render = ref.copy()
    render[0, 0, 3] = 0  # only alpha differs
    add_pair(project, "rgba.png", render, ref)
    assert run(capsys).code == 1
    out = project / "target" / "image-report"
    assert oiio.ImageBuf(str(out / "rgba.png.diff.png")).spec().nchannels == 3
    heat = oiio.ImageBuf(str(out / "rgba.png.heat.png")).get_pixels(oiio.FLOAT)
    assert heat[0, 0].min() == 1.0  # alpha error of 1.0 shows as white


def test_stale_artifacts_are_removed(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = project / "target" / "image-report"
    out.mkdir(parents=True)
    (out / "old.png.diff.png").write_bytes(b"stale")
    add_pair(project, "a.png", gradient(), gradient())
    run(capsys)
    assert not (out / "old.png.diff.png").exists()


def test_heat_stops_stay_increasing_for_loose_overrides() -> None:
    loose = verify_images.Thresholds(failthresh=0.5, hardfail=0.3)
    stops = verify_images.heat_stops(loose)
    assert np.all(np.diff(stops) > 0)


# ---------------------------------------------------------------- --update


def test_update_copies_new_and_changed_only(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    changed = gradient()
    changed[0, 0, 0] += 1
    add_pair(project, "changed.png", changed, gradient())
    add_pair(project, "same.png", gradient(), gradient())
    write_png(project / GOLDEN / "new.png", gradient())
    same_ref = project / "images" / "reference" / "same.png"
    same_mtime = same_ref.stat().st_mtime_ns

    r = run(capsys, "--update")
    assert r.code == 0, r.out + r.err
    assert "UPDATED  changed.png  changed: max error" in r.out
    assert "UPDATED  new.png  new" in r.out
    assert "UNCHANGED  same.png" in r.out
    assert "copied 2 image(s) to images/reference: changed.png, new.png" in r.out
    assert r.last_line == "3 passed, 0 failed"
    assert same_ref.stat().st_mtime_ns == same_mtime
    ref_dir = project / "images" / "reference"
    assert (ref_dir / "new.png").read_bytes() == (project / GOLDEN / "new.png").read_bytes()
    assert (ref_dir / "changed.png").read_bytes() == (
        project / GOLDEN / "changed.png"
    ).read_bytes()

    assert run(capsys).last_line == "3 passed, 0 failed"


def test_update_keeps_reference_without_render_and_fails(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write_png(project / "images" / "reference" / "gone.png", gradient())
    r = run(capsys, "--update")
    assert r.code == 1
    assert "MISSING-RENDER  gone.png" in r.out
    assert (project / "images" / "reference" / "gone.png").exists()


@pytest.mark.parametrize("ci_value", ["1", "true"])
def test_update_refused_under_ci(
    project: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    ci_value: str,
) -> None:
    monkeypatch.setenv("CI", ci_value)
    write_png(project / GOLDEN / "new.png", gradient())
    r = run(capsys, "--update")
    assert r.code == 2
    assert "--update refuses to run when CI is set" in r.err
    assert not (project / "images" / "reference" / "new.png").exists()


def test_update_allowed_with_empty_ci(
    project: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("CI", "")
    write_png(project / GOLDEN / "new.png", gradient())
    assert run(capsys, "--update").code == 0
    assert (project / "images" / "reference" / "new.png").exists()


# ---------------------------------------------------------------- real CLI


def test_command_line_defaults_and_exit_codes(project: Path) -> None:
    """Runs the script as CI will: a separate process, default paths from the project root."""
    add_pair(project, "a.png", gradient(), gradient())
    env = {k: v for k, v in os.environ.items() if k != "CI"}
    ok = subprocess.run(
        [sys.executable, str(SCRIPT)],
        cwd=project,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    assert ok.returncode == 0, ok.stderr
    assert ok.stdout.splitlines()[-1] == "1 passed, 0 failed"
    assert (project / "target" / "image-report" / "report.md").exists()

    bad = subprocess.run(
        [sys.executable, str(SCRIPT), "--update"],
        cwd=project,
        env={**env, "CI": "1"},
        capture_output=True,
        text=True,
        check=False,
    )
    assert bad.returncode == 2
    assert "refuses" in bad.stderr
