#!/usr/bin/env python3
"""Compare rendered PNGs with committed reference PNGs using OpenImageIO.

Renders are the ``*.png`` files directly in the renders folder; references are
the ``*.png`` files in the reference folder, matched by file name.  Thresholds
come from a JSON file (see images/reference/thresholds.json and
scripts/README.md).  Exit codes: 0 all passed, 1 at least one failure,
2 usage or configuration error.  The last line printed on a completed run is
exactly ``N passed, N failed``.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import shutil
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path
from typing import Any

import numpy as np
import OpenImageIO as oiio
from OpenImageIO import ImageBufAlgo

EXIT_OK = 0
EXIT_FAILED = 1
EXIT_USAGE = 2

# Differences of one or two 8-bit steps (~0.004-0.008) must be visible in the
# diff image, so it is amplified before being clamped to 0..1.
DIFF_GAIN = 20.0

# Heat map ramp: black -> blue -> red -> yellow -> white.  The first three
# stops sit at 0, failthresh and hardfail so a colour means the same thing
# relative to the image's limits; the last two are absolute errors.
HEAT_COLOURS = np.array([[0, 0, 0], [0, 0, 1], [1, 0, 0], [1, 1, 0], [1, 1, 1]], dtype=np.float32)
HEAT_YELLOW_ERROR = 0.25
HEAT_WHITE_ERROR = 1.0

THRESHOLD_KEYS = ("failthresh", "failpercent", "hardfail", "warnthresh", "warnpercent")
PERCENT_KEYS = frozenset({"failpercent", "warnpercent"})
TOP_LEVEL_KEYS = frozenset({"defaults", "overrides"})


class UsageError(Exception):
    """A problem with the command line, folders, thresholds file or report folder (exit 2).

    Kept apart from image failures so CI can tell "the renderer regressed"
    from "the check itself is misconfigured".
    """


class ImageError(Exception):
    """An image that OpenImageIO cannot read or compare; fails that image only."""


class Status(StrEnum):
    PASS = "PASS"
    FAIL = "FAIL"
    MISSING_REFERENCE = "MISSING-REFERENCE"
    MISSING_RENDER = "MISSING-RENDER"
    SIZE_MISMATCH = "SIZE-MISMATCH"
    ERROR = "ERROR"


@dataclass(frozen=True)
class Thresholds:
    """Limits on the 0..1 scale, with the meaning of OpenImageIO's idiff/testsuite.

    An image fails if more than ``failpercent`` % of its pixels have some
    channel differing by more than ``failthresh``, or if any channel of any
    pixel differs by more than ``hardfail``.  The warn pair only adds a note.
    """

    failthresh: float = 0.004
    failpercent: float = 0.02
    hardfail: float = 0.012
    warnthresh: float = 0.008
    warnpercent: float = 0.02


@dataclass(frozen=True)
class Override:
    thresholds: Thresholds
    reason: str


@dataclass(frozen=True)
class Config:
    defaults: Thresholds
    overrides: Mapping[str, Override]

    def thresholds_for(self, name: str) -> tuple[Thresholds, str | None]:
        override = self.overrides.get(name)
        if override is None:
            return self.defaults, None
        return override.thresholds, override.reason


@dataclass(frozen=True)
class Metrics:
    meanerror: float
    maxerror: float
    maxx: int
    maxy: int
    maxc: int
    psnr: float
    rms_error: float
    nfail: int
    nwarn: int
    npixels: int

    @property
    def fail_percent(self) -> float:
        return 100.0 * self.nfail / self.npixels if self.npixels else 0.0

    @property
    def warn_percent(self) -> float:
        return 100.0 * self.nwarn / self.npixels if self.npixels else 0.0

    def to_json(self) -> dict[str, Any]:
        """Strict JSON has no Infinity; identical images have infinite PSNR, so use null."""
        data = dataclasses.asdict(self)
        data["psnr"] = self.psnr if math.isfinite(self.psnr) else None
        data["maxerror"] = self.maxerror if math.isfinite(self.maxerror) else None
        data["fail_percent"] = self.fail_percent
        data["warn_percent"] = self.warn_percent
        return data


@dataclass
class ImageResult:
    name: str
    status: Status
    failed: bool
    message: str = ""
    warning: str = ""
    metrics: Metrics | None = None
    thresholds: Thresholds | None = None
    override_reason: str | None = None
    diff_image: str | None = None
    heat_image: str | None = None

    def to_json(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "status": str(self.status),
            "failed": self.failed,
            "message": self.message,
            "warning": self.warning,
            "metrics": self.metrics.to_json() if self.metrics else None,
            "thresholds": dataclasses.asdict(self.thresholds) if self.thresholds else None,
            "override_reason": self.override_reason,
            "diff_image": self.diff_image,
            "heat_image": self.heat_image,
        }


# --------------------------------------------------------------------------
# Configuration


def load_config(path: Path) -> Config:
    """Read the thresholds file; every mistake is a UsageError naming the bad value."""
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise UsageError(f"thresholds file not found: {path}") from None
    except OSError as exc:
        raise UsageError(f"cannot read thresholds file {path}: {exc.strerror}") from exc
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise UsageError(
            f"{path}: invalid JSON at line {exc.lineno} column {exc.colno}: {exc.msg}"
        ) from exc
    if not isinstance(data, dict):
        raise UsageError(f"{path}: top level must be a JSON object, got {type(data).__name__}")
    # Keys starting with "_" are documentation (JSON has no comments).
    unknown = sorted(k for k in data if k not in TOP_LEVEL_KEYS and not k.startswith("_"))
    if unknown:
        raise UsageError(
            f"{path}: unknown top-level key(s) {unknown}; expected 'defaults' and 'overrides'"
        )
    defaults_raw = data.get("defaults", {})
    if not isinstance(defaults_raw, dict):
        raise UsageError(f"{path}: 'defaults' must be an object, got {json.dumps(defaults_raw)}")
    defaults = parse_thresholds(defaults_raw, Thresholds(), f"{path}: defaults")
    overrides = parse_overrides(data.get("overrides", {}), defaults, path)
    return Config(defaults=defaults, overrides=overrides)


def parse_overrides(raw: Any, defaults: Thresholds, path: Path) -> dict[str, Override]:
    """Overrides loosen a shared limit, so each must say why (a reviewable reason)."""
    if not isinstance(raw, dict):
        raise UsageError(f"{path}: 'overrides' must be an object, got {json.dumps(raw)}")
    overrides: dict[str, Override] = {}
    for name, entry in raw.items():
        where = f"{path}: overrides[{json.dumps(name)}]"
        if not name.endswith(".png") or "/" in name or "\\" in name:
            raise UsageError(f"{where}: key must be a bare PNG file name like 'scene.png'")
        if not isinstance(entry, dict):
            raise UsageError(f"{where}: must be an object, got {json.dumps(entry)}")
        reason = entry.get("reason")
        if not isinstance(reason, str) or not reason.strip():
            raise UsageError(
                f'{where}: needs a non-empty "reason" string, got {json.dumps(reason)}'
            )
        values = {k: v for k, v in entry.items() if k != "reason"}
        if not values:
            raise UsageError(
                f"{where}: changes no threshold (expected one of {list(THRESHOLD_KEYS)})"
            )
        overrides[name] = Override(parse_thresholds(values, defaults, where), reason.strip())
    return overrides


def parse_thresholds(raw: Mapping[str, Any], base: Thresholds, where: str) -> Thresholds:
    """Keys left out inherit from ``base``, so an override only names what it changes."""
    values: dict[str, float] = {}
    for key, value in raw.items():
        if key not in THRESHOLD_KEYS:
            raise UsageError(
                f"{where}: unknown key {json.dumps(key)}; expected one of {list(THRESHOLD_KEYS)}"
            )
        values[key] = check_threshold_value(key, value, where)
    return dataclasses.replace(base, **values)


def check_threshold_value(key: str, value: Any, where: str) -> float:
    # bool is an int subclass; `true` as a threshold is a typo, not 1.0.
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise UsageError(f"{where}: {key} must be a number, got {json.dumps(value)}")
    number = float(value)
    if not math.isfinite(number) or number < 0:
        raise UsageError(f"{where}: {key} must be a finite number >= 0, got {value}")
    if key in PERCENT_KEYS and number > 100:
        raise UsageError(f"{where}: {key} is a percentage (0..100), got {value}")
    return number


# --------------------------------------------------------------------------
# Discovery


def require_dir(path: Path, role: str) -> None:
    if not path.exists():
        raise UsageError(f"{role} folder not found: {path} (resolved to {path.resolve()})")
    if not path.is_dir():
        raise UsageError(f"{role} path is not a folder: {path}")


def list_pngs(folder: Path) -> dict[str, Path]:
    """Non-recursive on purpose: the reference folder lives inside the renders folder."""
    return {p.name: p for p in sorted(folder.iterdir()) if p.suffix == ".png" and p.is_file()}


def check_distinct(renders: Path, references: Path) -> None:
    if renders.resolve() == references.resolve():
        raise UsageError(
            f"renders and references are the same folder ({renders}); every image would match itself"
        )


# --------------------------------------------------------------------------
# Image access


def read_image(path: Path) -> oiio.ImageBuf:
    """Read as float so 8- and 16-bit PNGs compare on the same 0..1 scale."""
    buf = oiio.ImageBuf(str(path))
    if not buf.read(convert=oiio.FLOAT):
        raise ImageError(f"cannot read {path}: {buf.geterror() or 'OpenImageIO gave no reason'}")
    return buf


def write_png(buf: oiio.ImageBuf, path: Path) -> None:
    if buf.has_error:
        raise UsageError(f"cannot build {path.name}: {buf.geterror()}")
    if not buf.write(str(path), oiio.UINT8):
        raise UsageError(f"cannot write {path}: {buf.geterror() or 'OpenImageIO gave no reason'}")


def channel_layout(spec: oiio.ImageSpec) -> str:
    names = list(spec.channelnames)
    return "".join(names) if all(len(n) == 1 for n in names) else ",".join(names)


def shape_mismatch(render: oiio.ImageBuf, reference: oiio.ImageBuf) -> str | None:
    """OpenImageIO's compare pads the smaller image with black over the union of
    both windows and treats missing channels as 0, so a mismatch can pass
    silently (e.g. RGB vs RGBA with alpha 0).  It must be caught up front."""
    rs, fs = render.spec(), reference.spec()
    problems = []
    if (rs.width, rs.height) != (fs.width, fs.height):
        problems.append(
            f"size differs: render {rs.width}x{rs.height}, reference {fs.width}x{fs.height}"
        )
    if rs.nchannels != fs.nchannels:
        problems.append(
            f"channel count differs: render {rs.nchannels} ({channel_layout(rs)}), "
            f"reference {fs.nchannels} ({channel_layout(fs)})"
        )
    return "; ".join(problems) or None


def measure(render: oiio.ImageBuf, reference: oiio.ImageBuf, t: Thresholds) -> Metrics:
    result = ImageBufAlgo.compare(render, reference, t.failthresh, t.warnthresh)
    # CompareResults.error is also True whenever nfail > 0 (it is "not ok"),
    # so only error-without-failures means the comparison itself broke.
    if result.error and result.nfail == 0:
        raise ImageError(
            f"OpenImageIO could not compare the images: {oiio.geterror() or 'no reason given'}"
        )
    spec = render.spec()
    return Metrics(
        meanerror=result.meanerror,
        maxerror=result.maxerror,
        maxx=result.maxx,
        maxy=result.maxy,
        maxc=result.maxc,
        psnr=result.PSNR,
        rms_error=result.rms_error,
        nfail=result.nfail,
        nwarn=result.nwarn,
        npixels=spec.width * spec.height,
    )


def failure_reasons(m: Metrics, t: Thresholds) -> list[str]:
    """Same rule as OpenImageIO's idiff: too many failing pixels, or one pixel too far off."""
    reasons = []
    if m.maxerror > t.hardfail:
        reasons.append(
            f"max error {m.maxerror:.4g} at ({m.maxx},{m.maxy}) channel {m.maxc} exceeds hardfail {t.hardfail:g}"
        )
    if m.nfail > t.failpercent / 100.0 * m.npixels:
        reasons.append(
            f"{m.fail_percent:.3f}% of pixels ({m.nfail}) differ by more than failthresh "
            f"{t.failthresh:g}, allowed {t.failpercent:g}%"
        )
    return reasons


