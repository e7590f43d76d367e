"""The ``ngc time`` surface of the soak (tests/fuzz/timed.py), a bounded slice for CI: random legal
machines (TOML, INI, both; values at the ends of their ranges) and programs, each timed through the
API and again with a trajectory.  A run ends in a result that passes every check (times finite and
non-negative, parts adding up to the total, rows finite with t non-decreasing, reports without
NaN) or in an ``NgcError``.  The soak runs the same by the ten thousand:

    python tests/fuzz/soak.py --api 0 --time 20000 --time-cli 1000 --seed 28
"""

from __future__ import annotations

import random
import sys
from collections import Counter
from pathlib import Path

import pytest

from ngc.errors import NgcError

sys.path.insert(0, str(Path(__file__).parent / "fuzz"))

import hostile
import timed

CORPUS = hostile.golden_corpus()
TIMING = timed.timing_corpus()
COUNT = 150


def test_random_machines_and_programs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    outcomes: Counter[str] = Counter()
    for index in range(COUNT):
        rng = random.Random(f"28/time/{index}")
        _, data = timed.program(rng, CORPUS, TIMING)
        folder = tmp_path / f"m{index}"
        folder.mkdir()
        files = timed.machine_files(rng, folder)
        try:
            with hostile.time_limit(10.0):
                outcomes[timed.run_api(hostile.decode(data, "utf-8"), files, rng, 2000)] += 1
        except NgcError:
            outcomes["NgcError"] += 1
    assert outcomes["ok"] >= COUNT // 10  # enough programs get through to be checked
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith("m")) == []


def test_every_generated_machine_loads(tmp_path: Path) -> None:
    for index in range(300):
        rng = random.Random(f"machines/{index}")
        folder = tmp_path / str(index)
        folder.mkdir()
        timed.load(timed.machine_files(rng, folder))  # legal: no NgcConfigError


def test_the_checks_catch_what_they_are_for() -> None:
    with pytest.raises(timed.TimeCheckError, match="total time nan"):
        timed.check_times(float("nan"), 0.0, {}, 0, 0.001, 0.0)
    with pytest.raises(timed.TimeCheckError, match="by_kind adds up to"):
        timed.check_times(1.0, 1.0, {"by_kind": [0.5]}, 1, 0.001, 0.0)
    rows = timed.Rows()
    rows.write("t,x,y,z,velocity,line\n0.0,0,0,0,0,1\n")
    with pytest.raises(timed.TimeCheckError, match=r"t -1\.0 after 0\.0"):
        rows.write("-1.0,0,0,0,0,1\n")
    with pytest.raises(timed.TimeCheckError, match="not finite"):
        rows.write("1.0,nan,0,0,0,1\n")
