"""The lathejob fuzz kind (tests/fuzz/lathejob.py): whole lathe jobs that run to their end and
print exactly what rs274 prints, kept as a regression batch; and the generator's own promises."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent / "fuzz"))

import gen
import run

# Seeds whose programs run to the end in rs274 and come out identical (picked from 1-89 with
# `python tests/fuzz/run.py --kinds lathejob --count 89 --seed 1`); a difference here is a
# regression, or a change of the generator (then pick them again).
IDENTICAL = [3, 4, 7, 8, 9, 14, 17, 18, 23, 26, 27, 28, 32, 36, 38, 40, 46, 47, 48, 56, 57, 58,
             59, 65, 66, 68, 69, 70, 72, 74, 79, 83, 89]


def test_programs_carry_a_lathe_table_and_use_the_cycles() -> None:
    texts = [gen.generate("lathejob", seed) for seed in range(1, 41)]
    assert all(gen.table_of(text) is not None for text in texts)
    joined = "\n".join(texts).upper()
    for code in ("G70", "G71", "G72", "G76", "G33", "G96", "G41", "G42", "G42.1", "G7", "G20"):
        assert code in joined, code


@pytest.mark.skipif(shutil.which("rs274") is None, reason="LinuxCNC's rs274 is not installed")
def test_batch_against_rs274() -> None:
    cfg = run.Config(["rs274"], None, timeout=10.0)
    results = run.run_all(cfg, [("lathejob", seed) for seed in IDENTICAL], workers=1,
                          progress=False)
    differ = [f"lathejob seed {r.seed}: {r.hint}" for r in results if r.differs]
    assert not differ, "\n".join(differ)
    assert all(r.ref.rc == 0 for r in results)