def warning_text(m: Metrics, t: Thresholds) -> str:
    if m.nwarn > t.warnpercent / 100.0 * m.npixels:
        return (
            f"warning: {m.warn_percent:.3f}% of pixels differ by more than warnthresh "
            f"{t.warnthresh:g} (warnpercent {t.warnpercent:g}%)"
        )
    return ""


# --------------------------------------------------------------------------
# Diff artefacts


def without_alpha(buf: oiio.ImageBuf) -> oiio.ImageBuf:
    """An alpha difference written as alpha would make the diff image transparent
    exactly where nothing changed; alpha errors still show in the heat map."""
    spec = buf.spec()
    if spec.alpha_channel < 0 or spec.nchannels < 2:
        return buf
    keep = tuple(c for c in range(spec.nchannels) if c != spec.alpha_channel)
    return ImageBufAlgo.channels(buf, keep)


def heat_stops(t: Thresholds) -> np.ndarray:
    """np.interp needs increasing stops; loose overrides may put hardfail past 0.25."""
    stops: list[float] = []
    for x in (0.0, t.failthresh, t.hardfail, HEAT_YELLOW_ERROR, HEAT_WHITE_ERROR):
        stops.append(max(x, stops[-1] + 1e-6) if stops else x)
    return np.array(stops, dtype=np.float64)


