"""The toolpath against rs274's own transcripts: every golden case's recorded canon (rs274's
output) is fed to the toolpath, and each move's machine point is worked out again here from the
offset rules of ``coordinates.adoc`` (machine = rotate(program + G92) + G5x + tool length
offset, lengths in mm), written another way (complex numbers for the rotation)."""

from __future__ import annotations

import cmath
import math
import re
from pathlib import Path

import pytest

from ngc.canon import ops
from ngc.toolpath.frame import Pos
from ngc.toolpath.tracker import ArcMove, Toolpath

CASES = Path(__file__).parent / "golden" / "cases"
CALL = re.compile(r"^(?: *\d+ )?N\S* ([A-Z_0-9]+)\((.*)\)$")
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")

PARSED = {
    "STRAIGHT_TRAVERSE": ops.StraightTraverse, "STRAIGHT_FEED": ops.StraightFeed,
    "ARC_FEED": ops.ArcFeed, "SET_G5X_OFFSET": ops.SetG5xOffset,
    "SET_G92_OFFSET": ops.SetG92Offset, "SET_XY_ROTATION": ops.SetXYRotation,
    "USE_TOOL_LENGTH_OFFSET": ops.UseToolLengthOffset,
}


def parse(text: str) -> list[ops.Op]:
    """The calls of a transcript the toolpath follows, as ops."""
    out: list[ops.Op] = []
    for line in text.splitlines():
        m = CALL.match(line)
        if m is None:
            continue
        name, args = m.groups()
        if name == "USE_LENGTH_UNITS":
            out.append(ops.UseLengthUnits(args))
        elif name == "SELECT_PLANE":
            out.append(ops.SelectPlane(args))
        elif name in PARSED:
            values = [float(v) for v in NUMBER.findall(args)]
            kind = PARSED[name]
            if kind is ops.SetG5xOffset:
                values[0] = int(values[0])
            if kind is ops.ArcFeed:
                values[4] = int(values[4])
            out.append(kind(*values))
    return out


class Oracle:
    """Follows the same calls and says where each move ends, its own way."""

    def __init__(self) -> None:
        self.scale = 1.0
        self.g5x = self.g92 = self.tlo = (0.0,) * 6
        self.turn = 1 + 0j

    def follow(self, op: ops.Op) -> None:
        if isinstance(op, ops.UseLengthUnits):
            self.scale = 25.4 if op.units == "CANON_UNITS_INCHES" else 1.0
        elif isinstance(op, ops.SetG5xOffset):
            self.g5x = tuple(v * (self.scale if i < 3 else 1.0)
                             for i, v in enumerate((op.x, op.y, op.z, op.a, op.b, op.c)))
        elif isinstance(op, ops.SetG92Offset):
            self.g92 = tuple(v * (self.scale if i < 3 else 1.0) for i, v in enumerate(op))
        elif isinstance(op, ops.UseToolLengthOffset):
            self.tlo = tuple(v * (self.scale if i < 3 else 1.0) for i, v in enumerate(op[:6]))
        elif isinstance(op, ops.SetXYRotation):
            self.turn = cmath.exp(1j * math.radians(op.degrees))

    def machine(self, p: tuple[float, ...]) -> tuple[float, ...]:
        s = self.scale
        xy = complex(p[0] * s + self.g92[0], p[1] * s + self.g92[1]) * self.turn
        xy += complex(self.g5x[0] + self.tlo[0], self.g5x[1] + self.tlo[1])
        z = p[2] * s + self.g92[2] + self.g5x[2] + self.tlo[2]
        rest = tuple(p[3 + i] + self.g92[3 + i] + self.g5x[3 + i] + self.tlo[3 + i]
                     for i in range(3))
        return (xy.real, xy.imag, z, *rest)


class Ends:
    """A toolpath reader keeping each move's machine and program end."""

    def __init__(self) -> None:
        self.ends: list[tuple[Pos, Pos]] = []
        self.toolpath = Toolpath(self)

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self.ends.append((end, self.toolpath.prog_end))

    def arc(self, arc: ArcMove, line: int) -> None:
        self.ends.append((arc.end, self.toolpath.prog_end))

    def nurbs(self, *args: object) -> None: ...

    def tap(self, *args: object) -> None: ...

    def other(self, op: ops.Op, line: int) -> None: ...

    def finish(self) -> None: ...


PLANE_OF = {"CANON_PLANE_XY": (0, 1, 2), "CANON_PLANE_YZ": (1, 2, 0),
            "CANON_PLANE_XZ": (2, 0, 1)}


def _framed_cases() -> list[Path]:
    """The golden cases whose transcripts move the frame (offsets, rotation, units, tools)."""
    found = []
    for out in sorted(CASES.glob("*.out")):
        text = out.read_text(errors="replace")
        if re.search(r"SET_XY_ROTATION\((?!0\.0000\))|SET_G92_OFFSET\((?!0\.0000, 0\.0000, "
                     r"0\.0000)|CANON_UNITS_INCHES|USE_TOOL_LENGTH_OFFSET\((?!0\.0000 0\.0000 "
                     r"0\.0000,)|SET_G5X_OFFSET\(\d, (?!0\.0000, 0\.0000, 0\.0000,)", text):
            found.append(out)
    return found


FRAMED = _framed_cases()


def test_there_are_framed_cases() -> None:
    assert len(FRAMED) >= 100


@pytest.mark.parametrize("out", FRAMED, ids=[p.stem for p in FRAMED])
def test_machine_points_follow_the_offset_rules(out: Path) -> None:
    calls = parse(out.read_text(errors="replace"))
    reader = Ends()
    oracle = Oracle()
    plane = (0, 1, 2)
    expected: list[tuple[tuple[float, ...], tuple[float, ...]]] = []
    for op in calls:
        reader.toolpath.emit(op, "", 0)
        oracle.follow(op)
        if isinstance(op, ops.SelectPlane):
            plane = PLANE_OF.get(op.plane, plane)
        if isinstance(op, (ops.StraightTraverse, ops.StraightFeed)):
            prog = tuple(op)
        elif isinstance(op, ops.ArcFeed):
            p = [0.0] * 6
            p[plane[0]], p[plane[1]], p[plane[2]] = op.first_end, op.second_end, op.axis_end_point
            p[3:] = [op.a, op.b, op.c]
            prog = tuple(p)
        else:
            continue
        expected.append((oracle.machine(prog), prog))
    assert len(reader.ends) == len(expected)
    for (machine, prog), (want, want_prog) in zip(reader.ends, expected, strict=True):
        assert prog == want_prog
        assert machine == pytest.approx(want, abs=1e-9, rel=1e-12)
