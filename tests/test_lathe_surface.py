"""The lathe surface of the soak (tests/fuzz/lathed.py), a bounded slice for CI: lathe jobs and
G71/G72 profiles from the fuzzers' generators, as generated and mutated (numbers made extreme,
lines dropped or duplicated, bytes changed), with their tool tables, run as ``ngc check``,
``ngc canon`` and ``ngc time`` (with a trajectory) run them, on random lathes.  A run ends in
results that pass every check or in an ``NgcError``.  The soak runs the same by the ten
thousand, and its own machinery (workers, counts, saved inputs) is run here on a few of each
surface:

    python tests/fuzz/soak.py --api 0 --lathe 50000 --seed 28 --jobs 2
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
import lathed
import soak

COUNT = 24


def test_random_lathe_programs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    outcomes: Counter[str] = Counter()
    for index in range(COUNT):
        rng = random.Random(f"28/lathe/{index}")
        _, data = lathed.program(rng)
        folder = tmp_path / f"m{index}"
        folder.mkdir()
        try:
            with hostile.time_limit(10.0):
                outcomes[lathed.soak_run(rng, data, folder, 2000, {})] += 1
        except NgcError:
            outcomes["NgcError"] += 1
    assert outcomes["ok"] >= COUNT // 8
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith("m")) == []


def test_mutations_make_numbers_extreme_and_move_lines() -> None:
    rng = random.Random(1)
    text = "G0 X10 Z2\nG1 Z-5 F0.2\nM2\n"
    changed = {lathed._extreme_numbers(rng, text) for _ in range(50)}
    assert any("[0/0]" in t or "9" * 400 in t or "0.0000000001" in t for t in changed)
    assert any(len(lathed._lines_changed(rng, text).splitlines()) != 3 for _ in range(10))


def test_a_lathe_is_x_and_z(tmp_path: Path) -> None:
    for index in range(100):
        files = lathed.write_inputs(random.Random(index), b";tooltable: T1 P1 D0.4 Q2\nM2\n",
                                    tmp_path)
        text = files["toml"].read_text()
        assert "[axes.X]" in text and "[axes.Z]" in text
        assert "tools" in files  # (its numbers made extreme now and then)


def test_the_soak_runs_both_surfaces(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # (the workers fork from this process and start with its peak RSS, which the tests before
    # this one set: the RSS limit is the soak's own business, not this test's)
    code = soak.main(["--api", "0", "--engine", "60", "--lathe", "4", "--seed", "28", "--jobs",
                      "1", "-q", "--rss-limit-mb", "100000", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 0, out
    assert "60 engine inputs, 4 lathe inputs" in out
    assert "failures: none" in out