def heat_colours(error: np.ndarray, t: Thresholds) -> np.ndarray:
    stops = heat_stops(t)
    rgb = [np.interp(error, stops, HEAT_COLOURS[:, k]) for k in range(3)]
    return np.stack(rgb, axis=-1).astype(np.float32)


def write_artifacts(
    name: str, render: oiio.ImageBuf, reference: oiio.ImageBuf, t: Thresholds, report_dir: Path
) -> tuple[str, str]:
    absdiff = ImageBufAlgo.absdiff(render, reference)
    amplified = ImageBufAlgo.clamp(ImageBufAlgo.mul(absdiff, DIFF_GAIN), 0.0, 1.0)
    diff_name, heat_name = f"{name}.diff.png", f"{name}.heat.png"
    write_png(without_alpha(amplified), report_dir / diff_name)
    pixels = absdiff.get_pixels(oiio.FLOAT)
    if pixels is None:
        # Not an image problem: OpenImageIO failed on a buffer it just made.
        raise RuntimeError(f"cannot read back the difference of {name}: {absdiff.geterror()}")
    error = pixels.max(axis=2)
    write_png(oiio.ImageBuf(heat_colours(error, t)), report_dir / heat_name)
    return diff_name, heat_name


# --------------------------------------------------------------------------
# Verification


