"""Random engine programs: no crash but an NgcError, segments that join, finite times; and
random programs of the codes both dialects share give the same canon under both."""

from __future__ import annotations

import math
import random

import pytest

from ngc.engine import Dwell, Engine, EngineSegment, ModeChange, Setup, run
from ngc.engine.names import NAMES
from ngc.engine.setup import Fixture
from ngc.errors import NgcError
from test_engine_vs_linuxcnc import _close, engine, linuxcnc

SETUP = Setup(fixtures=(Fixture(), Fixture(offsets=(5.0, -3.0, 1.0, 0, 0, 0, 0, 0, 0)),
                        Fixture(offsets=(0.0, 0.0, -2.0, 0, 0, 0, 0, 0, 0), tool_axis=(0, 1.0)),
                        *(Fixture(),) * 4), tool=1, lengths={1: 7.5})


def _num(r: random.Random) -> str:
    return r.choice(["0", "1", "-1", "2.5", "0.125", f"{r.uniform(-5, 5):.3f}", "[1 + 2]", "#1"])


def _line(r: random.Random) -> str:
    kind = r.random()
    axes = "".join(f" {a} {_num(r)}" for a in r.sample("XYZABC", r.randint(1, 3)))
    if kind < 0.25:
        return r.choice(["G0", "G1", "move", "rapid", "feed", "G31"]) + axes + \
            r.choice(["", f" F {r.uniform(1, 50):.2f}"])
    if kind < 0.35:
        return r.choice(["G0", "G1", "move"]) + r.choice(
            [f" PZ 0 {r.choice([90, 360, -720, 45])} {r.uniform(0.1, 3):.2f} {_num(r)}",
             f" VX {_num(r)} {_num(r)} {_num(r)}", f" PZ {_num(r)}", f" Y {_num(r)} {_num(r)}"])
    if kind < 0.5:
        return r.choice(["G2", "G3"]) + r.choice(
            [f" X {_num(r)} Y {_num(r)} I {_num(r)} J {_num(r)}", f" X {_num(r)} R {_num(r)}",
             f" X {_num(r)} Y {_num(r)} R {_num(r)} Z {_num(r)}", " I 1"]) + " F 10"
    if kind < 0.6:
        return r.choice(["G81", "G82", "G83", "G73", "G85", "G86", "G89"]) + axes + r.choice(
            ["", " R 2", " R 1 Q 0.5 P 0.1", " R -1 Q 1"]) + " F 5"
    if kind < 0.7:
        return r.choice(["G16 X 0 Y 0", "G15", "G16", "G100 X 20", "G100 X 0 A -10",
                         "G4 P 0.5", "dwell 1", "G80", "G92 X 1", "G103 PZ 0 1", "G69",
                         "G101 VZ 30 VX", "G102 VX X 1 Y 1", "G107 VX", "G108 VX 1"])
    code = r.choice(sorted(NAMES))
    return r.choice([f"G{code}", f"G{code}{axes}", r.choice(NAMES[code]).replace("(", "")
                     .replace(")", "") + axes])


@pytest.mark.parametrize("seed", range(60))
def test_random_engine_programs(seed: int) -> None:
    r = random.Random(seed)
    lines = ["#1 = 1.5"] + [_line(r) for _ in range(25)]
    text = "\n".join(lines)
    for program in (text, "G20\n" + text, "G91\nG54\nG43\n" + text, "G61\nG18\n" + text):
        pos: dict[str, float] = {}
        try:
            for op in run(program, Engine(setup=SETUP)):
                if isinstance(op, EngineSegment):
                    assert math.isfinite(op.duration) and op.duration >= 0.0
                    for a, c in op.axes.items():
                        assert all(math.isfinite(v) for v in c)
                        if a in pos:
                            assert math.isclose(c[0], pos[a], abs_tol=1e-9), (program, op)
                        pos[a] = c[3]
                elif isinstance(op, Dwell):
                    assert op.seconds >= 0.0
                elif isinstance(op, ModeChange) and op.name in ("UNITS", "SET_POSITION"):
                    pos = {}  # shown in other units, or preset: no longer comparable
        except NgcError as exc:
            assert exc.line is not None and exc.message


def _shared_line(r: random.Random) -> str:
    kind = r.random()
    axes = "".join(f" {a}{r.uniform(-10, 10):.4f}" for a in r.sample("XYZ", r.randint(1, 3)))
    if kind < 0.45:
        return "G0" + axes
    if kind < 0.8:
        return "G1" + axes + r.choice(["", f" F{r.uniform(1, 500):.1f}"])
    if kind < 0.88:
        return f"G4 P{r.uniform(0, 3):.2f}"
    return r.choice(["G17", "G18", "G19", "G90", "G91"])


@pytest.mark.parametrize("seed", range(60))
def test_shared_codes_random(seed: int) -> None:
    r = random.Random(1000 + seed)
    program = "%\nG21 F100\n" + "\n".join(_shared_line(r) for _ in range(30)) + "\n%\n"
    assert _close(engine(program), linuxcnc(program)), program
