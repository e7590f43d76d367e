"""The toolpath layer: moves in machine coordinates, worked out by hand from the offset rules of
``coordinates.adoc`` (machine = rotate(program + G92) + G5x + tool length offset, in mm), and
the same point in program coordinates as canon gives it."""

from __future__ import annotations

import math

import pytest

from ngc.interp.interpreter import Interpreter
from ngc.toolpath.moves import Event, Move, MoveList


def moves(text: str, *, inch_machine: bool = False) -> list[Move]:
    out: list[Move | Event] = []
    reader = MoveList(out.append, file="t.ngc", inch_machine=inch_machine)
    interp = Interpreter(reader.toolpath)
    interp.startup()
    interp.run(text.splitlines(), file="t.ngc")
    reader.toolpath.flush()
    return [m for m in out if isinstance(m, Move)]


def events(text: str) -> list[Event]:
    out: list[Move | Event] = []
    reader = MoveList(out.append)
    interp = Interpreter(reader.toolpath)
    interp.startup()
    interp.run(text.splitlines())
    return [e for e in out if isinstance(e, Event)]


def xyz(p: tuple[float, ...]) -> tuple[float, float, float]:
    return (round(p[0], 9) + 0.0, round(p[1], 9) + 0.0, round(p[2], 9) + 0.0)


def test_plain_moves_are_their_program_points() -> None:
    m = moves("G21 G0 X1 Y2 Z3\nG1 X4 F100\nM2")
    assert [x.kind for x in m] == ["rapid", "feed"]
    assert xyz(m[0].start) == (0.0, 0.0, 0.0)
    assert xyz(m[0].end) == (1.0, 2.0, 3.0) == xyz(m[0].prog_end)
    assert xyz(m[1].start) == (1.0, 2.0, 3.0)
    assert m[1].line == 2 and m[1].file == "t.ngc"
    assert m[1].feed == 100.0


def test_work_offset() -> None:
    m = moves("G21 G10 L2 P1 X10 Y20 Z-5\nG54 G0 X1 Y2 Z3\nM2")
    assert xyz(m[0].end) == (11.0, 22.0, -2.0)
    assert xyz(m[0].prog_end) == (1.0, 2.0, 3.0)


def test_g92_offset_and_g52() -> None:
    m = moves("G21 G0 X5 Y5\nG92 X0 Y0\nG1 X1 Y1 F100\nG92.1\nG52 X10\nG0 X1 Y0\nM2")
    assert xyz(m[1].start) == (5.0, 5.0, 0.0)
    assert xyz(m[1].prog_start) == (0.0, 0.0, 0.0)  # the point G92 named
    assert xyz(m[1].end) == (6.0, 6.0, 0.0)
    assert xyz(m[2].end) == (11.0, 0.0, 0.0)


def test_inch_program_in_mm() -> None:
    m = moves("G20 G0 X1 Y-2\nG21 G0 X10\nM2")
    assert xyz(m[0].end) == (25.4, -50.8, 0.0)
    assert xyz(m[0].prog_end) == (1.0, -2.0, 0.0)
    assert xyz(m[1].start) == (25.4, -50.8, 0.0)
    assert xyz(m[1].prog_start) == (25.4, -50.8, 0.0)  # the same point, now in mm
    assert xyz(m[1].end) == (10.0, -50.8, 0.0)


def test_inch_machine() -> None:
    m = moves("G21 G0 X25.4\nM2", inch_machine=True)
    assert xyz(m[0].end) == (1.0, 0.0, 0.0)


def test_offset_keeps_the_units_it_was_set_in() -> None:
    # 1 inch of G54 offset, then a mm program: the offset stays 25.4 mm
    m = moves("G20 G10 L2 P1 X1\nG21 G54 G0 X10\nM2")
    assert xyz(m[0].end) == (35.4, 0.0, 0.0)