def compare_pair(
    name: str, render_path: Path, reference_path: Path, config: Config, report_dir: Path
) -> ImageResult:
    t, reason = config.thresholds_for(name)
    base = ImageResult(
        name=name, status=Status.PASS, failed=False, thresholds=t, override_reason=reason
    )
    try:
        render, reference = read_image(render_path), read_image(reference_path)
        mismatch = shape_mismatch(render, reference)
        if mismatch:
            return dataclasses.replace(
                base, status=Status.SIZE_MISMATCH, failed=True, message=mismatch
            )
        metrics = measure(render, reference, t)
    except ImageError as exc:
        return dataclasses.replace(base, status=Status.ERROR, failed=True, message=str(exc))
    reasons = failure_reasons(metrics, t)
    if not reasons:
        # A warning is only news on an image that passed; a failure says more.
        return dataclasses.replace(base, metrics=metrics, warning=warning_text(metrics, t))
    diff_name, heat_name = write_artifacts(name, render, reference, t, report_dir)
    return dataclasses.replace(
        base,
        status=Status.FAIL,
        failed=True,
        metrics=metrics,
        message="; ".join(reasons),
        diff_image=diff_name,
        heat_image=heat_name,
    )


def missing_reference(name: str, references: Path, allow_new: bool) -> ImageResult:
    if allow_new:
        message = f"no reference in {references}; allowed by --allow-new"
    else:
        message = (
            f"no reference in {references}; add one with --update "
            "(or pass --allow-new to accept new images)"
        )
    return ImageResult(
        name=name, status=Status.MISSING_REFERENCE, failed=not allow_new, message=message
    )


