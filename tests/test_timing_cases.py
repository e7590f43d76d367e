"""The planner's cycle time against LinuxCNC's, program by program.

Two sets of programs, each with the cycle time LinuxCNC 2.9's own trajectory planner took to run
it (``motion_time``, measured with the ``lcnc-timing`` tool on the machine of
``../shared/timing/README.md``):

* ``tests/timing/cases``: programs made by ``tests/timing/generate.py`` (fixed seeds), measured by
  ``tests/timing/measure.py`` into ``tests/timing/cases/reference.json``;
* ``tests/timing/features``: programs made by ``tests/timing/features.py``, each a behaviour shop
  programs lean on (feeds on unit-switching lines, no G61/G64, adaptive clearing with feed
  changes, thread milling, coves, NURBS), measured the same way;
* ``tests/timing/joins``: small programs of joins with arcs and helices and of short lines between
  blends, the measurements the planner's rules for them were found from (``docs/planner.md``);
* ``../shared/timing``: the reference set beside the repository (skipped where it is absent).

Each program must come within 1 % of LinuxCNC.  A program known to be further off is marked
``xfail`` (not strict) in ``OVER_CASES`` / ``OVER_SHARED``, so the suite passes while the figure
stays visible; the summary tests print the table of both sets.
"""

from __future__ import annotations

import functools
import importlib.util
import json
import statistics
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from ngc.planner.timing import time_text

HERE = Path(__file__).resolve().parent
CASES = HERE / "timing" / "cases"
JOINS = HERE / "timing" / "joins"
FEATURES = HERE / "timing" / "features"
SHARED = HERE.parents[1] / "shared" / "timing"
TOLERANCE = 0.01  # per program, relative
MEDIAN_TOLERANCE = 0.005

# Programs whose estimate is currently more than 1 % off (relative error, for the record).
OVER_CASES: dict[str, float] = {
}
OVER_SHARED: dict[str, float] = {}
OVER_FEATURES: dict[str, float] = {}
OVER_JOINS: dict[str, float] = {
    # before any G61/G64 the first corners of a run beside an arc come out either way on LinuxCNC:
    # runs of 0.863, 0.863, 0.911 s and 0.808, 0.808, 0.866 s; ngc takes the 0.001 inch tolerance
    # later corners have (0.911 and 0.866 s)
    "61_line_quarter_into_63_no_mode.ngc": 0.0364,
    "62_line_quarter_away_45_no_mode.ngc": 0.0467,
}


def _reference(folder: Path) -> list[dict[str, Any]]:
    path = folder / "reference.json"
    if not path.exists():
        return []
    programs: list[dict[str, Any]] = json.loads(path.read_text())["programs"]
    return programs


@functools.cache
def estimate(path: Path) -> float:
    return time_text(path.read_text()).total_s


def _error(folder: Path, entry: dict[str, Any]) -> tuple[float, float]:
    est = estimate(folder / entry["file"])
    return est, (est - entry["motion_time"]) / entry["motion_time"]


def _params(folder: Path, over: dict[str, float]) -> list[Any]:
    out = []
    for entry in _reference(folder):
        marks = []
        if entry["file"] in over:
            marks.append(pytest.mark.xfail(strict=False, reason=f"known: {100 * over[entry['file']]:+.2f} %"))
        out.append(pytest.param(entry, marks=marks, id=entry["file"].removesuffix(".ngc")))
    return out


def _table(folder: Path, what: dict[str, str]) -> str:
    rows = []
    errors = []
    for entry in _reference(folder):
        est, err = _error(folder, entry)
        errors.append(abs(err))
        rows.append(f"{entry['file']:30s} {what.get(entry['file'], ''):62.62s} {entry['motion_time']:9.3f} "
                    f"{est:9.3f} {100 * err:+7.2f}{' *' if abs(err) > TOLERANCE else ''}")
    head = f"{'program':30s} {'exercises':62s} {'LinuxCNC':>9s} {'ngc':>9s} {'error %':>7s}"
    foot = (f"{len(rows)} programs, median |error| {100 * statistics.median(errors):.2f} %, "
            f"max {100 * max(errors):.2f} %, over 1 %: {sum(e > TOLERANCE for e in errors)}")
    return "\n".join([f"\n{folder}:", head, *rows, foot])


@functools.cache
def _generator(name: str = "generate") -> Any:
    spec = importlib.util.spec_from_file_location(f"timing_{name}", HERE / "timing" / f"{name}.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


# -- the sets -------------------------------------------------------------------------------------


def _what_cases() -> dict[str, str]:
    return {c.file: c.what for c in _generator().CASES}


def _what_features() -> dict[str, str]:
    return {name: what for name, (what, _) in _generator("features").files().items()}


def _what_shared() -> dict[str, str]:
    return {e["file"]: ", ".join(e.get("kinds", [])) for e in _reference(SHARED)}


def _what_joins() -> dict[str, str]:
    return {p.name: p.read_text().splitlines()[0].strip("()").lower() for p in JOINS.glob("*.ngc")}


# name: (folder, programs known to be over 1 %, what each program exercises)
SETS: dict[str, tuple[Path, dict[str, float], Callable[[], dict[str, str]]]] = {
    "cases": (CASES, OVER_CASES, _what_cases),
    "features": (FEATURES, OVER_FEATURES, _what_features),
    "joins": (JOINS, OVER_JOINS, _what_joins),
    "shared": (SHARED, OVER_SHARED, _what_shared),  # no programs where ../shared is absent
}


def test_cases_are_what_the_generator_makes() -> None:
    made = _generator().generate()
    files = {p.name: p.read_text() for p in CASES.glob("[0-9]*.ngc")}
    assert made == files


def test_features_are_what_the_generator_makes() -> None:
    made = _generator("features").generate()
    files = {p.name: p.read_text() for p in FEATURES.glob("[0-9]*.ngc")}
    assert made == files


@pytest.mark.parametrize("folder", [CASES, FEATURES, JOINS], ids=["cases", "features", "joins"])
def test_every_program_is_measured(folder: Path) -> None:
    measured = {e["file"] for e in _reference(folder)}
    assert measured == {p.name for p in folder.glob("[0-9]*.ngc")}


@pytest.mark.parametrize(("folder", "entry"), [
    pytest.param(folder, *p.values, marks=p.marks, id=f"{name}/{p.id}")
    for name, (folder, over, _) in SETS.items() for p in _params(folder, over)])
def test_within_1_percent(folder: Path, entry: dict[str, Any]) -> None:
    est, err = _error(folder, entry)
    assert abs(err) <= TOLERANCE, f"{entry['file']}: ngc {est:.3f} s, LinuxCNC {entry['motion_time']:.3f} s"


@pytest.mark.parametrize("name", sorted(SETS))
def test_median_within_half_a_percent(name: str) -> None:
    folder = SETS[name][0]
    if not _reference(folder):
        pytest.skip(f"{folder} is absent")
    errors = [abs(_error(folder, e)[1]) for e in _reference(folder)]
    assert statistics.median(errors) <= MEDIAN_TOLERANCE, [f"{100 * e:.2f}" for e in errors]


@pytest.mark.parametrize("name", sorted(SETS))
def test_summary(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    folder, _, what = SETS[name]
    if not _reference(folder):
        pytest.skip(f"{folder} is absent")
    with capsys.disabled():
        print(_table(folder, what()))
