"""Cutter radius compensation (interp/comp.py, handlers/ccomp.py): what the golden cases
(tests/golden/cases/ccomp-c-*) do not show on their own."""

from __future__ import annotations

import io

import pytest

import ngc
from ngc.canon import ops
from ngc.canon.jsonl import ListSink
from ngc.interp.interpreter import Interpreter


def _run(text: str) -> list[object]:
    sink = ListSink()
    ngc.interpret(text, sink)
    return [op for op, _, _ in sink.ops]


def _moves(text: str) -> list[tuple[float, ...]]:
    return [tuple(round(v, 4) for v in op) for op in _run(text)  # type: ignore[attr-defined]
            if isinstance(op, ops.StraightFeed | ops.ArcFeed)]


def test_ccomp_parameter_names_the_side() -> None:
    out = _run("g0x0y0\ng42.1 d2\n(debug,#<_ccomp>)\ng1x10f1\ng40\n(debug,#<_ccomp>)\ng1x20\nm2\n")
    assert [op.text for op in out if isinstance(op, ops.Message)] == ["420.000000", "400.000000"]


def test_negative_diameter_takes_the_other_side() -> None:
    left = _moves("g0x0y0\ng41.1 d2\ng1x10f1\ng40\ng1x20\nm2\n")
    flipped = _moves("g0x0y0\ng42.1 d-2\ng1x10f1\ng40\ng1x20\nm2\n")
    assert left == flipped
    assert left[0][:2] == (10.0, 1.0)


def test_end_of_program_releases_the_held_move() -> None:
    out = _run("g0x0y0\ng41.1 d2\ng1x10f1\nm2\n")
    kinds = [type(op) for op in out]
    assert kinds.index(ops.StraightFeed) < kinds.index(ops.ProgramEnd)


def test_g40_when_off_is_only_a_comment() -> None:
    assert _moves("g40\ng0x0y0\ng2x2i1f1\nm2\n")[0][:2] == (2.0, 0.0)


@pytest.mark.parametrize("fast", [True, False])
def test_the_fast_path_compensates_plain_lines(fast: bool) -> None:
    sink = ListSink()
    interp = Interpreter(sink, fast=fast)
    interp.run(io.StringIO("g0x0y0\ng41.1 d2\ng1x10f1\nx20\ny10\ng40\nx30\nm2\n"))
    feeds = [tuple(round(v, 4) for v in op[:2]) for op, _, _ in sink.ops
             if isinstance(op, ops.StraightFeed)]
    assert feeds == [(10.0, 1.0), (19.0, 1.0), (19.0, 10.0), (30.0, 10.0)]


_ON = "g21 g17 f300\ng0x0y-10\ng41.1 d4\ng1x0y0\nx20\n"


def _error(text: str) -> str:
    with pytest.raises(ngc.NgcError) as caught:
        _run(text)
    return caught.value.message


@pytest.mark.parametrize(("line", "message"), [
    ("m62 p0", "Cannot set motion output with cutter radius compensation on"),
    ("m63 p0", "Cannot set motion digital output with cutter radius compensation on"),
    ("m65 p0", "Cannot set auxiliary digital output with cutter radius compensation on"),
    ("m66 p0 l0", "Cannot wait for digital input with cutter radius compensation on"),
    ("m67 e0 q1", "Cannot set motion analog output with cutter radius compensation on"),
    ("m68 e0 q1", "Cannot set auxiliary analog output with cutter radius compensation on"),
    ("g33.1 z-1 k1", "Bug code not g0 or g1"),
    ("g76 p1 z-1 i1 j1 k1", "Bug code not g0 or g1"),
    ("g83 x1 z-1 r1 q1", "Cannot use canned cycles with cutter compensation on"),
    ("g38.2", "All axes missing with motion code"),
    # compensation turned off on the line: the code is not refused
    ("g40 g87 x30 z-1 r1 i1 j1 k1", "Spindle not turning in g87"),
    ("g33 z-1 k1", "Bug code not g0 or g1"),  # G33 in the plane runs as a compensated G1
])
def test_codes_refused_while_compensation_is_on(line: str, message: str) -> None:
    assert _error(f"{_ON}{line}\nm2\n") == message


def test_a_code_refused_on_the_line_that_turns_compensation_on() -> None:
    assert _error("g0x0y0 f10\ng41.1 d2 g81 x30 z-1 r1\nm2\n") == (
        "Cannot use canned cycles with cutter compensation on")


def test_offset_resets_leave_everything_while_compensation_is_on() -> None:
    text = "g21 g92 x5\n" + _ON[4:] + "g92.2\ng40\n(debug,#5210)\ng0x0y0\nm2\n"
    out = _run(text)
    assert [op for op in out if isinstance(op, ops.SetG92Offset)][-1].x == -5.0
    assert [op.text for op in out if isinstance(op, ops.Message)] == ["1.000000"]


def test_units_change_converts_the_held_arc() -> None:
    moves = _moves(_ON[:-4] + "g3 x20 y0 r10 z5\ng20\ng1 x1.5 y-.5\ng40\ng0 x0 y-1\nm2\n")
    assert moves[2] == (0.7087, 0.0, 0.3937, 0.0, 1, 0.1969, 0.0, 0.0, 0.0)