def missing_render(name: str, renders: Path) -> ImageResult:
    return ImageResult(
        name=name,
        status=Status.MISSING_RENDER,
        failed=True,
        message=f"reference has no render in {renders}: did a test stop producing it?",
    )


def verify(
    renders: Path, references: Path, config: Config, report_dir: Path, allow_new: bool
) -> list[ImageResult]:
    render_files, reference_files = list_pngs(renders), list_pngs(references)
    results = []
    for name in sorted(render_files.keys() | reference_files.keys()):
        if name not in reference_files:
            result = missing_reference(name, references, allow_new)
        elif name not in render_files:
            result = missing_render(name, renders)
        else:
            result = compare_pair(
                name, render_files[name], reference_files[name], config, report_dir
            )
        print(format_line(result), flush=True)
        results.append(result)
    return results


def format_line(r: ImageResult) -> str:
    """One greppable line per image; the metrics first, then why it failed."""
    parts = [f"{r.status}  {r.name}"]
    if r.metrics:
        m = r.metrics
        parts.append(
            f"mean {m.meanerror:.5f} max {m.maxerror:.4f} @ ({m.maxx},{m.maxy}) "
            f"psnr {m.psnr:.1f} dB  fail {m.fail_percent:.3f}%"
        )
    parts += [text for text in (r.message, r.warning) if text]
    if r.override_reason:
        parts.append(f"(override: {r.override_reason})")
    return "  ".join(parts)


def warn_stale_overrides(config: Config, renders: Path, references: Path) -> None:
    """A typo in an override name would otherwise silently keep the default limits."""
    known = list_pngs(renders).keys() | list_pngs(references).keys()
    for name in sorted(config.overrides.keys() - known):
        print(f"warning: thresholds override for {name} matches no render or reference")


# --------------------------------------------------------------------------
# Reports


def prepare_report_dir(report_dir: Path) -> None:
    """Old diff images from an earlier failure would read as current failures."""
    if report_dir.exists() and not report_dir.is_dir():
        raise UsageError(f"report path is not a folder: {report_dir}")
    try:
        report_dir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UsageError(f"cannot create report folder {report_dir}: {exc.strerror}") from exc
    for pattern in ("*.diff.png", "*.heat.png", "report.md", "report.json"):
        for stale in report_dir.glob(pattern):
            stale.unlink()


def md_cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def md_link(label: str, target: str | None) -> str:
    return f"[{label}](<{target}>)" if target else ""


