"""tests/fuzz/canon_read.py reads rs274's transcript back into canon operations, and
tests/fuzz/flatten_sweep.py compares two runs' machine paths and checks a written program is
plain.  The lines below are recorded from rs274 2.9.0~pre1; rs274 itself is needed only by the
last test, which is skipped without it."""

from __future__ import annotations

import io
import math
import shutil
import sys
from pathlib import Path

import pytest

FUZZ = Path(__file__).parent / "fuzz"
sys.path.insert(0, str(FUZZ))

import canon_read  # noqa: E402
import flatten_sweep  # noqa: E402

from ngc import Interpreter  # noqa: E402
from ngc.canon import ops  # noqa: E402
from ngc.canon.text import TextSink  # noqa: E402

RECORDED = """\
    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)
    8 N..... SET_G5X_OFFSET(1, 1.0000, 2.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    9 N..... SET_XY_ROTATION(10.0000)
   10 N..... SET_G92_OFFSET(-1.8321, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   11 N10    STRAIGHT_TRAVERSE(1.0000, 1.0000, 1.0000, 0.0000, 0.0000, 0.0000)
   12 N123456SET_FEED_RATE(10.0000)
   13 N123456STRAIGHT_FEED(2.0000, 1.0000, 1.0000, 0.0000, 0.0000, 0.0000)
   14 N..... ARC_FEED(3.0000, 1.0000, 2.5000, 1.0000, -1, 1.0000, 0.0000, 0.0000, 0.0000)
   15 N..... SELECT_PLANE(CANON_PLANE_XZ)
   16 N..... ARC_FEED(2.0000, 1.0000, 3.9900, 3.2450, 1, 1.0000, 0.0000, 0.0000, 0.0000)
   17 N..... SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.010000)
   18 N..... SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)
   19 N..... USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 0.5110, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)
 hi
   20 N..... COMMENT("a (nested) "quoted" comment")
   21 N..... NURBS_FEED(4, ...)
   22 N..... SET_SPINDLE_MODE(0 0.0000)
   23 N..... SPINDLE.0.WAIT_ORIENT_COMPLETE(30.0000)
   24 N..... PROGRAM_END()
"""


def test_every_recorded_call_is_read() -> None:
    calls = list(canon_read.read(RECORDED))
    assert [c.counter for c in calls] == list(range(1, 25))  # (" hi" is print text)
    by_counter = {c.counter: c.op for c in calls}
    assert not [c for c in calls if isinstance(c.op, canon_read.Unread)]
    assert by_counter[8] == ops.SetG5xOffset(1, 1.0, 2.0, 0.0, 0.0, 0.0, 0.0)
    assert by_counter[14] == ops.ArcFeed(3.0, 1.0, 2.5, 1.0, -1, 1.0, 0.0, 0.0, 0.0)
    assert by_counter[17] == ops.SetMotionControlContinuous(0.01)
    assert by_counter[18] == ops.SetMotionControlMode("CANON_EXACT_PATH")
    assert by_counter[19] == ops.UseToolLengthOffset(0, 0, 0.511, 0, 0, 0, 0, 0, 0)
    assert by_counter[20] == ops.Comment('a (nested) "quoted" comment')
    assert by_counter[21].size == 4
    assert by_counter[23] == ops.WaitOrientComplete(0, 30.0)
    assert [c.label for c in calls[10:13]] == ["N10    ", "N123456", "N123456"]


def test_an_unknown_call_is_kept_by_name() -> None:
    (call,) = canon_read.read("    7 N..... SOMETHING_NEW(1, 2)\n")
    assert call.op == canon_read.Unread("SOMETHING_NEW", "SOMETHING_NEW(1, 2)")


def test_the_machine_path_applies_units_offsets_and_rotation() -> None:
    run = canon_read.machine_path(RECORDED)
    kinds = [m[0] for m in run.moves]
    assert kinds == ["rapid", "feed", "arc", "arc", "nurbs"]
    assert run.unread == {"NURBS_FEED": 1}  # (its points are not printed)
    # X: (1 + G92 -1.8321) turned 10 degrees, + G5x 1, in mm
    x = ((1.0 - 1.8321) * math.cos(math.radians(10)) - math.sin(math.radians(10))) + 1.0
    assert run.moves[0][1][0] == pytest.approx(x * 25.4)
    rapid = run.bounds[0]
    # the move's print and the G92 print, turned, the G5x print, the rotation's print
    assert rapid.xy > (1 + 1 + 1) * canon_read.PRINTED * 25.4
    assert rapid.z == pytest.approx(3 * canon_read.PRINTED * 25.4)
    assert math.isinf(run.bounds[-1].xy)


@pytest.mark.parametrize("program", [
    "G20 G10 L2 P1 X1 Y2 R30\nG92 X.5\nG0 X1 Y1 Z1\nG1 F10 X2\nG2 X3 Y1 I.5 J0\n"
    "G18 G3 X1 Z2 R3\nG19 G2 Y1 Z2 J0 K1 P3\nM2\n",
    "G21 G0 X10 Y10\nG43.1 Z5\nG1 F100 X20 A30\nG3 X30 Y20 I5 J5 Z-3\nG91 G2 X1 Y0 I.5\nM2\n",
])
def test_ngc_text_read_back_gives_ngcs_own_path(program: str) -> None:
    """The text sink's transcript, read back, makes the path of the ops themselves (within
    the print's rounding)."""
    from ngc.canon.jsonl import ListSink

    out = io.StringIO()
    text = TextSink(out)
    listed = ListSink()
    for sink in (text, listed):
        interp = Interpreter(sink)
        interp.startup()
        interp.run(program.splitlines())
        sink.flush()
    read = canon_read.machine_path(out.getvalue())
    direct = canon_read.machine_path(
        canon_read.Canon(k, label, op, "") for k, (op, label, _line) in enumerate(listed.ops, 1))
    assert [m[0] for m in read.moves] == [m[0] for m in direct.moves]
    for m, n, bound in zip(read.moves, direct.moves, read.bounds, strict=True):
        assert max(abs(p - q) for p, q in zip(m[1][:3], n[1][:3], strict=True)) <= bound.xy


