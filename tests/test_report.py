"""The motion summary (``ngc.commands.check``): arc geometry in every plane, units and offsets followed
from canon, and the doctests of the public functions."""

from __future__ import annotations

import doctest
import math
from pathlib import Path

import pytest

import ngc
from ngc.canon.jsonl import ListSink
from ngc.commands import check as report
from ngc.commands.check import Arc, Summary, check_file, summarize


def summary_of(program: str) -> Summary:
    """Run a program through the interpreter and summarize its canon."""
    sink = ListSink()
    ngc.interpret(program, sink)
    return summarize(op for op, _, _ in sink.ops)


def box(s: Summary) -> list[float]:
    assert s.extents is not None
    return [round(v, 4) for v in s.extents.low + s.extents.high]


@pytest.mark.parametrize("module", [ngc, report], ids=lambda m: m.__name__)
def test_doctests(module: object) -> None:
    failed, attempted = doctest.testmod(module)  # type: ignore[arg-type]
    assert attempted > 0
    assert failed == 0


# -- arc geometry ---------------------------------------------------------------------------------
def test_full_circle_when_start_is_end() -> None:
    circle = Arc(start=(2.0, 0.0, 0.0), end=(2.0, 0.0, 0.0), center=(0.0, 0.0), rotation=-1)
    assert circle.sweep() == pytest.approx(2 * math.pi)
    assert circle.length() == pytest.approx(4 * math.pi)
    assert len(circle.extremes()) == 4


def test_turns_and_helix_rise() -> None:
    helix = Arc(start=(1.0, 0.0, 0.0), end=(1.0, 0.0, -3.0), center=(0.0, 0.0), rotation=3)
    assert helix.sweep() == pytest.approx(6 * math.pi)
    assert helix.length() == pytest.approx(math.hypot(6 * math.pi, 3.0))


def test_clockwise_quarter_goes_the_short_way_round() -> None:
    cw = Arc(start=(0.0, 1.0, 0.0), end=(1.0, 0.0, 0.0), center=(0.0, 0.0), rotation=-1)
    ccw = Arc(start=(0.0, 1.0, 0.0), end=(1.0, 0.0, 0.0), center=(0.0, 0.0), rotation=1)
    assert cw.sweep() == pytest.approx(math.pi / 2)
    assert ccw.sweep() == pytest.approx(3 * math.pi / 2)
    assert [tuple(round(v, 9) for v in p) for p in cw.extremes()] == [
        (1.0, 0.0, 0.0),
        (0.0, 1.0, 0.0),
    ]
    assert len(ccw.extremes()) == 4  # from 90° (the start) through 180° and 270° to 0° (the end)


def test_spiral_length_uses_mean_radius() -> None:
    spiral = Arc(start=(1.0, 0.0, 0.0), end=(-1.002, 0.0, 0.0), center=(0.0, 0.0), rotation=1)
    assert spiral.length() == pytest.approx(math.pi * 1.001)


# -- planes, from the interpreter's canon ----------------------------------------------------------
def test_xy_circle_extents() -> None:
    s = summary_of("G21 F100\nG1 X10\nG3 X10 Y0 I-5 J0\nM2\n")
    assert (s.feeds, s.arcs) == (1, 1)
    assert s.feed_length == pytest.approx(10 + 10 * math.pi)
    assert box(s) == [0.0, -5.0, 0.0, 10.0, 5.0, 0.0]


def test_xz_plane_helix() -> None:
    """G18: ARC_FEED's (first, second, axis) are (Z, X, Y)."""
    s = summary_of("G21 G18 F100\nG0 X52 Y30 Z5\nG2 X52 Y40 Z5 I-12 K0\nM2\n")
    assert box(s) == [28.0, 30.0, -7.0, 52.0, 40.0, 17.0]
    assert s.feed_length == pytest.approx(math.hypot(24 * math.pi, 10))


def test_yz_plane_half_circle() -> None:
    """G19: ARC_FEED's (first, second, axis) are (Y, Z, X)."""
    s = summary_of("G21 G19 F100\nG0 X3 Y0 Z0\nG3 Y10 Z0 J5 K0\nM2\n")
    assert box(s) == [3.0, 0.0, -5.0, 3.0, 10.0, 0.0]
    assert s.feed_length == pytest.approx(5 * math.pi)