def md_row(r: ImageResult) -> str:
    m = r.metrics
    numbers = (
        [
            f"{m.meanerror:.5f}",
            f"{m.maxerror:.4f}",
            f"({m.maxx},{m.maxy})",
            f"{m.psnr:.1f}",
            f"{m.rms_error:.5f}",
            f"{m.fail_percent:.3f}",
        ]
        if m
        else [""] * 6
    )
    notes = "; ".join(t for t in (r.message, r.warning) if t)
    if r.override_reason:
        notes = (
            f"{notes}; override: {r.override_reason}" if notes else f"override: {r.override_reason}"
        )
    cells = [
        md_cell(r.name),
        str(r.status),
        *numbers,
        md_link("diff", r.diff_image),
        md_link("heat", r.heat_image),
        md_cell(notes),
    ]
    return "| " + " | ".join(cells) + " |"


def render_markdown(results: Sequence[ImageResult], summary: str, config: Config) -> str:
    d = config.defaults
    lines = [
        "# Image verification report",
        "",
        f"**{summary}**",
        "",
        (
            f"Default thresholds: failthresh {d.failthresh:g}, failpercent {d.failpercent:g}%, "
            f"hardfail {d.hardfail:g}, warnthresh {d.warnthresh:g}, warnpercent {d.warnpercent:g}%."
        ),
        "",
        "| Image | Status | Mean | Max | Max at | PSNR (dB) | RMS | Fail % | Diff | Heat | Notes |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
        *(md_row(r) for r in results),
        "",
    ]
    return "\n".join(lines)


def write_reports(
    report_dir: Path,
    results: Sequence[ImageResult],
    counts: tuple[int, int],
    args: argparse.Namespace,
    config: Config,
) -> None:
    passed, failed = counts
    summary = f"{passed} passed, {failed} failed"
    payload = {
        "renders": str(args.renders),
        "references": str(args.references),
        "thresholds_file": str(args.thresholds),
        "defaults": dataclasses.asdict(config.defaults),
        "summary": {
            "passed": passed,
            "failed": failed,
            "new_allowed": sum(
                1 for r in results if r.status is Status.MISSING_REFERENCE and not r.failed
            ),
        },
        "missing_renders": [r.name for r in results if r.status is Status.MISSING_RENDER],
        "missing_references": [r.name for r in results if r.status is Status.MISSING_REFERENCE],
        "images": [r.to_json() for r in results],
    }
    (report_dir / "report.json").write_text(
        json.dumps(payload, indent=2, allow_nan=False) + "\n", encoding="utf-8"
    )
    (report_dir / "report.md").write_text(
        render_markdown(results, summary, config), encoding="utf-8"
    )


def count(results: Sequence[ImageResult]) -> tuple[int, int]:
    """New images let through by --allow-new were not verified, so they count as neither."""
    passed = sum(1 for r in results if r.status is Status.PASS)
    failed = sum(1 for r in results if r.failed)
    return passed, failed


def print_missing(results: Sequence[ImageResult]) -> None:
    for status, label in (
        (Status.MISSING_RENDER, "references with no render"),
        (Status.MISSING_REFERENCE, "renders with no reference"),
    ):
        names = [r.name for r in results if r.status is status]
        if names:
            print(f"{label} ({len(names)}): {', '.join(names)}")


def run_verify(args: argparse.Namespace) -> int:
    require_dir(args.renders, "renders")
    require_dir(args.references, "references")
    check_distinct(args.renders, args.references)
    config = load_config(args.thresholds)
    prepare_report_dir(args.report_dir)
    warn_stale_overrides(config, args.renders, args.references)
    results = verify(args.renders, args.references, config, args.report_dir, args.allow_new)
    passed, failed = count(results)
    write_reports(args.report_dir, results, (passed, failed), args, config)
    print_missing(results)
    print(f"report: {args.report_dir / 'report.md'}")
    print(f"{passed} passed, {failed} failed")
    return EXIT_FAILED if failed else EXIT_OK


