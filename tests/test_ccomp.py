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