def test_plain() -> None:
    plain = ("(flattened: #1 [x] o100 G41)\nG21 G90 G91.1 G94 G40 G49 G80 G17 G97\nG54\n"
             "G0 X1 Y-2.5 Z.5\nG43 H1\nG3 F100 X1 Y2 I0.5 J0 P2\nG64 P0.01 Q0\nM62 P1\n"
             "M67 E0 Q2.5\n(MSG,hello #1)\nG96 D2000 S100\nM19 R90 Q5 P0\nG33 Z-10 K1.5\n"
             "G33.1 Z-5 K1\n(PRINT|,a=#1)\n(print ,b)\n%\nM2\n")
    assert flatten_sweep.not_plain(plain) is None
    for line, why in (
            ("G1 X#1", "not words alone"), ("G1 X[1+2]", "not words alone"),
            ("O100 sub", "not words alone"), ("O100", "the word O"), ("G81 X1 Y1 Z-1 R1", "G81"),
            ("G41 D1", "G41"), ("G5.2 X1 Y1 P1", "G5.2"), ("G92 X0", "G92"),
            ("G38.2 Z-1", "G38.2"), ("M98 P100", "M98"), ("(debug, #1)", "active"),
            ("( Print,x)", "active"), ("(LOGCLOSE)", "active"), ("G76 P1 Z-1 I-.1 J.1 K.2", "G76"),
            ("G10 L2 P1 X0", "G10"), ("G1 X1 R2", "the word R"), ("G97 D100", "the word D")):
        found = flatten_sweep.not_plain(plain + line + "\n")
        assert found is not None and why in found, (line, found)


def _run(moves: list[tuple[float, ...]]) -> canon_read.Run:
    kept = [("feed", (*p, 0.0, 0.0, 0.0), None, 0, k, None, None, 100.0)
            for k, p in enumerate(moves)]
    bounds = [canon_read.Bound(5e-5, 5e-5, 5e-5)] * len(kept)
    return canon_read.Run(kept, bounds, {}, canon_read.Counter())  # type: ignore[arg-type]


def test_compare_takes_rounding_and_leaves_out_moves_of_no_length() -> None:
    w = flatten_sweep.written_rounding("linuxcnc", inch=False)
    assert w.linear == pytest.approx(5e-5)
    a = _run([(1.0, 2.0, 3.0), (4.0, 5.0, 6.0)])
    b = _run([(1.0001, 2.0, 3.0), (1.0001, 2.0, 3.0), (4.0, 5.0, 6.0)])
    same = flatten_sweep.compare_runs(a, b, w)
    assert same.difference is None and same.idle == (0, 1)
    assert same.worst == pytest.approx(1e-4)
    off = flatten_sweep.compare_runs(a, _run([(1.0002, 2.0, 3.0), (4.0, 5.0, 6.0)]), w)
    assert off.difference is not None and "off by 0.000200 on X" in off.difference


def test_a_sliver_written_as_one_line_is_followed() -> None:
    # an arc whose printed start and end are a rounding apart, written as one line whose end
    # is nearer the printed start: the line ends the curve; the next line is not part of it
    start, end = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0), (-0.0012, 0.0, 0.0, 0.0, 0.0, 0.0)
    lines = [("feed", (-0.0001, 0.0, 0.0, 0.0, 0.0, 0.0)), ("feed", (-20.0, 5.0, 0.0) + (0.0,) * 3)]
    after, worst, difference = flatten_sweep._follow([start, end], lines, 0, 0.002, 1e-3)
    assert (after, difference) == (1, None) and worst < 0.002
    # two lines there: the later ends it
    two = [("feed", (-0.0005, 0.0, 0.0, 0.0, 0.0, 0.0)), *lines]
    after, worst, difference = flatten_sweep._follow([start, end], two, 0, 0.002, 1e-3)
    assert (after, difference) == (2, None)
    # a whole circle is not ended by a line that comes back near its start early
    circle = [(math.cos(t / 8 * math.tau), math.sin(t / 8 * math.tau), 0.0, 0.0, 0.0, 0.0)
              for t in range(9)]
    near_start = [("feed", (0.9999, 0.01, 0.0, 0.0, 0.0, 0.0))]
    after, _, difference = flatten_sweep._follow(circle, near_start, 0, 0.002, 1e-3)
    assert difference is not None


@pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")
def test_a_generated_program_flattens_to_the_same_path_in_rs274() -> None:
    cfg = flatten_sweep.Config("rs274", "linuxcnc", inch=False)
    result = flatten_sweep.sweep_one(flatten_sweep.generated_program("motion", 1), cfg)
    assert result.outcome == flatten_sweep.SAME, result.detail
    assert result.moves > 10