# --------------------------------------------------------------------------
# --update


def update_reason(render_path: Path, reference_path: Path | None) -> str | None:
    """Copy only real pixel changes, so re-encoded but identical PNGs cause no churn."""
    if reference_path is None:
        return "new"
    render = read_image(render_path)
    try:
        reference = read_image(reference_path)
    except ImageError as exc:
        return f"replacing unreadable reference ({exc})"
    mismatch = shape_mismatch(render, reference)
    if mismatch:
        return f"changed: {mismatch}"
    metrics = measure(render, reference, Thresholds(failthresh=0.0, warnthresh=0.0))
    if metrics.maxerror > 0:
        return f"changed: max error {metrics.maxerror:.4g}, {metrics.fail_percent:.3f}% of pixels differ"
    return None


def run_update(args: argparse.Namespace) -> int:
    ci = os.environ.get("CI", "")
    if ci:
        raise UsageError(
            f"--update refuses to run when CI is set (CI={ci!r}): "
            "references must be updated deliberately on a developer machine and committed"
        )
    require_dir(args.renders, "renders")
    check_distinct(args.renders, args.references)
    args.references.mkdir(parents=True, exist_ok=True)
    renders, references = list_pngs(args.renders), list_pngs(args.references)
    copied: list[str] = []
    passed = failed = 0
    for name, render_path in renders.items():
        try:
            reason = update_reason(render_path, references.get(name))
        except ImageError as exc:
            print(f"{Status.ERROR}  {name}  {exc}; reference not touched")
            failed += 1
            continue
        if reason:
            shutil.copyfile(render_path, args.references / name)
            copied.append(name)
            print(f"UPDATED  {name}  {reason}")
        else:
            print(f"UNCHANGED  {name}")
        passed += 1
    for name in sorted(references.keys() - renders.keys()):
        print(
            f"{Status.MISSING_RENDER}  {name}  no render in {args.renders}; reference kept, delete it by hand if its test is gone"
        )
        failed += 1
    print(
        f"copied {len(copied)} image(s) to {args.references}"
        + (f": {', '.join(copied)}" if copied else "")
    )
    print(f"{passed} passed, {failed} failed")
    return EXIT_FAILED if failed else EXIT_OK


# --------------------------------------------------------------------------
# Entry point


def parse_args(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        description="Compare rendered PNGs with reference PNGs (OpenImageIO).",
        epilog="Exit codes: 0 all passed, 1 some image failed, 2 usage/configuration error.",
    )
    parser.add_argument(
        "--renders",
        type=Path,
        default=Path("target/test-run/images/golden"),
        help="folder with rendered *.png (not searched recursively; default: %(default)s)",
    )
    parser.add_argument(
        "--references",
        type=Path,
        default=Path("images/reference"),
        help="folder with reference *.png (default: %(default)s)",
    )
    parser.add_argument(
        "--thresholds",
        type=Path,
        default=Path("images/reference/thresholds.json"),
        help="thresholds JSON (default: %(default)s)",
    )
    parser.add_argument(
        "--report-dir",
        type=Path,
        default=Path("target/image-report"),
        help="where report.md, report.json and diff/heat images go (default: %(default)s)",
    )
    parser.add_argument(
        "--allow-new", action="store_true", help="do not fail renders that have no reference yet"
    )
    parser.add_argument(
        "--update",
        action="store_true",
        help="copy new or changed renders over the references (refused when CI is set)",
    )
    return parser.parse_args(argv)


def main(argv: Sequence[str] | None = None) -> int:
    args = parse_args(argv)
    try:
        return run_update(args) if args.update else run_verify(args)
    except UsageError as exc:
        print(f"verify_images: error: {exc}", file=sys.stderr)
        return EXIT_USAGE


if __name__ == "__main__":
    sys.exit(main())
