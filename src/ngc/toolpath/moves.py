"""The toolpath as records: :class:`Move` for each move, :class:`Event` for each standstill or
change a reader may want to show (a dwell, a tool change, a stop, the end), built by
:class:`MoveList`, a reader of :class:`~ngc.toolpath.tracker.Toolpath`.

Machine coordinates (``start``, ``end``, ``centre``) are those the machine's axes go to: the
program's point with the work offset (G54...), the G92/G52 offset, the XY rotation and the tool
length offset applied (``coordinates.adoc``), in the machine's units (mm unless asked for
inches).  So ``end`` includes the tool length offset: ``end[2] - tool_offset[2]`` is where the
tool's tip goes.  Program coordinates (``prog_start``, ``prog_end``) are canon's own: the
program's units and its current coordinate system.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from ..canon import ops
from .frame import Pos
from .tracker import ARC, BEZIER, NURBS, PLANE_NAMES, TAP, ArcMove, Cubics, Toolpath, Vec

# operations a drawing or a sender marks, by the name of the event
EVENTS: dict[type, str] = {
    ops.Dwell: "dwell",
    ops.ChangeTool: "tool change",
    ops.ChangeToolNumber: "tool change",
    ops.ProgramStop: "stop",
    ops.OptionalProgramStop: "optional stop",
    ops.ProgramEnd: "end",
    ops.StartSpindleClockwise: "spindle",
    ops.StartSpindleCounterclockwise: "spindle",
    ops.StopSpindleTurning: "spindle",
    ops.MistOn: "coolant", ops.MistOff: "coolant", ops.FloodOn: "coolant",
    ops.FloodOff: "coolant",
}


@dataclass(frozen=True, slots=True)
class Move:
    """One move of the toolpath.

    ``kind``: ``"rapid"``, ``"feed"``, ``"arc"``, ``"probe"``, ``"sync"`` (spindle-synchronised:
    G33, G76), ``"tap"`` (G33.1: to ``end`` and back to ``start``), ``"nurbs"`` or ``"bezier"``
    (an engine-dialect segment).  ``feed`` is
    the feed rate in machine units per minute (per revolution where ``feed_mode`` says so), as
    the last ``SET_FEED_RATE`` gave it; ``spindle`` the spindle speed (rpm, or surface speed
    under G96).  Arcs have ``centre`` (a point on their axis), ``normal`` (a unit vector) and
    ``turns`` (> 0 counterclockwise seen from the normal's tip, |turns| - 1 extra full turns);
    a NURBS move has ``curve``, the call as canon gave it (program coordinates); an engine
    segment (``"bezier"``) has ``cubics``, the four control points of X Y Z A B C over its
    time."""

    file: str | None
    line: int
    kind: str
    start: Pos
    end: Pos
    prog_start: Pos
    prog_end: Pos
    tool: int
    tool_offset: Pos
    feed: float
    feed_mode: str
    spindle: float
    plane: str
    centre: Vec | None = None
    normal: Vec | None = None
    turns: int = 0
    curve: ops.NurbsFeed | None = None
    cubics: Cubics | None = None


@dataclass(frozen=True, slots=True)
class Event:
    """A standstill or a change on the way: ``kind`` one of :data:`EVENTS`' names, ``op`` the
    operation, ``at`` the machine position."""

    file: str | None
    line: int
    kind: str
    op: ops.Op
    at: Pos


class MoveList:
    """A reader of the toolpath that makes a :class:`Move` of each move and an :class:`Event`
    of each operation in :data:`EVENTS`, handing them to ``out`` (a list's ``append``, or
    anything that takes one record).  ``toolpath`` is the one it reads (see
    :class:`~ngc.toolpath.tracker.Toolpath`): ``MoveList(out).toolpath`` is the canon sink to
    give an interpreter."""

    def __init__(self, out: Callable[[Move | Event], object], *, file: str | None = None,
                 inch_machine: bool = False) -> None:
        self.out = out
        self.file = file
        self.toolpath = Toolpath(self, inch_machine=inch_machine)
        self.feed = 0.0
        self.feed_mode = "per minute"
        self.spindle = 0.0

    def _move(self, kind: str, start: Pos, end: Pos, line: int, **extra: object) -> None:
        tp = self.toolpath
        self.out(Move(self.file, line, kind, start, end, tp.prog, tp.prog_end, tp.tool,
                      tp.frame.tlo, self.feed, self.feed_mode, self.spindle,
                      PLANE_NAMES[tp.plane], **extra))  # type: ignore[arg-type]

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self._move(kind, start, end, line)

    def arc(self, arc: ArcMove, line: int) -> None:
        self._move(ARC, arc.start, arc.end, line, centre=arc.centre, normal=arc.normal,
                   turns=arc.turns)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        tp = self.toolpath
        self._move(NURBS, start, tp.frame.to_machine(tp.prog_end), line, curve=curve)

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self._move(TAP, start, bottom, line)

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        self._move(BEZIER, start, self.toolpath.prog_end, line, cubics=cubics)

    def other(self, op: ops.Op, line: int) -> None:
        kind = type(op)
        if kind is ops.SetFeedRate:
            self.feed = op.rate * self.toolpath.frame.scale  # type: ignore[attr-defined]
        elif kind is ops.SetFeedMode:
            self.feed_mode = "per revolution" if op.mode == 1 else "per minute"  # type: ignore[attr-defined]
        elif kind is ops.SetSpindleSpeed:
            self.spindle = op.rpm  # type: ignore[attr-defined]
        name = EVENTS.get(kind)
        if name is not None:
            self.out(Event(self.file, line, name, op, self.toolpath.pos))

    def finish(self) -> None:
        """Nothing is held back."""