def test_tool_length_offset_is_in_the_machine_point() -> None:
    # the default table's T1 has Z 0.511 (inch, as rs274's table is read in the program's units)
    m = moves("G20 T1 M6 G43 H1\nG0 Z0\nG49\nG0 Z0\nM2")
    assert m[0].tool == 1
    assert m[0].tool_offset[2] == pytest.approx(0.511 * 25.4)
    assert m[0].end[2] == pytest.approx(0.511 * 25.4)
    assert m[0].prog_end[2] == 0.0
    assert m[1].end[2] == pytest.approx(0.0)


def test_rotation() -> None:
    m = moves("G21 G10 L2 P1 X10 R90\nG54 G0 X1 Y0\nG1 Y2 F100\nM2")
    assert xyz(m[0].end) == (10.0, 1.0, 0.0)
    assert xyz(m[1].end) == (8.0, 1.0, 0.0)


def test_rotation_with_g92_rotates_the_g92_offset_too() -> None:
    # G92 is applied before the rotation (coordinates.adoc: G92 offsets the rotated system)
    m = moves("G21 G0 X1 Y0\nG92 X0 Y0\nG10 L2 P1 R90\nG54 G0 X1 Y0\nM2")
    # program (1, 0) + G92 (1, 0) = (2, 0), turned 90 degrees: (0, 2)
    assert xyz(m[1].end) == (0.0, 2.0, 0.0)


def test_arc_in_xz_under_rotation_turns_its_normal() -> None:
    m = moves("G21 G10 L2 P1 R90\nG54 G18 G0 X0 Z0\nG2 X2 Z0 I1 K0 F100\nM2")
    arc = m[1]
    assert arc.kind == "arc" and arc.plane == "XZ"
    assert arc.normal is not None and arc.centre is not None
    assert xyz(arc.normal) == (-1.0, 0.0, 0.0)  # Y turned 90 degrees about Z
    assert xyz(arc.centre) == (0.0, 1.0, 0.0)
    assert xyz(arc.end) == (0.0, 2.0, 0.0)
    assert arc.turns == -1


def test_every_combination_in_inch() -> None:
    text = ("G20 G10 L2 P2 X1 Y2 Z3 R30\nG55 G0 X0.5 Y0.25\nG92 X0 Y0\nT2 M6 G43\n"
            "G1 X1 Y1 Z-0.1 F10\nM2")
    m = moves(text)
    last = m[-1]
    s = 25.4
    x, y = 0.5 * s + 1 * s, 0.25 * s + 1 * s  # program + G92 (the G92 offset is 0.5, 0.25)
    c, sn = math.cos(math.radians(30)), math.sin(math.radians(30))
    want = (x * c - y * sn + 1 * s, x * sn + y * c + 2 * s, -0.1 * s + 3 * s + 0.1 * s)
    assert last.end[:3] == pytest.approx(want)
    assert last.prog_end[:3] == pytest.approx((1.0, 1.0, -0.1))
    assert last.feed == pytest.approx(10 * s)


def test_kinds() -> None:
    text = ("G21 G0 X0 Y0 Z5\nG38.3 Z-1 F100\nS100 M3\nG33 Z-5 K1\nG0 Z5\nG33.1 Z-3 K1\n"
            "G5 X10 Y10 I5 J0 P0 Q5\nM2")
    kinds = [m.kind for m in moves(text)]
    assert kinds == ["rapid", "probe", "sync", "rapid", "tap", "nurbs"]


def test_tap_goes_down_and_back() -> None:
    m = moves("G21 G0 Z5\nS100 M3\nG33.1 Z-3 K1\nG0 X1\nM2")
    tap = m[1]
    assert xyz(tap.start) == (0.0, 0.0, 5.0) and xyz(tap.end) == (0.0, 0.0, -3.0)
    assert xyz(m[2].start) == (0.0, 0.0, 5.0)


def test_events() -> None:
    got = [e for e in events("T1 M6\nG4 P1\nM0\nM2") if e.kind not in ("spindle", "coolant")]
    assert [e.kind for e in got] == ["tool change", "dwell", "stop", "end"]
    assert got[1].line == 2
