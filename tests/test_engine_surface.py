"""The engine dialect's surface of the soak (tests/fuzz/engined.py), a bounded slice for CI: random
setup sheets (legal ones at the ends of what a number holds, unknown keys, hostile TOML) and
engine programs (token soup of the dialect's words, mutated examples and golden cases), each run as
``ngc canon --dialect engine`` (text and JSON) and ``ngc check --dialect engine`` run them.  A run
ends in results that pass every check (segments and dwells finite and non-negative, the check's
times adding up, outputs without NaN) or in an ``NgcError``.  The soak runs the same by the
hundred thousand:

    python tests/fuzz/soak.py --api 0 --engine 200000 --seed 28 --jobs 2
"""

from __future__ import annotations

import random
import sys
from collections import Counter
from pathlib import Path

import pytest

from ngc.engine import EngineSegment, ModeChange
from ngc.errors import NgcError

sys.path.insert(0, str(Path(__file__).parent / "fuzz"))

import engined
import hostile

PROGRAMS = engined.corpus()
COUNT = 300


def test_random_setup_sheets_and_programs(tmp_path: Path) -> None:
    outcomes: Counter[str] = Counter()
    for index in range(COUNT):
        rng = random.Random(f"28/engine/{index}")
        _, data = engined.program(rng, PROGRAMS)
        folder = tmp_path / str(index)
        folder.mkdir()
        try:
            with hostile.time_limit(10.0):
                outcomes[engined.soak_run(rng, data, folder, 2000, {})] += 1
        except NgcError:
            outcomes["NgcError"] += 1
    assert outcomes["ok"] >= COUNT // 20  # enough programs run to their end to be checked
    assert outcomes["ok, setup refused"] > 0


def test_the_corpus_holds_the_examples_and_the_golden_cases() -> None:
    assert len(PROGRAMS) > 60
    assert b"move PZ 0 360 0.5 0 PZ 0 3960 0.125 0\n" in PROGRAMS  # the seed's first example


def test_generated_sheets_are_mostly_legal(tmp_path: Path) -> None:
    refused = 0
    for index in range(200):
        path = tmp_path / f"{index}.toml"
        path.write_bytes(engined.setup_sheet(random.Random(index)))
        refused += engined.load_setup(path)[1] == "setup refused"
    assert 0 < refused < 60


def test_the_checks_catch_what_they_are_for() -> None:
    with pytest.raises(engined.EngineCheckError, match="segment duration inf"):
        engined.check_op(EngineSegment(3, float("inf"), {"X": (0.0, 1.0, 2.0, 3.0)}, "rapid"))
    with pytest.raises(engined.EngineCheckError, match="segment position not finite"):
        engined.check_op(EngineSegment(3, 1.0, {"X": (0.0, float("nan"), 2.0, 3.0)}, "rapid"))
    with pytest.raises(engined.EngineCheckError, match="RUN holds nan"):
        engined.check_op(ModeChange(2, "RUN", {"X": float("nan")}))
    with pytest.raises(engined.EngineCheckError, match="canon's JSON holds NaN"):
        engined._strict('{"a": NaN}\n', "canon's JSON")