# -- units and offsets ----------------------------------------------------------------------------
def test_units_change_converts_the_totals() -> None:
    s = summary_of("G21 F100\nG1 X25.4\nG20\nG1 X2\nM2\n")
    assert (s.units, s.mixed_units) == ("inch", True)
    assert s.feed_length == pytest.approx(2.0)
    assert box(s) == [0.0, 0.0, 0.0, 2.0, 0.0, 0.0]  # (the first cut starts at X0)


def test_extents_start_where_the_program_takes_the_tool() -> None:
    """The start position is not in the extents unless a cut starts there: an axis enters them
    when a move changes it (the first ``G0 Z5`` leaves X and Y out)."""
    start = "G21 G10 L2 P2 X-120 Y-80\nG55\n"
    s = summary_of(start + "G0 Z5\nG0 X10 Y10\nG1 Z-1 F100\nG1 X20\nG0 Z5\nM2\n")
    assert box(s) == [10.0, 10.0, -1.0, 20.0, 10.0, 5.0]
    # a cut starting with an axis where the program found it: that position counts
    s = summary_of("G21\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nM2\n")
    assert box(s) == [0.0, 0.0, -1.0, 10.0, 0.0, 5.0]
    # rapids only: an axis none changes is where it stayed
    s = summary_of(start + "G0 Z5\nG0 Z7\nM2\n")
    assert box(s) == [120.0, 80.0, 5.0, 120.0, 80.0, 7.0]
    s = summary_of(start + "G0 Z5\nG2 X130 Y80 I5 J0 F100\nM2\n")  # an arc is a cut: its start
    assert box(s) == [120.0, 80.0, 5.0, 130.0, 85.0, 5.0]  # (clockwise over the top)


def test_inch_program_has_no_rounding_noise() -> None:
    s = summary_of("G20 F10\nG1 X1\nY1\nX0\nY0\nM2\n")
    assert (s.units, s.mixed_units, s.feed_length) == ("inch", False, 4.0)


def test_work_offset_change_keeps_the_tool_in_place() -> None:
    """After G10 L2 moves the origin by X10, the tool (machine X5) is at program X-5."""
    s = summary_of("G21 F100\nG1 X5\nG10 L2 P1 X10\nG1 X0\nM2\n")
    assert s.feed_length == pytest.approx(5.0 + 5.0)
    assert box(s) == [0.0, 0.0, 0.0, 5.0, 0.0, 0.0]


def test_g92_offset_change() -> None:
    s = summary_of("G21 F100\nG1 X5\nG92 X0\nG1 X1\nM2\n")
    assert s.feed_length == pytest.approx(6.0)


def test_nothing_moves() -> None:
    s = summary_of("G21\nM2\n")
    assert (s.moves, s.rapid_length, s.feed_length, s.extents) == (0, 0.0, 0.0, None)


# -- check_file -----------------------------------------------------------------------------------
def test_check_file_counts_lines_after_the_end(tmp_path: Path) -> None:
    path = tmp_path / "p.ngc"
    path.write_text("G0 X1\nM2\n(after the end)\n\n")
    result = check_file(path)
    assert (result.ok, result.lines, result.summary.traverses) == (True, 4, 1)


def test_check_file_keeps_the_summary_up_to_the_error(tmp_path: Path) -> None:
    path = tmp_path / "p.ngc"
    path.write_text("G0 X1\nG0 X2\nG1 X3\nG0 X4\nM2\n")
    result = check_file(path)
    assert result.error is not None
    assert (result.error.line, result.lines, result.summary.traverses) == (3, 5, 2)


def test_check_file_missing(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError):
        check_file(tmp_path / "nope.ngc")


def test_an_infinite_value_is_an_error_not_an_infinite_length() -> None:
    # It used to pass as "ok, rapid length: inf".
    result = report.check_lines(["G0 X[EXP[710]]", "M2"], "huge.ngc")
    assert not result.ok
    assert result.error is not None
    assert (result.error.line, result.error.message) == (1, "Calculation resulted in 'infinity'")
