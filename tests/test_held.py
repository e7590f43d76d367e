"""``toolpath.held``: calls held back and handed on a batch at a time, each reader seeing the
toolpath's state (units, offsets, rotation, plane, tool) as it was when the call was made."""

from __future__ import annotations

from typing import Any

import pytest

from ngc.canon import ops
from ngc.flatten import Refused, flatten
from ngc.interp.interpreter import Interpreter
from ngc.toolpath.frame import Pos
from ngc.toolpath.held import Held, View
from ngc.toolpath.tracker import ArcMove, Cubics, Toolpath

# units, G92, G52, work offsets, rotation, planes, tool lengths and changes, between moves
PROGRAM = """G21 G17 G0 X1 Y2 Z3
G1 X2 F100
G20 G1 X1
G92 X0 Y0
G1 X0.5 Y0.5
G92.1 G21
G10 L2 P2 X5 R30
G55 G1 X3 Y3
G18 G2 I0.5 K-0.5
G54 G17 G3 I-1 J0.5
T2 M6 G43 H2
G1 Z-1
G52 X2
G1 X0
G49 G1 Z5
M2
"""


class Seen:
    """A reader noting, at each call, the state its toolpath (or view) gives."""

    def __init__(self, state: Toolpath | View | None = None) -> None:
        self.state = state
        self.notes: list[tuple[Any, ...]] = []

    def _note(self, what: str, line: int) -> None:
        assert self.state is not None
        f = self.state.frame
        self.notes.append((what, line, f.scale, f.inch_program, f.g5x, f.g92, f.tlo,
                           f.rotation, self.state.plane, self.state.tool))

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self._note(kind, line)

    def arc(self, arc: ArcMove, line: int) -> None:
        self._note("arc", line)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        self._note("nurbs", line)

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self._note("tap", line)

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        self._note("bezier", line)

    def other(self, op: ops.Op, line: int) -> None:
        self._note(type(op).__name__, line)

    def finish(self) -> None:
        self.notes.append(("finish",))


def notes_direct() -> list[tuple[Any, ...]]:
    reader = Seen()
    toolpath = Toolpath(reader)
    reader.state = toolpath  # (read as the calls come)
    run(toolpath)
    return reader.notes


def notes_held(size: int) -> list[tuple[Any, ...]]:
    held = Held(size)
    toolpath = Toolpath(held)
    reader = Seen(held.follow(toolpath))
    held.add(reader)
    run(toolpath)
    return reader.notes


def run(toolpath: Toolpath) -> None:
    interp = Interpreter(toolpath)
    interp.startup()
    interp.run(PROGRAM.splitlines(), file="t.ngc")
    toolpath.flush()


@pytest.mark.parametrize("size", [1, 2, 3, 512])
def test_a_held_reader_sees_the_state_each_call_saw(size: int) -> None:
    direct = notes_direct()
    assert len(direct) > 30
    assert len({n[2:] for n in direct if len(n) > 2}) > 6  # (the state did change)
    assert notes_held(size) == direct


def test_calls_wait_for_a_full_batch_or_settle() -> None:
    held = Held(3)
    toolpath = Toolpath(held)
    reader = Seen(held.follow(toolpath))
    held.add(reader)
    batches: list[int] = []
    held.after = lambda: batches.append(len(reader.notes))
    start = (0.0,) * 6
    held.straight("feed", start, start, 1)
    held.straight("feed", start, start, 2)
    assert reader.notes == []
    held.straight("feed", start, start, 3)
    assert [n[1] for n in reader.notes] == [1, 2, 3] and batches == [3]
    held.straight("feed", start, start, 4)
    held.settle()
    assert [n[1] for n in reader.notes] == [1, 2, 3, 4] and batches == [3, 4]
    held.settle()  # (nothing held: no batch)
    assert batches == [3, 4]


def test_a_refusal_before_a_program_error_comes_first() -> None:
    program = "G21 G1 X1 F100\nG38.2 Z-5 F10\nG1 X2\nG1 X3 Y\nM2\n"
    with pytest.raises(Refused) as refused:
        flatten(program, "t.ngc", lambda sink: Interpreter(sink), verify=False)
    assert refused.value.line == 2
